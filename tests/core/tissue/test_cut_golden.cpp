// Optimisations do not change cuts (issue 20): sequences of random intersecting cuts through
// Tissue::cut (scoops and mouse-like strokes; hybrid at the defaults with the improvement step,
// the bare hybrid pipeline, subdivision; with and without anchors and resection; with the
// embedded surface) give, after every cut, exactly the tet mesh that the unoptimised code gave:
// the same tets in the same order, the same node positions, reference positions and masses
// to the bit, and the same anchored nodes, schemes and cut marks. The fingerprints below were recorded with the code before issue 20's
// optimisations (166185c); the embedded surface's are its triangle count, the order of its
// triangles' corners, and a weighted sum of its positions compared to 1e-9 of its size (its
// update may round differently once vectorised).
//
// When a change is meant to change cuts, print the new fingerprints with
// RESECT_PRINT_GOLDEN=1 and say in the commit why they changed.
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"
#include "core/sweep/stroke_shapes.h"
#include "core/tissue/tissue.h"

#include "tests/core/fingerprint.h"

#include <QTest>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

using namespace resect;

namespace {

struct Fingerprint {
    int tets = 0, nodes = 0;
    std::uint64_t topology = 0;  ///< the tets' nodes in order
    std::uint64_t geometry = 0;  ///< positions, reference positions and masses, bit for bit
    int triangles = 0;           ///< the embedded surface's
    std::uint64_t surfaceTopology = 0;
    double surfaceSum = 0;       ///< sum over vertices of (i % 7 + 1) (x + 2 y + 3 z)
    std::uint64_t marks = 0;     ///< anchored nodes, schemes, cut marks of tets and nodes
};

using testing::Fnv1a;

Fingerprint fingerprintOf(const Tissue& tissue) {
    const TetMesh& m = tissue.mesh();
    Fingerprint f;
    f.tets = m.tetCount();
    f.nodes = m.nodeCount();
    Fnv1a topology, geometry;
    for (int t = 0; t < m.tetCount(); ++t)
        topology.add(m.tet(t).data(), sizeof(Tet));
    for (int n = 0; n < m.nodeCount(); ++n) {
        geometry.add(m.pos(n).data(), 3 * sizeof(double));
        geometry.add(m.ref(n).data(), 3 * sizeof(double));
        const double mass = m.masses()[n];
        geometry.add(&mass, sizeof(double));
    }
    f.topology = topology.h;
    f.geometry = geometry.h;
    const TriangleSurface& s = tissue.surface().surface();
    f.triangles = s.triangleCount();
    Fnv1a st;
    for (const auto& t : s.triangles)
        st.add(t.data(), sizeof(t));
    f.surfaceTopology = st.h;
    Fnv1a marks;
    marks.add(tissue.anchors().nodes().data(), tissue.anchors().nodes().size() * sizeof(int));
    marks.add(tissue.schemes().data(), tissue.schemes().size() * sizeof(Scheme));
    marks.add(tissue.tetCuts().data(), tissue.tetCuts().size() * sizeof(int));
    marks.add(tissue.onCutSurface().data(), tissue.onCutSurface().size());
    f.marks = marks.h;
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        const Vec3& p = s.positions[i];
        f.surfaceSum += static_cast<double>(i % 7 + 1) * (p.x() + 2 * p.y() + 3 * p.z());
    }
    return f;
}

enum class Setup { Defaults, Bare, Subdivision };

struct Case {
    const char* name;
    const char* body;  ///< "polyp", "myoma" or "box"
    double scale;
    Setup setup;
    bool anchored;     ///< anchored at the bottom 5 %, resected pieces removed
    int passes;
    unsigned seed;
};

const Case kCases[] = {
    {"polyp-defaults", "polyp", 1.0, Setup::Defaults, true, 10, 3},
    {"myoma-bare", "myoma", 1.0, Setup::Bare, false, 8, 5},
    {"box-defaults-1e-3", "box", 1e-3, Setup::Defaults, true, 10, 7},
    {"polyp-subdivision-1e3", "polyp", 1e3, Setup::Subdivision, false, 3, 11},
};

// Recorded at 166185c (RESECT_PRINT_GOLDEN=1), the rows with the mesh improvement again after
// its smoothing raised near-tied tets together, split edges and ran again around what it left
// bad (issue 16), again when it kept every node in the body and the nodes of the body's
// surface on it (issue 16), and again when it glued the two walls of each crack for the pass
// (issue 16: the later cuts of polyp-defaults and box-defaults-1e-3, which leave cracks whose
// walls both stay), and again when the improvement's overlap guard came (issue 16: the same
// rows' later cuts, where walls that are not glued meet); one row per cut.
struct Golden {
    const char* name;
    Fingerprint f;
};
const Golden kGolden[] = {
#include "cut_golden.inc"
};

CutOptions optionsOf(Setup setup) {
    CutOptions o;
    o.snap = true;
    o.relaxSteps = 10;
    if (setup != Setup::Defaults)
        o.improve = false;
    if (setup == Setup::Subdivision)
        o.method = CutMethod::Subdivision;
    return o;
}

/// The case's tissue (its embedded surface at detail 0.05 for the samples) and its cuts'
/// fingerprints.
std::vector<Fingerprint> runCase(const Case& c) {
    TetMesh mesh;
    TriangleSurface surface;
    if (std::strcmp(c.body, "box") == 0) {
        mesh = makeBoxTetMesh(Vec3::Zero(), Vec3(10, 10, 10) * c.scale, 6, 6, 6);
    } else {
        const Sample sample = std::strcmp(c.body, "polyp") == 0 ? Sample::Polyp : Sample::Myoma;
        TriangleSurface anatomy = sampleSurface(sample, 0.25);
        for (Vec3& p : anatomy.positions)
            p *= c.scale;
        MeshingOptions meshing;
        meshing.reorder = false;  // the meshes as recorded (the reordering came later)
        if (!tetrahedralize(anatomy, meshing, mesh).ok())
            qFatal("meshing %s failed", c.body);
        surface = sampleSurface(sample, 0.05);
        for (Vec3& p : surface.positions)
            p *= c.scale;
    }
    const Material material;
    computeLumpedMasses(mesh, material.density);
    std::vector<Vec3> points(mesh.positions().begin(), mesh.positions().end());
    const auto [lo, hi] = boundingBox(points);
    const Eigen::AlignedBox3d bounds(lo, hi);
    FixedSelection anchors;
    if (c.anchored) {
        const Vec3 margin = Vec3::Constant(0.01 * (hi - lo).norm());
        anchors.box = std::array<Vec3, 2>{lo - margin, Vec3(hi.x(), hi.y(), lo.z() + 0.05 * (hi.z() - lo.z())) + margin};
    }
    Tissue tissue;
    if (Status s = Tissue::create(std::move(mesh), surface, material, anchors, tissue); !s.ok())
        qFatal("%s: %s", c.name, s.message().c_str());
    if (c.anchored)
        tissue.setResectedPieces(ResectedPieces::Remove);
    const Vec3 axis = std::strcmp(c.body, "polyp") == 0 ? Vec3(1.2, 0.5, 0) * c.scale : Vec3(0.5 * (lo + hi));
    std::mt19937 rng(c.seed);
    std::uniform_real_distribution<double> jitter(-1, 1);
    std::vector<Fingerprint> out;
    for (int k = 0; k < c.passes; ++k) {
        SweepSurface sweep;
        if (k % 5 == 4) {
            MouseStrokeShape shape;
            shape.halfWidth = 0.3 * (hi.x() - lo.x());
            if (!SweepSurface::fromCurves(mouseStroke(rng, bounds, shape), sweep).ok())
                continue;
        } else {
            ScoopShape shape = resectionScoop(bounds, axis, k);
            shape.angle += 0.3 * jitter(rng);
            shape.centre += 0.05 * (hi - lo).cwiseProduct(Vec3(jitter(rng), jitter(rng), 0));
            if (!SweepSurface::fromCurves(loopScoop(shape), sweep).ok())
                qFatal("%s: scoop %d is not a valid sweep", c.name, k);
        }
        tissue.updateSurface();
        if (Status s = tissue.cut(sweep, optionsOf(c.setup)); !s.ok())
            qFatal("%s, pass %d: %s", c.name, k + 1, s.message().c_str());
        tissue.updateSurface();
        out.push_back(fingerprintOf(tissue));
    }
    return out;
}

} // namespace

class TestCutGolden : public QObject {
    Q_OBJECT
private slots:
    void cutsAreUnchanged_data() {
        QTest::addColumn<int>("index");
        for (int i = 0; i < static_cast<int>(std::size(kCases)); ++i)
            QTest::newRow(kCases[i].name) << i;
    }

    void cutsAreUnchanged() {
        QFETCH(int, index);
        const Case& c = kCases[index];
        const std::vector<Fingerprint> got = runCase(c);
        if (std::getenv("RESECT_PRINT_GOLDEN")) {
            for (const Fingerprint& f : got)
                std::printf("    {\"%s\", {%d, %d, 0x%016" PRIx64 "ull, 0x%016" PRIx64 "ull, %d, 0x%016" PRIx64
                            "ull, %.17g, 0x%016" PRIx64 "ull}},\n",
                            c.name, f.tets, f.nodes, f.topology, f.geometry, f.triangles, f.surfaceTopology,
                            f.surfaceSum, f.marks);
            QSKIP("printed the fingerprints");
        }
        std::vector<Fingerprint> want;
        for (const Golden& g : kGolden)
            if (std::strcmp(g.name, c.name) == 0)
                want.push_back(g.f);
        QCOMPARE(got.size(), want.size());
        double size = 0;
        for (std::size_t k = 0; k < got.size(); ++k)
            size = std::max(size, std::abs(want[k].surfaceSum));
        for (std::size_t k = 0; k < got.size(); ++k) {
            const QString at = QString("%1, cut %2").arg(c.name).arg(k + 1);
            const Fingerprint &g = got[k], &w = want[k];
            QVERIFY2(g.tets == w.tets && g.nodes == w.nodes,
                     qPrintable(at + QString(": %1 tets, %2 nodes; recorded %3, %4").arg(g.tets).arg(g.nodes).arg(w.tets).arg(w.nodes)));
            QVERIFY2(g.topology == w.topology, qPrintable(at + ": the tets differ"));
            QVERIFY2(g.geometry == w.geometry, qPrintable(at + ": positions, reference positions or masses differ"));
            QVERIFY2(g.triangles == w.triangles && g.surfaceTopology == w.surfaceTopology,
                     qPrintable(at + QString(": surface of %1 triangles; recorded %2 (or their corners differ)").arg(g.triangles).arg(w.triangles)));
            QVERIFY2(g.marks == w.marks, qPrintable(at + ": anchors, schemes or cut marks differ"));
            QVERIFY2(std::abs(g.surfaceSum - w.surfaceSum) <= 1e-9 * std::max(size, 1e-300),
                     qPrintable(at + QString(": surface positions: %1, recorded %2").arg(g.surfaceSum, 0, 'g', 17).arg(w.surfaceSum, 0, 'g', 17)));
        }
    }
};

QTEST_GUILESS_MAIN(TestCutGolden)
#include "test_cut_golden.moc"
