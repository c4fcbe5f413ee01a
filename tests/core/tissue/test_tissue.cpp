// Tissue: the one path that applies a cut to the mesh, its embedded surface, its simulation,
// its anchors, schemes and pieces (core/tissue/tissue.h). Checked on the polyp sample at three
// scales: everything follows a cut; a cut cancelled before any stage leaves the tissue (and a
// running simulation) bit-identical to one that never saw it; copies cut identically; a tissue
// that moved is cut where it is now.
#include "core/mesh/masses.h"
#include "core/mesh/predicates.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"
#include "core/sim/fixed_nodes_effect.h"
#include "core/tissue/tissue.h"
#include "tissue_snapshot.h"

#include <QTest>

#include <limits>
#include <map>
#include <set>

using namespace resect;
using resect::testing::TissueSnapshot;

namespace {

/// The polyp (20 mm tall, base at z = 0) and its surface, scaled.
struct Inputs {
    TetMesh mesh;
    TriangleSurface surface;
    double scale = 1;
};

const Inputs& polyp(double scale) {
    static std::map<double, Inputs> cache;
    auto it = cache.find(scale);
    if (it != cache.end())
        return it->second;
    Inputs in;
    in.scale = scale;
    in.surface = sampleSurface(Sample::Polyp, 0.25);
    TriangleSurface meshed = in.surface;
    for (Vec3& p : meshed.positions)
        p *= scale;
    in.surface = meshed;
    if (!tetrahedralize(meshed, MeshingOptions{}, in.mesh).ok())
        qFatal("meshing the polyp failed");
    return cache.emplace(scale, std::move(in)).first->second;
}

/// The base of the stalk (z in [-0.5, 1] mm), as anchors.
FixedSelection baseAnchors(double scale) {
    FixedSelection f;
    f.box = std::array<Vec3, 2>{Vec3(-6, -6, -0.5) * scale, Vec3(6, 6, 1) * scale};
    return f;
}

Tissue makeTissue(double scale, bool withSurface = true) {
    const Inputs& in = polyp(scale);
    Tissue t;
    Material material;
    const Status s = Tissue::create(in.mesh, withSurface ? in.surface : TriangleSurface{}, material,
                                    baseAnchors(scale), t);
    if (!s.ok())
        qFatal("%s", s.message().c_str());
    return t;
}

/// A slightly tilted plane at height z (mm, before scaling) across the whole polyp.
SweepSurface planeAt(double z, double scale) {
    SweepSurface sweep;
    const Status s = SweepSurface::fromStartEnd({Vec3(-12, -12, z) * scale, Vec3(12, -12, z + 0.3) * scale},
                                                {Vec3(-12, 12, z + 0.2) * scale, Vec3(12, 12, z + 0.5) * scale},
                                                sweep);
    if (!s.ok())
        qFatal("bad sweep");
    return sweep;
}

/// Deformation, gravity and the anchored base. The mass-spring model's equilibrium strain
/// under gravity is g l / stiffness (Eq. 4: k = stiffness m / l^2), so gravity is scaled by
/// 1 / scale to give the same sag at every scale.
SimulationSetup sceneSetup(double scale = 1) {
    SimulationSetup setup;
    setup.effects = {"deformation", "gravity", "fixed"};
    setup.settings.gravity /= scale;
    setup.options.threads = 1;
    return setup;
}

} // namespace

class TestTissue : public QObject {
    Q_OBJECT
private slots:
    void cutFollowsEverything_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }
    void cutFollowsEverything() {
        QFETCH(double, scale);
        Tissue tissue = makeTissue(scale);
        QVERIFY(!tissue.anchors().empty());
        QVERIFY(tissue.startSimulation(sceneSetup(scale)).ok());
        const double dt = tissue.simulator()->timeStep();
        for (int i = 0; i < 10; ++i)
            QVERIFY(tissue.step(dt).ok());
        tissue.updateSurface();
        const int tetsBefore = tissue.mesh().tetCount();
        const double massBefore = sumOfMasses(tissue.mesh());
        const double volumeBefore = tissue.mesh().totalReferenceVolume();
        const double surfaceVolumeBefore = enclosedVolume(tissue.surface().surface());
        QCOMPARE(tissue.pieces().count, 1);

        TissueCut cut;
        const Status s = tissue.cut(planeAt(15, scale), CutOptions{}, &cut);
        QVERIFY2(s.ok(), s.message().c_str());
        const TetMesh& mesh = tissue.mesh();
        // Tets: the head is cut off, volume and mass (Eq. 3, updated locally) are conserved.
        QCOMPARE(tissue.pieces().count, 2);
        QCOMPARE(tissue.cutCount(), 1);
        // The improvement step (7) may collapse edges the cut left short, removing tets.
        QCOMPARE(mesh.tetCount(), tetsBefore + cut.tets.addedTets + cut.improveAddedTets - cut.removedTets);
        QVERIFY(cut.improveAddedTets >= 0);
        if (cut.flips + cut.splits == 0)
            QCOMPARE(cut.improveAddedTets, 0);  // only flips and splits add tets
        QVERIFY(cut.tets.addedTets > 0);
        QVERIFY(std::abs(mesh.totalReferenceVolume() - volumeBefore) <= 1e-12 * volumeBefore);
        QVERIFY(std::abs(sumOfMasses(mesh) - massBefore) <= 1e-12 * massBefore);
        // Schemes: every tet the cut made carries the scheme of its parent's cut.
        QCOMPARE(static_cast<int>(tissue.schemes().size()), mesh.tetCount());
        for (int t = cut.changes.firstNewTet; t < mesh.tetCount(); ++t)
            QVERIFY(tissue.schemes()[t] != Scheme::None);
        // Surface: cut and closed with caps; the pieces enclose what the whole did.
        QVERIFY(cut.surface.surface.capTriangles > 0);
        QVERIFY(cut.surface.surface.splitEdges > 0);
        const double surfaceVolumeAfter = enclosedVolume(tissue.surface().surface());
        QVERIFY2(std::abs(surfaceVolumeAfter - surfaceVolumeBefore) <= 1e-9 * std::abs(surfaceVolumeBefore),
                 qPrintable(QString("%1 -> %2").arg(surfaceVolumeBefore, 0, 'g', 17).arg(surfaceVolumeAfter, 0, 'g', 17)));
        QCOMPARE(tissue.surface().binding().vertexCount(), tissue.surface().surface().vertexCount());
        // Anchors: the tissue's and the fixed effect's are the same list.
        const auto* fixed = dynamic_cast<const FixedNodesEffect*>(tissue.simulator()->findEffect("fixed"));
        QVERIFY(fixed);
        QCOMPARE(fixed->nodes(), tissue.anchors().nodes());
        // Exactly one piece (the stalk) holds anchors.
        const Components& pieces = tissue.pieces();
        std::set<int> anchoredPieces;
        for (int n : tissue.anchors().nodes())
            anchoredPieces.insert(pieces.nodeComponent[n]);
        QCOMPARE(static_cast<int>(anchoredPieces.size()), 1);
        // No tet is inverted by the cut (nor by the improvement after it) where the tissue is now.
        for (int t = 0; t < mesh.tetCount(); ++t)
            QVERIFY2(mesh.currentVolume(t) > 0, qPrintable(QString("tet %1 after the cut").arg(t)));
        // The simulation goes on from where it was, with the cut's tets.
        QCOMPARE(tissue.simulator()->stepsTaken(), 10);
        // (At the step the cut tissue allows: the cut made smaller elements.)
        const double dtAfter = tissue.simulator()->timeStep();
        QVERIFY(dtAfter > 0 && dtAfter <= dt);
        for (int i = 0; i < 10; ++i)
            QVERIFY(tissue.step(dtAfter).ok());
        for (int t = 0; t < mesh.tetCount(); ++t)
            QVERIFY2(mesh.currentVolume(t) > 0, qPrintable(QString("tet %1 after 10 steps").arg(t)));
    }

    void anchorsFollowACutThroughThem() {
        // A cut through the anchored base: both copies of every anchored cut node stay
        // anchored, and the new nodes in the box are anchored.
        // (The cut alone: the change list is what the improvement step renumbers away.)
        Tissue tissue = makeTissue(1, false);
        Tissue improved = makeTissue(1, false);
        QVERIFY(tissue.startSimulation(sceneSetup()).ok());
        TissueCut cut;
        QVERIFY(tissue.cut(planeAt(0.4, 1), CutOptions{.improve = false}, &cut).ok());
        QVERIFY(!cut.changes.duplicatedNodes.empty());
        int anchoredCopies = 0;
        for (const auto& [orig, copy] : cut.changes.duplicatedNodes)
            if (tissue.anchors().contains(orig)) {
                QVERIFY(tissue.anchors().contains(copy));
                ++anchoredCopies;
            }
        QVERIFY(anchoredCopies > 0);
        const auto& box = *tissue.anchors().box();
        for (int n = cut.changes.firstNewNode; n < tissue.mesh().nodeCount(); ++n) {
            const Vec3& p = tissue.mesh().ref(n);
            const bool inBox = (p.array() >= box[0].array()).all() && (p.array() <= box[1].array()).all();
            if (inBox)
                QVERIFY(tissue.anchors().contains(n));
        }
        const auto* fixed = dynamic_cast<const FixedNodesEffect*>(tissue.simulator()->findEffect("fixed"));
        QCOMPARE(fixed->nodes(), tissue.anchors().nodes());
        // With the improvement (the default), still every node in the box is anchored and no
        // other is (the improvement may move anchored nodes, within the box:
        // ImproveOptions::moveAnchored), and the simulation holds them where they are now.
        QVERIFY(improved.startSimulation(sceneSetup()).ok());
        QVERIFY(improved.cut(planeAt(0.4, 1), CutOptions{}, &cut).ok());
        for (int n = 0; n < improved.mesh().nodeCount(); ++n) {
            const Vec3& p = improved.mesh().ref(n);
            const bool inBox = (p.array() >= box[0].array()).all() && (p.array() <= box[1].array()).all();
            QCOMPARE(improved.anchors().contains(n), inBox);
        }
        const auto* fixedAfter = dynamic_cast<const FixedNodesEffect*>(improved.simulator()->findEffect("fixed"));
        QCOMPARE(fixedAfter->nodes(), improved.anchors().nodes());
        std::vector<Vec3> heldAt;
        for (int n : improved.anchors().nodes())
            heldAt.push_back(improved.mesh().pos(n));
        for (int s = 0; s < 5; ++s)
            QVERIFY(improved.step(1e-4).ok());
        for (std::size_t i = 0; i < heldAt.size(); ++i)
            QCOMPARE(improved.mesh().pos(improved.anchors().nodes()[i]), heldAt[i]);
    }

    void cancelledCutChangesNothing_data() {
        QTest::addColumn<int>("stage");
        for (CutStage s : {CutStage::Intersect, CutStage::Select, CutStage::Decompose, CutStage::Snap,
                           CutStage::Relax, CutStage::RestState, CutStage::Surface})
            QTest::newRow(cutStageName(s)) << static_cast<int>(s);
    }
    void cancelledCutChangesNothing() {
        // Two identical tissues, both simulating; one gets a cut cancelled before `stage`
        // (the stages after Decompose cancel with the mesh already decomposed, snapped and
        // relaxed, Surface with the tet cut complete). It must stay bit-identical to the
        // other, and both must go on identically (simulation, then a real cut).
        QFETCH(int, stage);
        Tissue a = makeTissue(1), b = makeTissue(1);
        QVERIFY(a.startSimulation(sceneSetup()).ok());
        QVERIFY(b.startSimulation(sceneSetup()).ok());
        const double dt = a.simulator()->timeStep();
        for (int i = 0; i < 5; ++i) {
            QVERIFY(a.step(dt).ok());
            QVERIFY(b.step(dt).ok());
        }
        // Both refresh their index and surface the same way before a cut.
        a.updateSurface();
        b.updateSurface();
        CutOptions options;
        options.snap = true;
        options.relaxSteps = 10;
        const SweepSurface sweep = planeAt(15, 1);
        std::vector<CutStage> asked;
        const Status s = a.cut(sweep, options, nullptr, [&](CutStage s) {
            asked.push_back(s);
            return static_cast<int>(s) != stage;
        });
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("cancelled") != std::string::npos, s.message().c_str());
        QCOMPARE(static_cast<int>(asked.back()), stage);
        QCOMPARE(static_cast<int>(asked.size()), stage + 1);  // every stage before was asked, in order
        const TissueSnapshot after(a), untouched(b);
        const QString diff = after.differenceTo(untouched);
        QVERIFY2(diff.isEmpty(), qPrintable("changed by a cancelled cut: " + diff));
        QCOMPARE(a.pieces().count, 1);

        for (int i = 0; i < 5; ++i) {
            QVERIFY(a.step(dt).ok());
            QVERIFY(b.step(dt).ok());
        }
        TissueCut cutA, cutB;
        QVERIFY(a.cut(sweep, options, &cutA).ok());
        QVERIFY(b.cut(sweep, options, &cutB).ok());
        QVERIFY2(TissueSnapshot(a).differenceTo(TissueSnapshot(b)).isEmpty(),
                 qPrintable(TissueSnapshot(a).differenceTo(TissueSnapshot(b))));
        QCOMPARE(cutA.tets.touchedTets, cutB.tets.touchedTets);
        QCOMPARE(a.pieces().count, 2);
    }

    void copiesCutIdentically() {
        // A copy has the same spatial index and unit of d: the same later cuts give the same
        // tissue, down to the bits and the number of tets examined.
        Tissue a = makeTissue(1);
        QVERIFY(a.cut(planeAt(16, 1), CutOptions{}).ok());
        Tissue b(a);
        QVERIFY(!b.isSimulating());
        QCOMPARE(b.meanEdgeLength(), a.meanEdgeLength());
        CutOptions options;
        options.snap = true;
        options.relaxSteps = 5;
        for (double z : {13.0, 8.0}) {
            TissueCut ca, cb;
            QVERIFY(a.cut(planeAt(z, 1), options, &ca).ok());
            QVERIFY(b.cut(planeAt(z, 1), options, &cb).ok());
            QCOMPARE(ca.tets.touchedTets, cb.tets.touchedTets);
        }
        const QString diff = TissueSnapshot(a).differenceTo(TissueSnapshot(b));
        QVERIFY2(diff.isEmpty(), qPrintable(diff));
        QCOMPARE(a.pieces().count, 4);
    }

    void aTissueThatMovedIsCutWhereItIs() {
        // Under gravity with nothing anchored the polyp falls; a cut placed where it has
        // fallen to must cut it as it would a tissue created there (the spatial index
        // follows the simulation's steps).
        const Inputs& in = polyp(1);
        Tissue tissue;
        QVERIFY(Tissue::create(in.mesh, {}, Material{}, {}, tissue).ok());
        SimulationSetup setup;
        setup.effects = {"deformation", "gravity"};
        setup.options.threads = 1;
        QVERIFY(tissue.startSimulation(setup).ok());
        const double dt = tissue.simulator()->timeStep();
        // t = 0.1 s: a fall of g t^2 / 2 = 49 mm, well below where the polyp was.
        while (tissue.simulator()->time() < 0.1)
            QVERIFY(tissue.step(dt).ok());
        double top = -1e300;
        for (const Vec3& p : tissue.mesh().positions())
            top = std::max(top, p.z());
        QVERIFY(top < -20);
        const SweepSurface sweep = planeAt(top - 5, 1);
        Tissue fresh;
        QVERIFY(Tissue::create(tissue.mesh(), {}, Material{}, {}, fresh).ok());
        TissueCut moved, created;
        QVERIFY(tissue.cut(sweep, CutOptions{}, &moved).ok());
        QVERIFY(fresh.cut(sweep, CutOptions{}, &created).ok());
        QVERIFY(created.tets.crossedEdges > 0);
        QCOMPARE(moved.tets.crossedEdges, created.tets.crossedEdges);
        QCOMPARE(moved.tets.addedTets, created.tets.addedTets);
        QCOMPARE(tissue.pieces().count, 2);
    }

    void aTissueTurnedInsideOutIsCut() {
        // The simulation can turn tets inside out (a 1 mm femur pulled about by the loop had
        // one where the 8th of 20 pulls arrived, and that cut failed: "a cut polyhedron
        // cannot be split into positive tets"). Here every tet is: the current configuration
        // is the reference one mirrored (x -> -x). A plane across the stalk still cuts the
        // tissue in two, with its embedded surface, every tet positive in the reference
        // configuration and inside out in the current one, and the volume kept.
        const Inputs& in = polyp(1);
        TetMesh mirrored = in.mesh;
        for (int v = 0; v < mirrored.nodeCount(); ++v)
            mirrored.positions()[v] = mirrored.ref(v).cwiseProduct(Vec3(-1, 1, 1));
        Tissue tissue;
        QVERIFY(Tissue::create(mirrored, in.surface, Material{}, baseAnchors(1), tissue).ok());
        const double volume = tissue.mesh().totalReferenceVolume();
        TissueCut cut;
        const Status s = tissue.cut(planeAt(10, 1), CutOptions{}, &cut);
        QVERIFY2(s.ok(), s.message().c_str());
        QVERIFY(cut.tets.crossedEdges > 0);
        QVERIFY(cut.tets.addedTets > 0);
        QCOMPARE(tissue.pieces().count, 2);
        const TetMesh& m = tissue.mesh();
        for (int t = 0; t < m.tetCount(); ++t) {
            const Tet& q = m.tet(t);
            QVERIFY(orient3d(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])) > 0);
            QVERIFY2(orient3d(m.pos(q[0]), m.pos(q[1]), m.pos(q[2]), m.pos(q[3])) < 0, qPrintable(QString::number(t)));
        }
        QVERIFY(std::abs(m.totalReferenceVolume() - volume) <= 1e-12 * volume);
    }

    void resectedPiecesLeaveTheTissue_data() {
        QTest::addColumn<int>("policy");
        QTest::newRow("remove") << static_cast<int>(ResectedPieces::Remove);
        QTest::newRow("rigid") << static_cast<int>(ResectedPieces::Rigid);
    }
    void resectedPiecesLeaveTheTissue() {
        // The head cut off a polyp anchored at its base is resected: it leaves the tet mesh
        // and the surface, mass and volume are accounted for, the simulation goes on, and a
        // later cut through where the head was cuts nothing.
        QFETCH(int, policy);
        Tissue tissue = makeTissue(1);
        tissue.setResectedPieces(static_cast<ResectedPieces>(policy));
        QVERIFY(tissue.startSimulation(sceneSetup()).ok());
        const double dt = tissue.simulator()->timeStep();
        for (int i = 0; i < 5; ++i)
            QVERIFY(tissue.step(dt).ok());
        const double mass = sumOfMasses(tissue.mesh()), volume = tissue.mesh().totalReferenceVolume();
        const int tets = tissue.mesh().tetCount();
        TissueCut cut;
        QVERIFY(tissue.cut(planeAt(15, 1), CutOptions{}, &cut).ok());
        QCOMPARE(cut.resectedPieces, 1);
        QCOMPARE(static_cast<int>(tissue.chips().size()), 1);
        QCOMPARE(tissue.pieces().count, 1);
        const Chip& chip = tissue.chips().front();
        QCOMPARE(chip.cut, 1);
        QCOMPARE(tissue.mesh().tetCount() + chip.mesh.tetCount(), tets + cut.tets.addedTets + cut.improveAddedTets - cut.removedTets);
        QVERIFY(std::abs(sumOfMasses(tissue.mesh()) + tissue.resectedMass() - mass) <= 1e-12 * mass);
        QVERIFY(std::abs(tissue.mesh().totalReferenceVolume() + tissue.resectedVolume() - volume) <= 1e-12 * volume);
        QCOMPARE(tissue.resectedMass(), chip.mass);
        // The surface went with its piece: both closed.
        QVERIFY(!chip.surface.triangles.empty());
        QVERIFY(testing::surfaceIsClosed(chip.surface));
        QVERIFY(testing::surfaceIsClosed(tissue.surface().surface()));
        QCOMPARE(tissue.surface().binding().vertexCount(), tissue.surface().surface().vertexCount());
        // Every anchored node is still in the tissue; the fixed effect holds the same list.
        const auto* fixed = dynamic_cast<const FixedNodesEffect*>(tissue.simulator()->findEffect("fixed"));
        QVERIFY(fixed);
        QCOMPARE(fixed->nodes(), tissue.anchors().nodes());
        QCOMPARE(tissue.simulator()->stepsTaken(), 5);
        const double after = tissue.simulator()->timeStep();  // the cut's elements set it now
        for (int i = 0; i < 20; ++i) {
            const Status s = tissue.step(after);
            QVERIFY2(s.ok(), s.message().c_str());
        }
        if (static_cast<ResectedPieces>(policy) == ResectedPieces::Rigid) {
            // The head lies on the cut it was taken off with (gravity is -z): it rests on the
            // tissue's surface, following the stump as it sags, instead of falling through it
            // to the floor (0.2 s of free fall would take it 196 mm down).
            while (tissue.simulator()->time() < 0.2)
                QVERIFY(tissue.step(after).ok());
            const RigidBody& body = tissue.chips().front().body;
            // (Not falling: free fall would be at 1962 mm/s by now; on the tissue it follows
            // the surface, gaining at most one step of gravity between contacts.)
            QVERIFY2(body.velocity.norm() < 50, qPrintable(QString::number(body.velocity.norm())));
            double lowest = std::numeric_limits<double>::infinity();
            for (const Vec3& p : tissue.chips().front().mesh.positions())
                lowest = std::min(lowest, p.z());
            double tissueTop = -std::numeric_limits<double>::infinity();
            for (const Vec3& p : tissue.mesh().positions())
                tissueTop = std::max(tissueTop, p.z());
            QVERIFY2(lowest > 2, qPrintable(QString::number(lowest)));  // the floor is at 0
            QVERIFY2(lowest >= tissueTop - 1, qPrintable(QString("%1 vs %2").arg(lowest).arg(tissueTop)));
        }
        // Where the head was there is nothing left to cut.
        TissueCut again;
        QVERIFY(tissue.cut(planeAt(17, 1), CutOptions{}, &again).ok());
        QCOMPARE(again.tets.crossedEdges, 0);
        QCOMPARE(again.resectedPieces, 0);
    }

    void keptOrUnanchoredPiecesStay() {
        Tissue kept = makeTissue(1, false);  // ResectedPieces::Keep by default
        QVERIFY(kept.cut(planeAt(15, 1), CutOptions{}).ok());
        QCOMPARE(kept.pieces().count, 2);
        QVERIFY(kept.chips().empty());
        Tissue free;
        QVERIFY(Tissue::create(polyp(1).mesh, {}, Material{}, {}, free).ok());
        free.setResectedPieces(ResectedPieces::Remove);
        QVERIFY(free.cut(planeAt(15, 1), CutOptions{}).ok());
        QCOMPARE(free.pieces().count, 2);  // no anchors: nothing tells tissue from chip
        QVERIFY(free.chips().empty());
    }

    void refusals() {
        Tissue empty;
        QVERIFY(empty.empty());
        Status s = empty.cut(planeAt(15, 1), CutOptions{});
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("no tets") != std::string::npos, s.message().c_str());
        QVERIFY(!Tissue::create(TetMesh{}, {}, Material{}, {}, empty).ok());

        FixedSelection bad;
        bad.nodes = {0, 100000};
        s = Tissue::create(polyp(1).mesh, {}, Material{}, bad, empty);
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("100000") != std::string::npos, s.message().c_str());
        QVERIFY(empty.empty());  // unchanged on failure

        Tissue tissue = makeTissue(1, false);
        SimulationSetup setup = sceneSetup();
        setup.settings.fixed.nodes = {0};
        s = tissue.startSimulation(setup);
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("anchors") != std::string::npos, s.message().c_str());
        QVERIFY(!tissue.isSimulating());
        setup = sceneSetup();
        setup.effects.push_back("no-such-effect");
        QVERIFY(!tissue.startSimulation(setup).ok());
        QVERIFY(!tissue.isSimulating());

        CutOptions options;
        options.d = 0.7;
        s = tissue.cut(planeAt(15, 1), options);
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("[0, 0.5]") != std::string::npos, s.message().c_str());
        QCOMPARE(tissue.cutCount(), 0);
    }

    void replacedAnchorsAreCreatesAnchors() {
        // Re-anchoring an uncut tissue (the studio's fixed-region edits) gives the tissue that
        // create() makes with the new anchors: it cuts and resects identically.
        Tissue unanchored;
        QVERIFY(Tissue::create(polyp(1).mesh, polyp(1).surface, Material{}, {}, unanchored).ok());
        QVERIFY(unanchored.anchors().empty());
        QVERIFY(unanchored.setAnchors(baseAnchors(1)).ok());
        Tissue created = makeTissue(1);
        QCOMPARE(unanchored.anchors().nodes(), created.anchors().nodes());
        QVERIFY(!unanchored.anchors().empty());
        for (Tissue* t : {&unanchored, &created}) {
            t->setResectedPieces(ResectedPieces::Remove);
            QVERIFY(t->cut(planeAt(15, 1), CutOptions{}).ok());
        }
        QCOMPARE(unanchored.chips().size(), std::size_t(1));
        const QString diff = TissueSnapshot(unanchored).differenceTo(TissueSnapshot(created));
        QVERIFY2(diff.isEmpty(), qPrintable(diff));

        // Refused on a cut or simulated tissue, and for nodes outside the mesh; unchanged then.
        const std::vector<int> before = created.anchors().nodes();
        Status s = created.setAnchors({});
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("cut") != std::string::npos, s.message().c_str());
        QCOMPARE(created.anchors().nodes(), before);
        Tissue simulated = makeTissue(1, false);
        QVERIFY(simulated.startSimulation(sceneSetup()).ok());
        QVERIFY(!simulated.setAnchors({}).ok());
        Tissue fresh = makeTissue(1, false);
        FixedSelection bad;
        bad.nodes = {100000};
        const std::vector<int> anchored = fresh.anchors().nodes();
        QVERIFY(!fresh.setAnchors(bad).ok());
        QCOMPARE(fresh.anchors().nodes(), anchored);
    }

    void takeMeshLeavesAnEmptyTissue() {
        Tissue tissue = makeTissue(1, false);
        QVERIFY(tissue.cut(planeAt(15, 1), CutOptions{}).ok());
        const int tets = tissue.mesh().tetCount();
        const TetMesh mesh = std::move(tissue).takeMesh();
        QCOMPARE(mesh.tetCount(), tets);
        QVERIFY(tissue.empty());
    }
};

QTEST_GUILESS_MAIN(TestTissue)
#include "test_tissue.moc"
