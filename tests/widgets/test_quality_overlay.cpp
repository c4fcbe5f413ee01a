// Quality overlays (issue 8) under the `offscreen` platform: the TetMeshActor's measure,
// colour range, display modes, quality filter, clipping plane and position fast path; the
// legend; the histogram and the Table-1 summary; all driven through the QualityPanel's
// controls where there is one.

#include "core/mesh/box_mesh.h"
#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/topology.h"
#include "widgets/quality_colors.h"
#include "widgets/quality_histogram.h"
#include "widgets/quality_legend.h"
#include "widgets/quality_panel.h"
#include "widgets/quality_summary_table.h"
#include "widgets/tet_mesh_actor.h"
#include "widgets/vtk_viewport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

#include <limits>

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkScalarBarActor.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <set>

using namespace resect;

namespace {

/// 3 x 3 x 3 cubes of six tets on [0, 1]^3, with interior node (1, 1, 1) (index 21) moved
/// towards (2, 2, 2)/3 in the reference configuration: the tets around it become slivers
/// and needles, the others stay Kuhn tets (radius ratio ~0.72).
TetMesh distortedBox() {
    const TetMesh box = makeBoxTetMesh(Vec3::Zero(), Vec3::Ones(), 3, 3, 3);
    std::vector<Vec3> ref(box.referencePositions().begin(), box.referencePositions().end());
    ref[21] = Vec3(0.56, 0.58, 0.61);
    return TetMesh::fromArrays(std::move(ref), box.tets());
}

/// Tets whose measure is below the threshold, computed independently of the actor.
std::set<int> tetsBelow(const TetMesh& mesh, QualityMeasure measure, double threshold) {
    std::set<int> out;
    const std::vector<TetQuality> q = tetQualities(mesh);
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const double v = measure == QualityMeasure::MinDihedral
                             ? q[t].minDihedral * 180.0 / std::numbers::pi
                             : q[t].radiusRatio;
        if (v < threshold)
            out.insert(t);
    }
    return out;
}

/// The owning tets of the displayed triangles (cell data "tet").
std::set<int> displayedOwners(const TetMeshActor& actor) {
    std::set<int> out;
    vtkDataArray* ids = actor.boundary()->GetCellData()->GetArray(kTetIdArray);
    if (ids == nullptr)
        return out;
    for (vtkIdType c = 0; c < ids->GetNumberOfTuples(); ++c)
        out.insert(static_cast<int>(ids->GetTuple1(c)));
    return out;
}

template <class T> T* child(QWidget& parent, const char* name) {
    T* w = parent.findChild<T*>(QString::fromLatin1(name));
    if (w == nullptr)
        qFatal("missing child widget %s", name);
    return w;
}

/// Clicks a check box on its indicator (a wide box's centre may lie outside its hit area).
void clickCheckBox(QCheckBox* box) {
    QTest::mouseClick(box, Qt::LeftButton, Qt::NoModifier, QPoint(6, box->height() / 2));
}

} // namespace

class TestQualityOverlay : public QObject {
    Q_OBJECT

private slots:
    void boundaryCarriesTetIdAndMeasures() {
        const TetMesh mesh = distortedBox();
        TetMeshActor actor;
        actor.setMesh(mesh);
        vtkPolyData* poly = actor.boundary();
        // Surface mode: the 3x3x3 box has 6 * 9 * 2 boundary triangles.
        QCOMPARE(poly->GetNumberOfCells(), vtkIdType(108));
        vtkDataArray* ids = poly->GetCellData()->GetArray(kTetIdArray);
        vtkDataArray* rr = poly->GetCellData()->GetArray(kRadiusRatioArray);
        vtkDataArray* dih = poly->GetCellData()->GetArray(kMinDihedralArray);
        QVERIFY(ids != nullptr && rr != nullptr && dih != nullptr);
        const std::vector<TetQuality> q = tetQualities(mesh);
        for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
            const int t = static_cast<int>(ids->GetTuple1(c));
            QVERIFY(t >= 0 && t < mesh.tetCount());
            QCOMPARE(rr->GetTuple1(c), q[t].radiusRatio);
            QCOMPARE(dih->GetTuple1(c), q[t].minDihedral * 180.0 / std::numbers::pi);
        }
        QCOMPARE(int(actor.displayedTets().size()), mesh.tetCount());
    }

    void measureSwitchChangesArrayRangeAndLegend() {
        const TetMesh mesh = distortedBox();
        VtkViewport viewport;
        viewport.setTetMesh(mesh);
        QualityPanel panel;
        panel.show();
        panel.attach(&viewport);
        panel.meshChanged();
        TetMeshActor& actor = viewport.tetMeshActor();
        vtkMapper* mapper = actor.actor()->GetMapper();

        // Default: radius ratio over [0, 1].
        QCOMPARE(QString::fromLatin1(mapper->GetArrayName()), QString::fromLatin1("quality"));
        QVERIFY(mapper->GetScalarVisibility());
        QCOMPARE(actor.colorRange().second, 1.0);
        QCOMPARE(panel.legend().title(), qualityMeasureTitle(QualityMeasure::RadiusRatio));
        QVERIFY(panel.legend().visible());
        QCOMPARE(panel.legend().actor()->GetLookupTable(),
                 static_cast<vtkScalarsToColors*>(actor.lookupTable()));

        auto* measure = child<QComboBox>(panel, "overlayMeasure");
        measure->setCurrentIndex(static_cast<int>(QualityMeasure::MinDihedral));
        QCOMPARE(actor.overlayMeasure(), QualityMeasure::MinDihedral);
        QCOMPARE(QString::fromLatin1(mapper->GetArrayName()), QString::fromLatin1("min_dihedral"));
        QCOMPARE(actor.colorRange().first, 0.0);
        QCOMPARE(actor.colorRange().second, kRegularDihedralDeg);
        QCOMPARE(mapper->GetScalarRange()[1], kRegularDihedralDeg);
        QCOMPARE(actor.lookupTable()->GetRange()[1], kRegularDihedralDeg);
        QCOMPARE(panel.legend().title(), qualityMeasureTitle(QualityMeasure::MinDihedral));
        // The spin box shows the range (to its one decimal).
        QVERIFY(std::abs(child<QDoubleSpinBox>(panel, "rangeMax")->value() - kRegularDihedralDeg) <
                0.051);

        // "Auto" takes the data range.
        double lo = 1e9, hi = -1e9;
        for (const TetQuality& q : tetQualities(mesh)) {
            lo = std::min(lo, q.minDihedral * 180.0 / std::numbers::pi);
            hi = std::max(hi, q.minDihedral * 180.0 / std::numbers::pi);
        }
        QTest::mouseClick(child<QPushButton>(panel, "rangeAuto"), Qt::LeftButton);
        QVERIFY(std::abs(actor.colorRange().first - lo) < 1e-9);
        QVERIFY(std::abs(actor.colorRange().second - hi) < 1e-9);
        QVERIFY(std::abs(actor.lookupTable()->GetRange()[0] - lo) < 1e-9);

        // A range typed into the spin box reaches the actor.
        auto* rangeMin = child<QDoubleSpinBox>(panel, "rangeMin");
        rangeMin->setValue(5.0);
        QCOMPARE(actor.colorRange().first, 5.0);

        // None: uniform colour, no legend.
        measure->setCurrentIndex(static_cast<int>(QualityMeasure::None));
        QVERIFY(!mapper->GetScalarVisibility());
        QVERIFY(!panel.legend().visible());
        QCOMPARE(panel.legend().title(), qualityMeasureTitle(QualityMeasure::None));
    }

    void filterShowsExactlyTheWorseTets_data() {
        QTest::addColumn<int>("measure");
        QTest::addColumn<double>("threshold");
        QTest::newRow("radius ratio 0.5") << int(QualityMeasure::RadiusRatio) << 0.5;
        QTest::newRow("radius ratio 0.3") << int(QualityMeasure::RadiusRatio) << 0.3;
        QTest::newRow("min dihedral 20") << int(QualityMeasure::MinDihedral) << 20.0;
    }
    void filterShowsExactlyTheWorseTets() {
        QFETCH(int, measure);
        QFETCH(double, threshold);
        const TetMesh mesh = distortedBox();
        const std::set<int> expected =
            tetsBelow(mesh, static_cast<QualityMeasure>(measure), threshold);
        // The mesh has bad tets, but not only bad ones.
        QVERIFY(!expected.empty());
        QVERIFY(int(expected.size()) < mesh.tetCount());

        VtkViewport viewport;
        viewport.setTetMesh(mesh);
        QualityPanel panel;
        panel.show();
        panel.attach(&viewport);
        TetMeshActor& actor = viewport.tetMeshActor();
        child<QComboBox>(panel, "overlayMeasure")->setCurrentIndex(measure);
        child<QDoubleSpinBox>(panel, "filterThreshold")->setValue(threshold);
        QCOMPARE(int(actor.displayedTets().size()), mesh.tetCount()); // not enabled yet
        clickCheckBox(child<QCheckBox>(panel, "filterEnabled"));
        QVERIFY(actor.qualityFilterEnabled());

        const std::set<int> shown(actor.displayedTets().begin(), actor.displayedTets().end());
        QCOMPARE(shown, expected);
        QCOMPARE(displayedOwners(actor), expected);
        // Drawn as shrunk tets: four triangles each, inside the tet.
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(4 * expected.size()));
        QCOMPARE(actor.boundary()->GetNumberOfPoints(), vtkIdType(4 * expected.size()));

        // Off again: everything.
        clickCheckBox(child<QCheckBox>(panel, "filterEnabled"));
        QCOMPARE(int(actor.displayedTets().size()), mesh.tetCount());
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(108));
    }

    void displayModes() {
        const TetMesh mesh = distortedBox();
        VtkViewport viewport;
        viewport.setTetMesh(mesh);
        QualityPanel panel;
        panel.show();
        panel.attach(&viewport);
        TetMeshActor& actor = viewport.tetMeshActor();
        auto* mode = child<QComboBox>(panel, "displayMode");

        mode->setCurrentIndex(static_cast<int>(TetDisplayMode::Wireframe));
        QCOMPARE(actor.displayMode(), TetDisplayMode::Wireframe);
        QCOMPARE(actor.actor()->GetProperty()->GetRepresentation(), VTK_WIREFRAME);
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(allFaces(mesh).size()));

        mode->setCurrentIndex(static_cast<int>(TetDisplayMode::ShrunkTets));
        QCOMPARE(actor.actor()->GetProperty()->GetRepresentation(), VTK_SURFACE);
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(4 * mesh.tetCount()));
        // Every shrunk corner lies strictly between the centroid and the node.
        vtkPoints* points = actor.boundary()->GetPoints();
        const Tet& t0 = mesh.tet(0);
        const Vec3 c =
            0.25 * (mesh.pos(t0[0]) + mesh.pos(t0[1]) + mesh.pos(t0[2]) + mesh.pos(t0[3]));
        Vec3 p;
        points->GetPoint(0, p.data());
        QVERIFY(((p - c) - actor.shrinkFactor() * (mesh.pos(t0[0]) - c)).norm() < 1e-12);

        mode->setCurrentIndex(static_cast<int>(TetDisplayMode::Surface));
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(108));
    }

    void clippingHidesTetsBeyondThePlane() {
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Ones(), 3, 3, 3);
        VtkViewport viewport;
        viewport.setTetMesh(mesh);
        QualityPanel panel;
        panel.show();
        panel.attach(&viewport);
        TetMeshActor& actor = viewport.tetMeshActor();
        auto* slider = child<QSlider>(panel, "clipPosition");
        child<QComboBox>(panel, "clipAxis")->setCurrentIndex(0); // x
        slider->setValue(slider->maximum());
        clickCheckBox(child<QCheckBox>(panel, "clipEnabled"));
        QVERIFY(actor.clipEnabled());
        QCOMPARE(int(actor.displayedTets().size()), mesh.tetCount());

        // Half way: the plane x = 0.5; the tets with all nodes at x >= 0.5 (the last layer
        // of cubes, 9 * 6 tets) are hidden, and the cut exposes interior faces.
        slider->setValue(slider->maximum() / 2);
        QVERIFY(std::abs(actor.clipOrigin().x() - 0.5) < 1e-12);
        QCOMPARE(actor.clipNormal(), Vec3(1, 0, 0));
        std::set<int> expected;
        for (int t = 0; t < mesh.tetCount(); ++t) {
            bool allBeyond = true;
            for (int n : mesh.tet(t))
                allBeyond = allBeyond && mesh.pos(n).x() >= 0.5;
            if (!allBeyond)
                expected.insert(t);
        }
        QCOMPARE(int(expected.size()), mesh.tetCount() - 54);
        const std::set<int> shown(actor.displayedTets().begin(), actor.displayedTets().end());
        QCOMPARE(shown, expected);
        // The displayed triangles belong to displayed tets only (interior ones own none).
        for (int t : displayedOwners(actor))
            QVERIFY(shown.count(t) == 1);
        // 2 x 3 x 3 cubes remain, closed by the exposed interior faces:
        // 2 * (3*3 + 2*3 + 2*3) squares = 84 triangles.
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(84));

        // Fully: nothing shown, the actor hidden, bounds unchanged (the camera does not jump).
        slider->setValue(0);
        QCOMPARE(int(actor.displayedTets().size()), 0);
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(0));
        QVERIFY(!actor.actor()->GetVisibility());
        QCOMPARE(actor.bounds()[1], 1.0);

        // Clipping off: everything back.
        clickCheckBox(child<QCheckBox>(panel, "clipEnabled"));
        QCOMPARE(int(actor.displayedTets().size()), mesh.tetCount());
        QCOMPARE(actor.boundary()->GetNumberOfCells(), vtkIdType(108));
    }

    void clippingAlongTheViewDirection() {
        const TetMesh mesh = distortedBox();
        VtkViewport viewport;
        viewport.resize(400, 300);
        viewport.setTetMesh(mesh);
        QualityPanel panel;
        panel.show();
        panel.attach(&viewport);
        TetMeshActor& actor = viewport.tetMeshActor();
        child<QComboBox>(panel, "clipAxis")->setCurrentIndex(int(QualityPanel::ClipAxis::View));
        child<QSlider>(panel, "clipPosition")->setValue(500);
        child<QCheckBox>(panel, "clipEnabled")->setChecked(true);
        QVERIFY(actor.clipEnabled());
        // The normal points towards the camera; part of the mesh is hidden.
        QVERIFY(actor.clipNormal().dot(viewDirection(viewport.camera())) < -0.999);
        QVERIFY(!actor.displayedTets().empty());
        QVERIFY(int(actor.displayedTets().size()) < mesh.tetCount());
    }

    void positionUpdateIsAFastPath() {
        TetMesh mesh = distortedBox();
        TetMeshActor actor;
        actor.setMesh(mesh);
        const int rebuilds = actor.cellRebuilds();
        vtkPolyData* poly = actor.boundary();
        const vtkMTimeType before = poly->GetPoints()->GetMTime();
        for (Vec3& p : mesh.positions())
            p += Vec3(0.1, -0.2, 0.05);
        QVERIFY(actor.updatePositions(mesh));
        QCOMPARE(actor.cellRebuilds(), rebuilds);
        QCOMPARE(actor.pointUpdates(), 1);
        QVERIFY(poly->GetPoints()->GetMTime() > before);
        Vec3 p;
        poly->GetPoints()->GetPoint(5, p.data());
        QCOMPARE(p, mesh.pos(5));
        QCOMPARE(poly->GetNumberOfCells(), vtkIdType(108));

        // Shrunk tets follow too.
        actor.setDisplayMode(TetDisplayMode::ShrunkTets);
        const int rebuilds2 = actor.cellRebuilds();
        mesh.positions()[0] += Vec3(0.01, 0, 0);
        QVERIFY(actor.updatePositions(mesh));
        QCOMPARE(actor.cellRebuilds(), rebuilds2);
        const Tet& t0 = mesh.tet(0);
        const Vec3 c =
            0.25 * (mesh.pos(t0[0]) + mesh.pos(t0[1]) + mesh.pos(t0[2]) + mesh.pos(t0[3]));
        poly->GetPoints()->GetPoint(0, p.data());
        QVERIFY((p - (c + actor.shrinkFactor() * (mesh.pos(t0[0]) - c))).norm() < 1e-12);

        // A different topology falls back to a rebuild.
        const TetMesh other = makeBoxTetMesh(Vec3::Zero(), Vec3::Ones(), 2, 2, 2);
        QVERIFY(!actor.updatePositions(other));
        QCOMPARE(actor.tetCount(), other.tetCount());
        QVERIFY(actor.cellRebuilds() > rebuilds2);
    }

    void histogramCountsSumToTheTetCount() {
        const TetMesh before = makeBoxTetMesh(Vec3::Zero(), Vec3::Ones(), 3, 3, 3);
        const TetMesh after = distortedBox();
        QualityPanel panel;
        panel.show();
        panel.resize(400, 600);
        panel.setBeforeMesh(before, 0.0);
        panel.setAfterMesh(after, 0.0);
        QualityHistogram* h = panel.histogram();
        using S = QualityHistogram::Series;
        for (S s : {S::Before, S::After}) {
            const std::vector<int> counts = h->binCounts(s);
            QCOMPARE(int(counts.size()), h->binCount());
            QCOMPARE(std::accumulate(counts.begin(), counts.end(), 0), 162);
        }
        // All Kuhn tets of the clean box have the same radius ratio: one bin holds them all.
        const std::vector<int> clean = h->binCounts(S::Before);
        QCOMPARE(*std::max_element(clean.begin(), clean.end()), 162);
        // The distorted box has tets in the bins below 0.5 (exactly the bad ones).
        const std::vector<int> bad = h->binCounts(S::After);
        const int lowBins = h->binCount() / 2;
        QCOMPARE(std::accumulate(bad.begin(), bad.begin() + lowBins, 0),
                 int(tetsBelow(after, QualityMeasure::RadiusRatio, h->binEdge(lowBins)).size()));

        // Switching the measure in the panel re-bins in degrees; counts still sum up.
        child<QComboBox>(panel, "overlayMeasure")
            ->setCurrentIndex(static_cast<int>(QualityMeasure::MinDihedral));
        QCOMPARE(h->measure(), QualityMeasure::MinDihedral);
        QCOMPARE(h->range().second, kRegularDihedralDeg);
        const std::vector<int> deg = h->binCounts(S::After);
        QCOMPARE(std::accumulate(deg.begin(), deg.end(), 0), 162);

        // Log scale is a display option only; painting works offscreen.
        clickCheckBox(child<QCheckBox>(panel, "histogramLogScale"));
        QVERIFY(h->logScale());
        QCOMPARE(h->binCounts(S::After), deg);
        h->resize(320, 180);
        QVERIFY(!h->grab().isNull());

        panel.clearAfter();
        QVERIFY(h->binCounts(S::After).empty());
    }

    void summaryTableMatchesSummarizeQuality() {
        const TetMesh before = makeBoxTetMesh(Vec3::Zero(), Vec3::Ones(), 3, 3, 3);
        const TetMesh after = distortedBox();
        QualityPanel panel;
        panel.show();
        QualitySummaryTable* table = panel.summaryTable();
        using T = QualitySummaryTable;
        panel.setBeforeMesh(before, 1.5e-4);
        QCOMPARE(table->value(T::Nodes, T::After), QStringLiteral("—"));
        QCOMPARE(table->value(T::Tets, T::After), QStringLiteral("—"));

        const QualitySummary s = summarizeQuality(before);
        auto near = [](const QString& text, double v) {
            bool ok = false;
            const double x = text.toDouble(&ok);
            return ok && std::abs(x - v) <= 1e-5 * std::max(1.0, std::abs(v));
        };
        QCOMPARE(table->value(T::Nodes, T::Before), QString::number(s.nodes));
        QCOMPARE(table->value(T::Edges, T::Before), QString::number(s.edges));
        QCOMPARE(table->value(T::Tets, T::Before), QString::number(s.tets));
        QVERIFY(near(table->value(T::MinRadiusRatio, T::Before), s.minRadiusRatio));
        QVERIFY(near(table->value(T::MinAspectRatioPaper, T::Before), s.minRadiusRatio / 3));
        QVERIFY(near(table->value(T::VolumeRatio, T::Before), s.volumeRatio));
        QVERIFY(near(table->value(T::EdgeRatio, T::Before), s.edgeRatio));
        QVERIFY(near(table->value(T::MinDihedral, T::Before), s.minDihedralDeg));
        QVERIFY(near(table->value(T::MaxDihedral, T::Before), s.maxDihedralDeg));
        QVERIFY(near(table->value(T::StableTimeStep, T::Before), 1.5e-4));
        QCOMPARE(table->value(T::Overlap, T::Before), QStringLiteral("—"));  // not given
        panel.setBeforeMesh(before, 1.5e-4, 0.0);
        QCOMPARE(table->value(T::Overlap, T::Before), QStringLiteral("0"));
        panel.setBeforeMesh(before, 1.5e-4, 0.125);
        QCOMPARE(table->value(T::Overlap, T::Before), QStringLiteral("0.125"));
        panel.setBeforeMesh(before, 1.5e-4, std::numeric_limits<double>::quiet_NaN());
        QCOMPARE(table->value(T::Overlap, T::Before), QStringLiteral("—"));
        QCOMPARE(table->verticalHeaderItem(T::Overlap)->text(), QStringLiteral("Overlap (mm)"));

        panel.setAfterMesh(after, 0.0);
        const QualitySummary a = summarizeQuality(after);
        QCOMPARE(table->value(T::Tets, T::After), QString::number(a.tets));
        QVERIFY(near(table->value(T::MinRadiusRatio, T::After), a.minRadiusRatio));
        QVERIFY(near(table->value(T::VolumeRatio, T::After), a.volumeRatio));
        QVERIFY(near(table->value(T::MinDihedral, T::After), a.minDihedralDeg));
        QCOMPARE(table->value(T::StableTimeStep, T::After), QStringLiteral("—"));
        QVERIFY(a.minRadiusRatio < s.minRadiusRatio);

        panel.clearAfter();
        QCOMPARE(table->value(T::Tets, T::After), QStringLiteral("—"));
    }

    // The per-tet schemes after a cut are the Tissue's (core/tissue, Tissue::schemes; the
    // studio's states are checked against it in test_tissue_session); the actor keeps what it
    // is given and answers None beyond it.
    void actorKeepsTheTetSchemes() {
        const std::vector<Scheme> schemes = {Scheme::B, Scheme::A, Scheme::None, Scheme::X, Scheme::A, Scheme::X};
        TetMeshActor actor;
        actor.setTetSchemes(schemes);
        for (int t = 0; t < int(schemes.size()); ++t)
            QCOMPARE(actor.tetScheme(t), schemes[t]);
        QCOMPARE(actor.tetScheme(99), Scheme::None);
        QCOMPARE(actor.tetScheme(-1), Scheme::None);
    }
};

QTEST_MAIN(TestQualityOverlay)
#include "test_quality_overlay.moc"
