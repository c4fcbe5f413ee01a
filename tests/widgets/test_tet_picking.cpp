// Tet picking and inspection (issue 8) under the `offscreen` platform: the TetPicker casts
// camera rays (widgets/camera_ray.h) against the displayed tets, so clicking where
// worldToPixel puts a visible boundary face must give its tet, the background -1, and the
// inspector must show that tet's values. Filter and clipping are respected.

#include "core/mesh/box_mesh.h"
#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/topology.h"
#include "widgets/camera_ray.h"
#include "widgets/quality_panel.h"
#include "widgets/tet_inspector.h"
#include "widgets/tet_mesh_actor.h"
#include "widgets/tet_picker.h"
#include "widgets/vtk_viewport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

#include <vtkCamera.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace resect;

namespace {

struct VisibleFace {
    int tet = -1;
    Vec3 centroid;
    QPointF pixel;
};

/// Boundary faces of the mesh that face the camera squarely, with the pixel of their
/// centroid.
std::vector<VisibleFace> visibleFaces(const TetMesh& mesh, const VtkViewport& viewport) {
    std::vector<VisibleFace> out;
    const Vec3 view = viewDirection(viewport.camera());
    for (const BoundaryFace& f : boundaryFaces(mesh)) {
        const Vec3& a = mesh.pos(f.nodes[0]);
        const Vec3& b = mesh.pos(f.nodes[1]);
        const Vec3& c = mesh.pos(f.nodes[2]);
        const Vec3 normal = (b - a).cross(c - a).normalized();
        if (normal.dot(-view) < 0.3)
            continue;
        const Vec3 centroid = (a + b + c) / 3.0;
        const auto pixel = worldToPixel(viewport.camera(), viewport.size(), centroid);
        if (pixel)
            out.push_back({f.tet, centroid, *pixel});
    }
    return out;
}

template <class T> T* child(QWidget& parent, const char* name) {
    T* w = parent.findChild<T*>(QString::fromLatin1(name));
    if (w == nullptr)
        qFatal("missing child widget %s", name);
    return w;
}

double labelValue(TetInspector& inspector, const char* name) {
    bool ok = false;
    const double v = child<QLabel>(inspector, name)->text().toDouble(&ok);
    return ok ? v : std::nan("");
}

} // namespace

class TestTetPicking : public QObject {
    Q_OBJECT

private slots:
    void pickTetAtFaceCentroids_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("unit") << 1.0;
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1e3") << 1e3;
    }
    void pickTetAtFaceCentroids() {
        QFETCH(double, scale);
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), scale * Vec3(2, 1.5, 1), 4, 3, 2);
        VtkViewport viewport;
        viewport.resize(400, 300);
        viewport.setTetMesh(mesh); // frames the mesh (resetCamera)
        const std::vector<VisibleFace> faces = visibleFaces(mesh, viewport);
        QVERIFY(faces.size() >= 10);
        for (const VisibleFace& f : faces)
            QCOMPARE(TetPicker::pickTet(viewport, f.pixel), f.tet);
        // The background.
        QCOMPARE(TetPicker::pickTet(viewport, QPointF(2, 2)), -1);
        QCOMPARE(TetPicker::pickTet(viewport, QPointF(398, 298)), -1);
    }

    void clickPicksAndInspects() {
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3(2, 1.5, 1), 4, 3, 2);
        VtkViewport viewport;
        viewport.resize(400, 300);
        viewport.show();
        QVERIFY(QTest::qWaitForWindowExposed(&viewport));
        viewport.setTetMesh(mesh);
        QualityPanel panel;
        panel.show();
        panel.attach(&viewport);
        panel.setMeshProvider([&mesh] { return &mesh; });
        std::vector<Scheme> schemes(mesh.tetCount(), Scheme::None);
        const std::vector<VisibleFace> faces = visibleFaces(mesh, viewport);
        QVERIFY(!faces.empty());
        const VisibleFace& target = faces[faces.size() / 2];
        schemes[target.tet] = Scheme::X;
        viewport.tetMeshActor().setTetSchemes(schemes);

        QTest::mouseClick(child<QPushButton>(panel, "pickEnabled"), Qt::LeftButton);
        QCOMPARE(viewport.tool(), static_cast<ViewportTool*>(panel.picker()));
        QSignalSpy spy(&panel, &QualityPanel::tetPicked);

        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, target.pixel.toPoint());
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toInt(), target.tet);
        QCOMPARE(panel.picker()->lastPicked(), target.tet);

        // The inspector shows that tet.
        TetInspector& inspector = *panel.inspector();
        QCOMPARE(inspector.tet(), target.tet);
        QCOMPARE(child<QLabel>(inspector, "tetIndex")->text(), QString::number(target.tet));
        const double volume = mesh.currentVolume(target.tet);
        QVERIFY(std::abs(labelValue(inspector, "currentVolume") - volume) <= 1e-5 * volume);
        QVERIFY(std::abs(labelValue(inspector, "referenceVolume") - volume) <= 1e-5 * volume);
        const TetQuality q = tetQualities(mesh)[target.tet];
        QVERIFY(std::abs(labelValue(inspector, "radiusRatio") - q.radiusRatio) < 1e-5);
        QVERIFY(std::abs(labelValue(inspector, "minDihedral") -
                         q.minDihedral * 180 / std::numbers::pi) < 1e-4);
        QVERIFY(std::abs(labelValue(inspector, "maxEdge") - q.maxEdge) < 1e-5);
        QCOMPARE(child<QLabel>(inspector, "tetScheme")->text(), QStringLiteral("X"));
        const int node0 = mesh.tet(target.tet)[0];
        QVERIFY(child<QLabel>(inspector, "tetNode0")
                    ->text()
                    .startsWith(QString::number(node0) + QLatin1Char(':')));

        // The background: a miss, the inspector cleared.
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(2, 2));
        QCOMPARE(spy.count(), 2);
        QCOMPARE(spy.at(1).at(0).toInt(), -1);
        QCOMPARE(inspector.tet(), -1);
        QCOMPARE(child<QLabel>(inspector, "currentVolume")->text(), QStringLiteral("—"));

        // A drag is not a click.
        QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, target.pixel.toPoint());
        QTest::mouseMove(&viewport, target.pixel.toPoint() + QPoint(30, 0));
        QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier,
                            target.pixel.toPoint() + QPoint(30, 0));
        QCOMPARE(spy.count(), 2);

        // Another tool replaces the picker: the button follows.
        viewport.setTool(nullptr);
        QVERIFY(!child<QPushButton>(panel, "pickEnabled")->isChecked());
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, target.pixel.toPoint());
        QCOMPARE(spy.count(), 2);
    }

    void pickingRespectsClippingAndFilter() {
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3(2, 1.5, 1), 4, 3, 2);
        VtkViewport viewport;
        viewport.resize(400, 300);
        viewport.setTetMesh(mesh);
        QualityPanel panel;
        panel.show();
        panel.attach(&viewport);
        const std::vector<VisibleFace> faces = visibleFaces(mesh, viewport);
        const VisibleFace& target = faces[faces.size() / 2];
        QCOMPARE(TetPicker::pickTet(viewport, target.pixel), target.tet);

        // Clip away the half of the mesh nearest to the camera: the tet under the pixel now
        // is another, displayed one, farther from the camera.
        child<QComboBox>(panel, "clipAxis")->setCurrentIndex(int(QualityPanel::ClipAxis::View));
        child<QSlider>(panel, "clipPosition")->setValue(500);
        child<QCheckBox>(panel, "clipEnabled")->setChecked(true);
        const TetMeshActor& actor = viewport.tetMeshActor();
        QVERIFY(!actor.isTetDisplayed(target.tet));
        const Ray ray = pixelRay(viewport.camera(), viewport.size(), target.pixel);
        double distance = 0;
        const int behind = TetPicker::pickTet(actor, ray, &distance);
        QVERIFY(behind >= 0);
        QVERIFY(behind != target.tet);
        QVERIFY(actor.isTetDisplayed(behind));
        QVERIFY(distance > (target.centroid - ray.origin).norm());
        child<QCheckBox>(panel, "clipEnabled")->setChecked(false);

        // A filter that no tet passes (all Kuhn tets have radius ratio ~0.72): nothing to
        // pick.
        child<QCheckBox>(panel, "filterEnabled")->setChecked(true);
        QVERIFY(actor.displayedTets().empty());
        QCOMPARE(TetPicker::pickTet(viewport, target.pixel), -1);
        // One that all pass: every tet drawn shrunk. The ray through the target's face
        // centroid now hits a shrunk tet, at a point on that tet's shrunk boundary.
        panel.findChild<QDoubleSpinBox*>(QStringLiteral("filterThreshold"))->setValue(1.0);
        QCOMPARE(int(actor.displayedTets().size()), mesh.tetCount());
        const int hit = TetPicker::pickTet(actor, ray, &distance);
        QVERIFY(hit >= 0);
        const Vec3 x = ray.at(distance);
        const Tet& nodes = mesh.tet(hit);
        const Vec3 c = 0.25 * (mesh.pos(nodes[0]) + mesh.pos(nodes[1]) + mesh.pos(nodes[2]) +
                               mesh.pos(nodes[3]));
        Vec3 corner[4];
        for (int k = 0; k < 4; ++k)
            corner[k] = c + actor.shrinkFactor() * (mesh.pos(nodes[k]) - c);
        // Barycentric coordinates of x in the shrunk tet: all >= 0, the smallest ~0.
        const double v = signedVolume(corner[0], corner[1], corner[2], corner[3]);
        double bary[4];
        for (int k = 0; k < 4; ++k) {
            Vec3 p[4] = {corner[0], corner[1], corner[2], corner[3]};
            p[k] = x;
            bary[k] = signedVolume(p[0], p[1], p[2], p[3]) / v;
        }
        const double minBary = *std::min_element(bary, bary + 4);
        QVERIFY(std::abs(minBary) < 1e-9);
        QVERIFY(*std::max_element(bary, bary + 4) <= 1.0 + 1e-9);
    }
};

QTEST_MAIN(TestTetPicking)
#include "test_tet_picking.moc"
