// TissueDisplay and the actors it drives (issue 19, "see the cut"), on the polyp sample with
// its head cut off through the stalk, under the offscreen platform (the actors' VTK data, no
// rendering): pieces in distinct palette colours, cut faces where the cut is, resected chips
// shown / dimmed / hidden, explode moving the pieces' drawn centroids apart without touching
// the tissue, the last cut's tets and a picked tet outlined. Each case runs with the head kept
// in the tissue (no anchors: a second piece of the tet mesh) and resected (a rigid chip).

#include "core/mesh/topology.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"
#include "core/tissue/tissue.h"
#include "widgets/piece_colors.h"
#include "widgets/quality_legend.h"
#include "widgets/tissue_display.h"
#include "widgets/vtk_viewport.h"

#include "tests/widgets/drawn_pieces.h"

#include <QTest>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include <map>
#include <set>

using namespace resect;

namespace {

/// The stalk of the sample polyp is at about z = 9.5 mm: a plane there takes the head off.
constexpr double kStalkZ = 9.5;

const TetMesh& polypMesh() {
    static const TetMesh mesh = [] {
        TetMesh m;
        if (!tetrahedralize(sampleSurface(Sample::Polyp, 0.25), MeshingOptions{}, m).ok())
            qFatal("meshing the polyp failed");
        return m;
    }();
    return mesh;
}

SweepSurface planeAt(double z) {
    SweepSurface sweep;
    if (!SweepSurface::fromStartEnd({Vec3(-12, -12, z), Vec3(12, -12, z + 0.3)},
                                    {Vec3(-12, 12, z + 0.2), Vec3(12, 12, z + 0.5)}, sweep)
             .ok())
        qFatal("bad sweep");
    return sweep;
}

/// The polyp with its surface, cut through the stalk; anchored at its base and resecting into
/// rigid chips when `resect`.
Tissue cutPolyp(bool resect) {
    FixedSelection anchors;
    if (resect)
        anchors.box = std::array<Vec3, 2>{Vec3(-6, -6, -0.5), Vec3(6, 6, 1)};
    Tissue t;
    if (!Tissue::create(polypMesh(), sampleSurface(Sample::Polyp, 0.25), Material{}, anchors, t)
             .ok())
        qFatal("tissue");
    t.setResectedPieces(resect ? ResectedPieces::Rigid : ResectedPieces::Keep);
    if (!t.cut(planeAt(kStalkZ), CutOptions{}).ok())
        qFatal("cut");
    t.updateSurface();
    return t;
}

/// A viewport showing `tissue` as ShownTissue shows it.
struct Scene {
    VtkViewport viewport;
    TissueDisplay display{viewport};
    explicit Scene(const Tissue& tissue) {
        viewport.setTetMesh(tissue.mesh(), false);
        viewport.setSurface(tissue.surface().surface(), false);
        display.show(tissue);
    }
};

vtkDataArray* cellArray(vtkPolyData* poly, const char* name) {
    return poly->GetCellData()->GetArray(name);
}

std::array<int, 3> bytes(const Rgb& c) {
    return {int(std::lround(255 * c[0])), int(std::lround(255 * c[1])),
            int(std::lround(255 * c[2]))};
}

} // namespace

class TestTissueDisplay : public QObject {
    Q_OBJECT

private slots:
    void paletteColoursAreDistinct() {
        // Every pair among the first 30 pieces differs clearly, and none is near the cut colour.
        for (int a = 0; a < 30; ++a) {
            const Rgb ca = piecePalette(a);
            double toCut = 0;
            for (int k = 0; k < 3; ++k)
                toCut = std::max(toCut, std::abs(ca[k] - kCutFaceColour[k]));
            QVERIFY2(toCut > 0.15, qPrintable(QString("piece %1 looks like a cut face").arg(a)));
            for (int b = a + 1; b < 30; ++b) {
                const Rgb cb = piecePalette(b);
                double d = 0;
                for (int k = 0; k < 3; ++k)
                    d = std::max(d, std::abs(ca[k] - cb[k]));
                QVERIFY2(d > 0.05, qPrintable(QString("pieces %1 and %2").arg(a).arg(b)));
            }
        }
        QCOMPARE(piecePalette(3), piecePalette(3)); // stable: a function of the index alone
    }

    void colourByPieceTellsThePiecesApart_data() {
        QTest::addColumn<bool>("resect");
        QTest::newRow("head kept") << false;
        QTest::newRow("head resected") << true;
    }
    void colourByPieceTellsThePiecesApart() {
        QFETCH(bool, resect);
        const Tissue tissue = cutPolyp(resect);
        QCOMPARE(tissue.pieces().count + int(tissue.chips().size()), 2);
        QCOMPARE(int(tissue.chips().size()), resect ? 1 : 0);
        Scene s(tissue);
        QCOMPARE(s.display.pieceCount(), 2);
        QVERIFY(s.viewport.chipsActor().empty() != resect);

        // Quality colouring by default: the mapper maps the radius ratio, the legend shows.
        TetMeshActor& actor = s.viewport.tetMeshActor();
        QualityLegend legend;
        legend.update(actor);
        QVERIFY(legend.visible());
        QCOMPARE(QString::fromLatin1(actor.actor()->GetMapper()->GetArrayName()),
                 QString::fromLatin1(kRadiusRatioArray));

        s.display.setResected(TissueDisplay::Resected::Shown); // undimmed: the palette's colours
        s.display.setColorMode(TetColorMode::Piece);
        QCOMPARE(QString::fromLatin1(actor.actor()->GetMapper()->GetArrayName()),
                 QString::fromLatin1(kPieceColourArray));
        QCOMPARE(actor.actor()->GetMapper()->GetColorMode(), VTK_COLOR_MODE_DIRECT_SCALARS);
        legend.update(actor);
        QVERIFY(!legend.visible());
        const auto colours = test::drawnColoursByPiece(s.viewport);
        QCOMPARE(int(colours.size()), 2);
        // One colour per piece, the palette's, and different pieces differ.
        std::set<std::array<int, 3>> all;
        for (const auto& [piece, set] : colours) {
            QCOMPARE(int(set.size()), 1);
            QCOMPARE(*set.begin(), bytes(piecePalette(piece)));
            all.insert(*set.begin());
        }
        QCOMPARE(int(all.size()), 2);

        // Back to quality.
        s.display.setColorMode(TetColorMode::Quality);
        QCOMPARE(QString::fromLatin1(actor.actor()->GetMapper()->GetArrayName()),
                 QString::fromLatin1(kRadiusRatioArray));
    }

    void cutFacesAreWhereTheCutIs_data() { colourByPieceTellsThePiecesApart_data(); }
    void cutFacesAreWhereTheCutIs() {
        QFETCH(bool, resect);
        const Tissue tissue = cutPolyp(resect);
        Scene s(tissue);
        const double tolerance =
            0.2 * tissue.meanEdgeLength() + 0.5; // d, plus the tilt of the plane
        int cutCells = 0;
        for (TetMeshActor* actor : {&s.viewport.tetMeshActor(), &s.viewport.chipsActor()}) {
            vtkPolyData* poly = actor->boundary();
            if (poly->GetNumberOfCells() == 0)
                continue;
            vtkDataArray* flags = cellArray(poly, kCutFaceArray);
            QVERIFY(flags != nullptr);
            int flagged = 0;
            for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
                if (flags->GetTuple1(c) == 0)
                    continue;
                ++flagged;
                double b[6];
                poly->GetCell(c)->GetBounds(b);
                QVERIFY2(b[4] > kStalkZ - tolerance && b[5] < kStalkZ + tolerance,
                         qPrintable(QString("a cut face at z %1 .. %2").arg(b[4]).arg(b[5])));
            }
            // Both sides of the cut have theirs; the overlay draws exactly them.
            QVERIFY(flagged > 0);
            QCOMPARE(actor->cutFaces()->GetNumberOfCells(), vtkIdType(flagged));
            QVERIFY(actor->cutFacesActor()->GetVisibility());
            cutCells += flagged;
        }
        QVERIFY(cutCells > 0);
        // The surface's cut faces are drawn apart, textured by the sweep's (u, v).
        const TriangleSurface& surface = tissue.surface().surface();
        const auto cutTriangles = std::count(surface.cutFaces.begin(), surface.cutFaces.end(), 1);
        QVERIFY(cutTriangles > 0);
        SurfaceActor& surfaceActor = s.viewport.surfaceActor();
        QCOMPARE(surfaceActor.cutPolyData()->GetNumberOfCells(), vtkIdType(cutTriangles));
        QCOMPARE(surfaceActor.polyData()->GetNumberOfCells(),
                 vtkIdType(surface.triangleCount() - cutTriangles));
        vtkDataArray* uv = surfaceActor.cutPolyData()->GetPointData()->GetTCoords();
        QVERIFY(uv != nullptr);
        QVERIFY(surfaceActor.cutActor()->GetTexture() != nullptr);
        // A corner of a cut face has the sweep's (u, v), scaled.
        const Tri first =
            surface.triangles[std::find(surface.cutFaces.begin(), surface.cutFaces.end(), 1) -
                              surface.cutFaces.begin()];
        QCOMPARE(uv->GetComponent(first[0], 0),
                 SurfaceActor::kCutTextureScale * surface.cutUvs[first[0]].x());

        // Switched off: no overlay, and the surface draws its cut faces like the rest.
        s.display.setCutFacesVisible(false);
        QVERIFY(!s.viewport.tetMeshActor().cutFacesActor()->GetVisibility());
        QCOMPARE(surfaceActor.cutPolyData()->GetNumberOfCells(), vtkIdType(0));
        QCOMPARE(surfaceActor.polyData()->GetNumberOfCells(), vtkIdType(surface.triangleCount()));
        s.display.setCutFacesVisible(true);
        QVERIFY(s.viewport.tetMeshActor().cutFacesActor()->GetVisibility());

        // An uncut tissue has none.
        Tissue uncut;
        QVERIFY(Tissue::create(polypMesh(), {}, Material{}, {}, uncut).ok());
        Scene fresh(uncut);
        QCOMPARE(fresh.viewport.tetMeshActor().cutFaces()->GetNumberOfCells(), vtkIdType(0));
        QVERIFY(!fresh.viewport.tetMeshActor().cutFacesActor()->GetVisibility());
    }

    void resectedChipsAreDimmedOrHidden() {
        const Tissue tissue = cutPolyp(true);
        Scene s(tissue);
        TetMeshActor& chips = s.viewport.chipsActor();
        QVERIFY(!chips.empty());
        QCOMPARE(chips.tetCount(), tissue.chips().front().mesh.tetCount());
        s.display.setColorMode(TetColorMode::Piece);
        // Dimmed by default: drawn, faded towards the background.
        QCOMPARE(s.display.resected(), TissueDisplay::Resected::Dimmed);
        QVERIFY(chips.actor()->GetVisibility());
        QVERIFY(chips.fade() > 0);
        const auto dimmed = test::drawnColoursByPiece(s.viewport);
        QVERIFY(*dimmed.at(1).begin() != bytes(piecePalette(1)));
        QCOMPARE(*dimmed.at(0).begin(), bytes(piecePalette(0))); // the tissue is not dimmed

        s.display.setResected(TissueDisplay::Resected::Shown);
        QCOMPARE(chips.fade(), 0.0);
        QCOMPARE(*test::drawnColoursByPiece(s.viewport).at(1).begin(), bytes(piecePalette(1)));

        s.display.setResected(TissueDisplay::Resected::Hidden);
        QVERIFY(!chips.actor()->GetVisibility());
        QVERIFY(!chips.cutFacesActor()->GetVisibility());
        QVERIFY(s.viewport.tetMeshActor().actor()->GetVisibility());
        // With the surface on show, the chips' surfaces follow the same choice.
        s.display.setMeshesVisible(true, true);
        QVERIFY(!s.viewport.chipSurfacesActor().actor()->GetVisibility());
        s.display.setResected(TissueDisplay::Resected::Shown);
        QVERIFY(s.viewport.chipSurfacesActor().actor()->GetVisibility());
        QVERIFY(chips.actor()->GetVisibility());

        // In the quality colouring chips are grey, not tissue.
        s.display.setColorMode(TetColorMode::Quality);
        QVERIFY(!chips.actor()->GetMapper()->GetScalarVisibility());
        double rgb[3];
        chips.actor()->GetProperty()->GetColor(rgb);
        QCOMPARE(bytes({rgb[0], rgb[1], rgb[2]}), bytes(kResectedColour));
    }

    void explodeMovesThePiecesApartAndNotTheTissue_data() {
        colourByPieceTellsThePiecesApart_data();
    }
    void explodeMovesThePiecesApartAndNotTheTissue() {
        QFETCH(bool, resect);
        const Tissue tissue = cutPolyp(resect);
        const std::vector<Vec3> positions(tissue.mesh().positions().begin(),
                                          tissue.mesh().positions().end());
        const std::vector<Vec3> surfacePositions = tissue.surface().surface().positions;
        Scene s(tissue);
        s.display.setResected(TissueDisplay::Resected::Shown);
        const double apart0 = (test::drawnCentroid(s.viewport, 0) - test::drawnCentroid(s.viewport, 1)).norm();
        const Bounds before = s.viewport.sceneBounds();
        double previous = apart0;
        for (double f : {0.5, 1.0, TissueDisplay::kMaxExplode}) {
            s.display.setExplode(f);
            const double apart =
                (test::drawnCentroid(s.viewport, 0) - test::drawnCentroid(s.viewport, 1)).norm();
            QVERIFY2(apart > previous + 0.1 * apart0,
                     qPrintable(QString("%1: %2 after %3").arg(f).arg(apart).arg(previous)));
            previous = apart;
        }
        // Along the line between the centroids: the head moves up, the stalk down.
        QVERIFY(test::drawnCentroid(s.viewport, 1).z() > test::drawnCentroid(s.viewport, 0).z());
        // The scene's bounds take the exploded pieces in (the camera's clipping range).
        const Bounds after = s.viewport.sceneBounds();
        QVERIFY(after[5] - after[4] > before[5] - before[4]);
        // The high-resolution surface explodes with its tets.
        double p[3];
        s.viewport.surfaceActor().polyData()->GetPoint(0, p);
        const int piece0 = tissue.pieces().tetComponent[tissue.surface().binding().tetOf(0)];
        const Vec3 expected =
            surfacePositions[0] + s.display.explode() * s.display.explodeDirections()[piece0];
        QVERIFY((Vec3(p[0], p[1], p[2]) - expected).norm() < 1e-9 * (1 + expected.norm()));
        // The tissue did not move.
        QVERIFY(std::equal(positions.begin(), positions.end(), tissue.mesh().positions().begin()));
        QVERIFY(surfacePositions == tissue.surface().surface().positions);
        // Back to 0: drawn where they are.
        s.display.setExplode(0);
        QVERIFY(std::abs((test::drawnCentroid(s.viewport, 0) - test::drawnCentroid(s.viewport, 1)).norm() -
                         apart0) < 1e-9 * apart0);
        for (int n = 0; n < tissue.mesh().nodeCount(); ++n)
            QCOMPARE(s.viewport.tetMeshActor().displayedPosition(n), tissue.mesh().pos(n));
    }

    void aSimulationStepOnlyMovesPoints() {
        // Exploded, the tets follow new positions with their offsets and without a rebuild.
        const Tissue tissue = cutPolyp(false);
        Scene s(tissue);
        s.display.setExplode(1.0);
        TetMeshActor& actor = s.viewport.tetMeshActor();
        const int rebuilds = actor.cellRebuilds();
        std::vector<Vec3> moved(tissue.mesh().positions().begin(), tissue.mesh().positions().end());
        for (Vec3& p : moved)
            p.z() -= 1.0;
        QVERIFY(actor.updatePositions(moved));
        QCOMPARE(actor.cellRebuilds(), rebuilds);
        const int head = tissue.pieces().tetComponent[tissue.mesh().tetCount() - 1];
        const int node = tissue.mesh().tet(tissue.mesh().tetCount() - 1)[0];
        const Vec3 expected = moved[node] + 1.0 * s.display.explodeDirections()[head];
        QVERIFY((actor.displayedPosition(node) - expected).norm() < 1e-12 * (1 + expected.norm()));
        double p[3];
        actor.boundary()->GetPoints()->GetPoint(node, p);
        QVERIFY((Vec3(p[0], p[1], p[2]) - expected).norm() < 1e-12 * (1 + expected.norm()));
    }

    void chipsFollowTheirBodies() {
        // A simulation step moves the falling chip: follow() moves its drawn points (with its
        // explode offset), nothing is rebuilt.
        Tissue tissue = cutPolyp(true);
        SimulationSetup setup;
        setup.effects = {"deformation", "gravity", "fixed"};
        setup.options.threads = 1;
        QVERIFY(tissue.startSimulation(setup).ok());
        Scene s(tissue);
        s.display.setExplode(0.5);
        TetMeshActor& chips = s.viewport.chipsActor();
        const int rebuilds = chips.cellRebuilds();
        const Vec3 before = tissue.chips().front().mesh.pos(0);
        for (int i = 0; i < 20; ++i)
            QVERIFY(tissue.step(tissue.simulator()->timeStep()).ok());
        const Vec3 after = tissue.chips().front().mesh.pos(0);
        QVERIFY((after - before).norm() > 0);
        s.display.follow(tissue);
        QCOMPARE(chips.cellRebuilds(), rebuilds);
        const Vec3 expected =
            after + 0.5 * s.display.explodeDirections()[s.display.tissuePieceCount()];
        QVERIFY((chips.displayedPosition(0) - expected).norm() < 1e-12 * (1 + expected.norm()));
    }

    void lastCutTouchedTetsAreOutlined_data() { colourByPieceTellsThePiecesApart_data(); }
    void lastCutTouchedTetsAreOutlined() {
        QFETCH(bool, resect);
        const Tissue tissue = cutPolyp(resect);
        Scene s(tissue);
        TetMeshActor& actor = s.viewport.tetMeshActor();
        vtkPolyData* poly = actor.boundary();
        vtkDataArray* touched = cellArray(poly, kTouchedArray);
        vtkDataArray* tets = cellArray(poly, kTetIdArray);
        QVERIFY(touched && tets);
        int flagged = 0;
        for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
            const int t = int(tets->GetTuple1(c));
            QCOMPARE(touched->GetTuple1(c) != 0, tissue.tetCuts()[t] == 1);
            flagged += touched->GetTuple1(c) != 0;
        }
        QVERIFY(flagged > 0);
        QVERIFY(actor.touchedEdges()->GetNumberOfLines() >= flagged); // at least one edge each
        QVERIFY(actor.touchedActor()->GetVisibility());
        s.display.setLastCutHighlighted(false);
        QVERIFY(!actor.touchedActor()->GetVisibility());

        // A tissue without cuts has nothing touched.
        Tissue uncut;
        QVERIFY(Tissue::create(polypMesh(), {}, Material{}, {}, uncut).ok());
        Scene fresh(uncut);
        QCOMPARE(fresh.viewport.tetMeshActor().touchedEdges()->GetNumberOfLines(), vtkIdType(0));
    }

    void aPickedTetIsOutlined() {
        const Tissue tissue = cutPolyp(false);
        Scene s(tissue);
        TetMeshActor& actor = s.viewport.tetMeshActor();
        QCOMPARE(actor.pickedOutline()->GetNumberOfLines(), vtkIdType(0));
        const int tet = tissue.mesh().tetCount() / 2;
        s.display.setPickedTet(tet);
        QCOMPARE(s.display.pickedTet(), tet);
        vtkPolyData* outline = actor.pickedOutline();
        QCOMPARE(outline->GetNumberOfPoints(), vtkIdType(4));
        QCOMPARE(outline->GetNumberOfLines(), vtkIdType(6));
        QVERIFY(actor.pickedActor()->GetVisibility());
        const auto corners = [&] {
            std::vector<Vec3> c;
            for (int k = 0; k < 4; ++k) {
                double p[3];
                outline->GetPoint(k, p);
                c.emplace_back(p[0], p[1], p[2]);
            }
            return c;
        };
        for (int k = 0; k < 4; ++k)
            QCOMPARE(corners()[k], tissue.mesh().pos(tissue.mesh().tet(tet)[k]));
        // It moves with the explode view.
        s.display.setExplode(1.0);
        for (int k = 0; k < 4; ++k)
            QCOMPARE(corners()[k], actor.displayedPosition(tissue.mesh().tet(tet)[k]));
        // Drawn shrunk with its tet.
        actor.setDisplayMode(TetDisplayMode::ShrunkTets);
        const Tet& q = tissue.mesh().tet(tet);
        const Vec3 centroid =
            0.25 * (actor.displayedPosition(q[0]) + actor.displayedPosition(q[1]) +
                    actor.displayedPosition(q[2]) + actor.displayedPosition(q[3]));
        QVERIFY((corners()[0] - centroid).norm() <
                (actor.displayedPosition(q[0]) - centroid).norm());
        // None: hidden; an index outside the mesh: none.
        s.display.setPickedTet(-1);
        QVERIFY(!actor.pickedActor()->GetVisibility());
        s.display.setPickedTet(tissue.mesh().tetCount());
        QCOMPARE(s.display.pickedTet(), -1);
    }
};

QTEST_MAIN(TestTissueDisplay)
#include "test_tissue_display.moc"
