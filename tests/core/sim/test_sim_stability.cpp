// The stability suite (issue 6): named hard cases, each cut with the hybrid method (with
// snapping and 10 relaxation steps, the product's defaults) and then simulated for thousands
// of explicit steps at the stable time step (the default, which the simulator sub-steps
// where a configuration needs it: simulator.h), for hundreds of backward-Euler steps at ten
// times it, and with the product's implicit integrator, projective dynamics, for 300 steps of
// 1 ms and 30 frames of 1/60 s. Each run must stay finite, keep its kinetic energy bounded and end without an inverted
// tet. Every node starts with a random velocity (5 cm/s) that excites all modes of the mesh,
// the highest (those of the worst elements, which limit the time step) included. Gravity
// acts in every case; the bottom layer is anchored except where a case says otherwise.
//
// The same cuts with plain subdivision print, in the test output, how much smaller the
// stable time step becomes (the price of slivers: section 6 of the paper).
//
// Meshes are boxes of side 6 mm with 1 mm cells (nodes at integer coordinates), so sweeps
// through nodes, along faces and tangent to edges are exact contacts.
#include "core/cut/hybrid_cutter.h"
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/quality.h"
#include "core/mesh/stable_time_step.h"
#include "core/mesh/topology.h"
#include "core/mesh/validity.h"
#include "core/sim/simulator.h"
#include "core/tissue/tissue.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>

using namespace resect;

namespace {

constexpr double kSide = 6.0;  // mm; one cell is 1 mm

SweepSurface sweepFrom(const std::vector<std::vector<Vec3>>& curves) {
    SweepSurface s;
    const Status st = SweepSurface::fromCurves(curves, s);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

/// Planar quad: curve 0 = c + r0 w + s u, curve 1 = c + r1 w + s u, s in [-a, a].
SweepSurface quad(const Vec3& c, const Vec3& u, const Vec3& w, double a, double r0, double r1) {
    std::vector<Vec3> first, second;
    for (int j = 0; j <= 4; ++j) {
        const double s = -a + 2 * a * j / 4;
        first.push_back(c + r0 * w + s * u);
        second.push_back(c + r1 * w + s * u);
    }
    return sweepFrom({first, second});
}

/// A loop-electrode scoop: a half circle of radius r hanging below height `top`, moved along
/// `dir` from -reach to +reach through the point (cx, cy).
SweepSurface scoop(double cx, double cy, double angle, double r, double top, double reach) {
    const Vec3 dir(std::cos(angle), std::sin(angle), 0), side(-std::sin(angle), std::cos(angle), 0);
    std::vector<std::vector<Vec3>> curves;
    for (double s : {-reach, reach}) {
        std::vector<Vec3> curve;
        for (int j = 0; j <= 12; ++j) {
            const double phi = std::numbers::pi * j / 12;
            curve.push_back(Vec3(cx, cy, top) + s * dir + r * std::cos(phi) * side - r * std::sin(phi) * Vec3::UnitZ());
        }
        curves.push_back(curve);
    }
    return sweepFrom(curves);
}

struct HardCase {
    TetMesh mesh;
    std::vector<SweepSurface> sweeps;
    std::optional<std::array<Vec3, 2>> fixedBox;  ///< anchored region (reference coordinates)
    bool gravity = true;
    int minPieces = 1;
};

TetMesh box() { return makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(kSide), 6, 6, 6); }

/// The bottom layer of nodes is anchored (tissue attached to what lies below it).
std::array<Vec3, 2> bottom() { return {Vec3(-1, -1, -1), Vec3(kSide + 1, kSide + 1, 0.001)}; }

HardCase makeCase(const QString& name) {
    HardCase c;
    c.mesh = box();
    c.fixedBox = bottom();
    const Vec3 centre = Vec3::Constant(kSide / 2);
    if (name == "through existing nodes") {
        // x + 2y + 4z = 21 holds many nodes of the integer grid.
        c.sweeps = {quad(centre, Vec3(2, -1, 0), Vec3(4, 0, -1), 3, -3, 3)};
        c.minPieces = 2;
    } else if (name == "along an existing face") {
        c.sweeps = {quad(Vec3(3, 3, 3), Vec3(1, 0, 0), Vec3(0, 1, 0), 5, -5, 5)};
        c.minPieces = 2;
    } else if (name == "tangent to an edge") {
        // A plane at 45 degrees touching the box only along its edge x = 6, z = 6.
        c.sweeps = {quad(Vec3(kSide, 3, kSide), Vec3(0, 1, 0), Vec3(1, 0, -1), 5, -3, 3)};
    } else if (name == "an edge cut twice") {
        // A V-shaped stroke: edges along y near the bottom of the V cross both of its arms.
        const auto line = [](double y, double z) { return std::vector<Vec3>{Vec3(-1, y, z), Vec3(kSide + 1, y, z)}; };
        c.sweeps = {sweepFrom({line(2.3, 7.5), line(3.1, 2.5), line(3.9, 7.5)})};
        c.minPieces = 2;
    } else if (name == "ten intersecting scoops") {
        for (int k = 0; k < 10; ++k)
            c.sweeps.push_back(scoop(3.013, 2.987, 0.1 + k * std::numbers::pi / 10, 1.4 + 0.03 * k, kSide + 0.5, 4));
        c.minPieces = 2;
    } else if (name == "sliver-rich input mesh") {
        // Interior nodes jittered by up to 0.35 cells: many badly shaped tets (checked below).
        for (unsigned seed = 1;; ++seed) {
            TetMesh m = box();
            std::mt19937 rng(seed);
            std::uniform_real_distribution<double> u(-0.35, 0.35);
            for (int n = 0; n < m.nodeCount(); ++n) {
                const Vec3 p = m.ref(n);
                if ((p.array() > 0.5).all() && (p.array() < kSide - 0.5).all()) {
                    const Vec3 jitter(u(rng), u(rng), u(rng));
                    m.referencePositions()[n] += jitter;
                    m.positions()[n] = m.ref(n);
                }
            }
            if (checkValidity(m).empty()) {
                c.mesh = std::move(m);
                break;
            }
        }
        c.sweeps = {quad(centre + Vec3(0.013, -0.021, 0.017), Vec3(1, 0.2, 0.1).normalized(),
                         Vec3(-0.1, 0.3, 1).normalized(), 6, -6, 6)};
        c.minPieces = 2;
    } else if (name == "tiny fragment cut off") {
        // x + y + z = 17.4 cuts a corner 0.6 mm deep off the top corner (6, 6, 6).
        c.sweeps = {quad(Vec3(5.8, 5.8, 5.8), Vec3(1, -1, 0).normalized(), Vec3(1, 1, -2).normalized(), 2, -2, 2)};
        c.minPieces = 2;
    } else if (name == "partial cut ending inside a tet") {
        // The plane y = 3.37 from outside to x = 3.41, z in [-1, 7]: its end line runs
        // through the inside of tets.
        std::vector<Vec3> start, end;
        for (int j = 0; j <= 4; ++j) {
            const double z = -1 + 8.0 * j / 4;
            start.push_back(Vec3(-1, 3.37, z));
            end.push_back(Vec3(3.41, 3.37, z));
        }
        c.sweeps = {sweepFrom({start, end})};
    } else if (name == "pieces fall under gravity") {
        // Anchored on its left face; a slanted cut frees the right part, which falls.
        c.fixedBox = std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(0.001, kSide + 1, kSide + 1)};
        c.sweeps = {quad(Vec3(3.3, 3, 3), Vec3(0.1, 1, 0).normalized(), Vec3(-0.05, 0, 1).normalized(), 5, -5, 5)};
        c.minPieces = 2;
    } else {
        qFatal("unknown case %s", qPrintable(name));
    }
    return c;
}

CutOptions options(CutMethod method) {
    CutOptions o;
    o.method = method;
    if (method == CutMethod::Hybrid) {
        o.snap = true;
        o.relaxSteps = 10;
    }
    return o;
}

int invertedTets(const TetMesh& mesh) {
    int n = 0;
    for (int t = 0; t < mesh.tetCount(); ++t)
        n += mesh.currentVolume(t) > 0 ? 0 : 1;
    return n;
}

bool finite(const TetMesh& mesh) {
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (!mesh.pos(n).allFinite() || !mesh.velocities()[n].allFinite())
            return false;
    return true;
}

/// Random velocities of `speed` mm/s in every direction (reproducible).
void excite(TetMesh& mesh, double speed, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g(0.0, speed / std::sqrt(3.0));
    for (int n = 0; n < mesh.nodeCount(); ++n)
        mesh.velocities()[n] = Vec3(g(rng), g(rng), g(rng));
}

struct RunResult {
    QString failure;  ///< empty if the run stayed finite, bounded and valid
    double maxKinetic = 0;
    double dt = 0;
};

/// Simulates `steps` steps with the given integrator at `dtFactor` times the stable step.
/// (absoluteDt > 0: that step instead, for the implicit integrator at the product's 1 ms.)
RunResult simulate(TetMesh mesh, const HardCase& c, Integrator integrator, double dtFactor, int steps,
                   double absoluteDt = 0) {
    RunResult r;
    const Material material;
    SimulatorOptions so;
    so.integrator = integrator;
    Simulator sim(mesh, material, so);
    if (Status s = sim.addEffect("deformation"); !s.ok())
        qFatal("%s", s.message().c_str());
    if (c.gravity)
        if (Status s = sim.addEffect("gravity"); !s.ok())
            qFatal("%s", s.message().c_str());
    if (c.fixedBox) {
        EffectSettings settings;
        settings.fixed.box = c.fixedBox;
        if (Status s = sim.addEffect("fixed", settings); !s.ok())
            qFatal("%s", s.message().c_str());
    }
    const double stable = sim.stableTimeStep();
    r.dt = absoluteDt > 0 ? absoluteDt : dtFactor * stable;
    // Random velocities of 5 cm/s, a brisk tissue motion.
    // (Scaling the speed with 1 / dt instead drives the small elements of a cut far beyond
    // the linear range in which the stable estimate holds.)
    excite(mesh, 50.0, 7);
    const double kinetic0 = sim.kineticEnergy();
    // Bound: the initial kinetic energy amplified tenfold (the energy of a symplectic
    // integrator oscillates, most near the stability limit) plus twice what free fall could
    // add over the run. An unstable run grows exponentially past it.
    const double duration = steps * r.dt;
    const double g = 9810;
    const double bound = 10 * kinetic0 + sumOfMasses(mesh) * g * g * duration * duration;
    for (int i = 0; i < steps; ++i) {
        if (Status s = sim.step(r.dt); !s.ok()) {
            r.failure = QString("step %1: %2").arg(i).arg(QString::fromStdString(s.message()));
            return r;
        }
        r.maxKinetic = std::max(r.maxKinetic, sim.kineticEnergy());
        if (r.maxKinetic > bound) {
            r.failure = QString("step %1: kinetic energy %2 above the bound %3").arg(i).arg(r.maxKinetic).arg(bound);
            return r;
        }
    }
    if (!finite(mesh))
        r.failure = "non-finite state";
    else if (const int inv = invertedTets(mesh); inv > 0)
        r.failure = QString("%1 inverted tets").arg(inv);
    return r;
}

/// Cuts the case's mesh with every sweep; empty on success.
QString cut(HardCase& c, CutMethod method, CutStats* total = nullptr) {
    HybridCutter cutter(c.mesh);
    for (const SweepSurface& sweep : c.sweeps) {
        CutResult result;
        if (Status s = cutter.cut(sweep, options(method), result); !s.ok())
            return QString::fromStdString(s.message());
        if (total)
            total->decomposedTets += result.stats.decomposedTets;
    }
    computeLumpedMasses(c.mesh, Material{}.density);
    if (const auto problems = checkValidity(c.mesh); !problems.empty())
        return QString::fromStdString(problems.front().message);
    return {};
}

/// Issue 16: no node leaves the body's surface. On the box: how far the farthest node
/// (reference position) is outside it, and how far the farthest boundary node on no cut's
/// surface (Tissue::onCutSurface: a node of the box's surface alone) is off its six planes.
struct OffTheBox {
    double outside = 0, offSurface = 0;
};
OffTheBox offTheBox(const Tissue& tissue) {
    const TetMesh& m = tissue.mesh();
    std::vector<char> boundary(m.nodeCount(), 0);
    for (const BoundaryFace& f : boundaryFaces(m))
        for (int n : f.nodes)
            boundary[n] = 1;
    OffTheBox off;
    for (int n = 0; n < m.nodeCount(); ++n) {
        const Vec3 p = m.ref(n);
        off.outside = std::max(off.outside, std::max(-p.minCoeff(), p.maxCoeff() - kSide));
        if (boundary[n] && tissue.onCutSurface()[n] == 0)
            off.offSurface = std::max(off.offSurface, std::min(p.cwiseAbs().minCoeff(), (Vec3::Constant(kSide) - p).cwiseAbs().minCoeff()));
    }
    return off;
}

} // namespace

class TestSimStability : public QObject {
    Q_OBJECT
private slots:
    void hardCases_data() {
        QTest::addColumn<QString>("name");
        for (const char* name : {"through existing nodes", "along an existing face", "tangent to an edge",
                                 "an edge cut twice", "ten intersecting scoops", "sliver-rich input mesh",
                                 "tiny fragment cut off", "partial cut ending inside a tet", "pieces fall under gravity"})
            QTest::newRow(name) << QString(name);
    }
    void hardCases() {
        QFETCH(QString, name);
        HardCase c = makeCase(name);
        const double volume = c.mesh.totalReferenceVolume();
        if (name == "sliver-rich input mesh")
            QVERIFY(summarizeQuality(c.mesh).minRadiusRatio < 0.2);
        HardCase sub = c;  // the same case for plain subdivision

        const QString cutProblem = cut(c, CutMethod::Hybrid);
        QVERIFY2(cutProblem.isEmpty(), qPrintable(cutProblem));
        QVERIFY(std::abs(c.mesh.totalReferenceVolume() - volume) <= 1e-9 * volume);
        const int pieces = connectedComponents(c.mesh).count;
        QVERIFY2(pieces >= c.minPieces, qPrintable(QString("%1 pieces").arg(pieces)));
        if (name == "partial cut ending inside a tet")
            QCOMPARE(pieces, 1);

        // Explicit at the stable step, thousands of steps.
        const RunResult ex = simulate(c.mesh, c, Integrator::SymplecticEuler, 1.0, 3000);
        QVERIFY2(ex.failure.isEmpty(), qPrintable("explicit: " + ex.failure));
        const RunResult verlet = simulate(c.mesh, c, Integrator::VelocityVerlet, 1.0, 2000);
        QVERIFY2(verlet.failure.isEmpty(), qPrintable("Verlet: " + verlet.failure));
        // Implicit at ten times the stable step.
        const RunResult im = simulate(c.mesh, c, Integrator::BackwardEuler, 10.0, 300);
        QVERIFY2(im.failure.isEmpty(), qPrintable("implicit: " + im.failure));
        // The product's integrator, projective dynamics, at its 1 ms and at a 1/60 s frame.
        const RunResult pd = simulate(c.mesh, c, Integrator::ProjectiveDynamics, 0, 300, 1e-3);
        QVERIFY2(pd.failure.isEmpty(), qPrintable("projective dynamics, 1 ms: " + pd.failure));
        const RunResult frame = simulate(c.mesh, c, Integrator::ProjectiveDynamics, 0, 30, 1.0 / 60);
        QVERIFY2(frame.failure.isEmpty(), qPrintable("projective dynamics, 1/60 s: " + frame.failure));

        // Subdivision on the same case: how much smaller its stable step is.
        const QString subProblem = cut(sub, CutMethod::Subdivision);
        QVERIFY2(subProblem.isEmpty(), qPrintable(subProblem));
        const Material material;
        const double hybridDt = stableTimeStep(c.mesh, material).dt;
        const double subdivisionDt = stableTimeStep(sub.mesh, material).dt;
        qInfo("%s: hybrid %d tets, min radius ratio %.3g, stable dt %.3g s; subdivision %d tets, min radius "
              "ratio %.3g, stable dt %.3g s (%.1fx smaller)",
              qPrintable(name), c.mesh.tetCount(), summarizeQuality(c.mesh).minRadiusRatio, hybridDt,
              sub.mesh.tetCount(), summarizeQuality(sub.mesh).minRadiusRatio, subdivisionDt,
              hybridDt / subdivisionDt);
        QVERIFY(hybridDt > 0 && subdivisionDt > 0);
    }

    void tenScoopsMovedAbout() {
        // The ten scoops of tenScoopsThroughTheTissue, moved about: scoop k through
        // (3.013 + s sin(7k + 1), 2.987 + s cos(5k + 2)) for s = 0, 0.02, ..., 0.5 mm. The worst
        // tet after any cut, over the input's: at least 0.5 in most placements and never
        // catastrophic; no node ever outside the box, and the nodes of its surface within 1 % of
        // a cell of it (offTheBox). Measured: 20 of 26 at 0.5 or more, 0.541 on average, 0.314
        // at the least, no node outside, the box's surface nodes on it up to rounding (before the
        // improvement's overlap guard: 19, 0.534, 0.294; with each crack wall improved on its
        // own, before the glued cracks: 19, 0.544, 0.30, and 0.0051 mm off the surface in one
        // placement). Before the
        // improvement kept to the body's surface: 16, 0.51, 0.26, with nodes up to 0.43 mm
        // outside the box; before issue 16's splits and repeated passes: 2, 0.34, 0.02. Issue
        // 16 asks 0.5 everywhere: not reached yet.
        const TetMesh input = box();
        const double ratio0 = summarizeQuality(input).minRadiusRatio;
        const Material material;
        int good = 0;
        double sum = 0, least = 1, offSurface = 0, overlap = 0;
        const int placements = 26;
        for (int i = 0; i < placements; ++i) {
            const double shift = 0.02 * i;
            TetMesh mesh = input;
            computeLumpedMasses(mesh, material.density);
            FixedSelection anchors;
            anchors.box = bottom();
            Tissue tissue;
            QVERIFY(Tissue::create(mesh, {}, material, anchors, tissue).ok());
            tissue.setResectedPieces(ResectedPieces::Remove);
            double worst = 1;
            for (int k = 0; k < 10; ++k) {
                const SweepSurface sweep = scoop(3.013 + shift * std::sin(7.0 * k + 1), 2.987 + shift * std::cos(5.0 * k + 2),
                                                 0.1 + k * std::numbers::pi / 10, 1.4 + 0.03 * k, kSide + 0.5, 4);
                const Status st = tissue.cut(sweep, CutOptions{.snap = true, .relaxSteps = 10});
                QVERIFY2(st.ok(), st.message().c_str());
                worst = std::min(worst, summarizeQuality(tissue.mesh()).minRadiusRatio / ratio0);
                const OffTheBox off = offTheBox(tissue);
                QVERIFY2(off.outside <= 1e-9 * kSide, qPrintable(QString("placement %1, cut %2: a node %3 mm outside the box").arg(i).arg(k + 1).arg(off.outside)));
                offSurface = std::max(offSurface, off.offSurface);
                overlap = std::max(overlap, deepestOverlap(tissue.mesh()).depth);
            }
            if (const auto problems = checkValidity(tissue.mesh()); !problems.empty())
                QFAIL(problems.front().message.c_str());
            good += worst >= 0.5 ? 1 : 0;
            sum += worst;
            least = std::min(least, worst);
        }
        qInfo("ten scoops in %d placements: %d at 0.5 x the input's worst ratio or more, %.3f on average, %.3f at "
              "the least; nodes of the box's surface at most %.3g mm off it; overlap %.3g mm",
              placements, good, sum / placements, least, offSurface, overlap);
        // Known defect (README, "Crack walls: glued for the improvement"): the improvement reaches these figures
        // partly by pushing one wall of a crack into the other (0.118 mm, measured, with the
        // overlap guard's slack, ImproveOptions::overlapSlack; 0.21 before the guard, 0.22 with
        // the walls improved on their own, before the glued cracks). Issue 16 asks for none;
        // this bound only keeps it from growing unseen.
        QVERIFY2(overlap <= 0.13, qPrintable(QString::number(overlap)));
        QVERIFY2(offSurface <= 0.01, qPrintable(QString::number(offSurface)));
        QVERIFY2(good >= 20, qPrintable(QString::number(good)));
        QVERIFY2(sum / placements >= 0.535, qPrintable(QString::number(sum / placements)));
        QVERIFY2(least >= 0.3, qPrintable(QString::number(least)));
    }

    void tenScoopsThroughTheTissue() {
        // The ten intersecting scoops as the product makes them (Tissue::cut at the defaults:
        // the mesh improvement after every cut, chips off the anchored base removed): the
        // remaining tissue keeps its worst element within 0.5 times the input's after every
        // cut (the bare cutter above leaves 3e-5; measured 0.58 at worst, 0.70 before the
        // improvement's overlap guard, 0.52 before the glued cracks), no node leaves the
        // box's surface (none outside it, those of its surface on it up to rounding), its
        // stable step stays within a factor 7 of the input's, and it simulates stably at that
        // step. (The same ten scoops moved by up to 0.5 mm reach 0.5 in 20 placements of 26:
        // tenScoopsMovedAbout.)
        HardCase c = makeCase("ten intersecting scoops");
        const Material material;
        computeLumpedMasses(c.mesh, material.density);
        const double ratio0 = summarizeQuality(c.mesh).minRadiusRatio;
        const double dt0 = stableTimeStep(c.mesh, material).dt;
        const double volume0 = c.mesh.totalReferenceVolume();
        FixedSelection anchors;
        anchors.box = c.fixedBox;
        Tissue tissue;
        QVERIFY(Tissue::create(c.mesh, {}, material, anchors, tissue).ok());
        tissue.setResectedPieces(ResectedPieces::Remove);
        double worst = 1, overlap = 0;
        for (const SweepSurface& sweep : c.sweeps) {
            TissueCut cut;
            const Status st = tissue.cut(sweep, CutOptions{.snap = true, .relaxSteps = 10}, &cut);
            QVERIFY2(st.ok(), st.message().c_str());
            const double ratio = summarizeQuality(tissue.mesh()).minRadiusRatio;
            worst = std::min(worst, ratio);
            overlap = std::max(overlap, deepestOverlap(tissue.mesh()).depth);
            QVERIFY2(ratio >= 0.5 * ratio0, qPrintable(QString("after cut %1: %2 (input %3)").arg(tissue.cutCount()).arg(ratio).arg(ratio0)));
            const OffTheBox off = offTheBox(tissue);
            QVERIFY2(off.outside <= 1e-9 * kSide && off.offSurface <= 1e-9 * kSide,
                     qPrintable(QString("after cut %1: a node %2 mm outside the box, one of its surface %3 mm off it")
                                    .arg(tissue.cutCount()).arg(off.outside).arg(off.offSurface)));
        }
        QVERIFY(tissue.chips().size() >= 1);
        QVERIFY(std::abs(tissue.mesh().totalReferenceVolume() + tissue.resectedVolume() - volume0) <= 1e-9 * volume0);
        const double dt = stableTimeStep(tissue.mesh(), material).dt;
        qInfo("ten scoops through the tissue: %d tets, %zu chips, min radius ratio %.3g at the end, %.3g at worst "
              "(input %.3g), stable dt %.3g s (input %.3g s); overlap %.3g mm",
              tissue.mesh().tetCount(), tissue.chips().size(), summarizeQuality(tissue.mesh()).minRadiusRatio, worst,
              ratio0, dt, dt0, overlap);
        // Known defect (README, "Crack walls: glued for the improvement"): one wall of a crack
        // is pushed 0.068 mm into another (measured, within the overlap guard's slack; 0.15 mm
        // before the guard, 0.19 mm before the glued cracks). This bound keeps it from growing
        // unseen.
        QVERIFY2(overlap <= 0.08, qPrintable(QString::number(overlap)));
        QVERIFY(dt >= 0.15 * dt0);  // measured 0.40 x (the bare cutter: 1e-4 x)
        if (const auto problems = checkValidity(tissue.mesh()); !problems.empty())
            QFAIL(problems.front().message.c_str());
        HardCase after = c;
        after.mesh = tissue.mesh();
        // At the estimated stable step, kept stable by the simulator's sub-steps (a fixed step
        // there diverged after about 1000 steps on this mesh before issue 17).
        const RunResult ex = simulate(after.mesh, after, Integrator::SymplecticEuler, 1.0, 3000);
        QVERIFY2(ex.failure.isEmpty(), qPrintable("explicit: " + ex.failure));
        const RunResult im = simulate(after.mesh, after, Integrator::BackwardEuler, 10.0, 300);
        QVERIFY2(im.failure.isEmpty(), qPrintable("implicit: " + im.failure));
        const RunResult pd = simulate(after.mesh, after, Integrator::ProjectiveDynamics, 0, 300, 1e-3);
        QVERIFY2(pd.failure.isEmpty(), qPrintable("projective dynamics, 1 ms: " + pd.failure));
    }

    void piecesReallyFall() {
        // The freed part of "pieces fall under gravity" falls as a free body: after t its
        // centre of mass has dropped by g t^2 / 2 (within 5 %); the anchored part hangs.
        HardCase c = makeCase("pieces fall under gravity");
        QVERIFY(cut(c, CutMethod::Hybrid).isEmpty());
        const Components comp = connectedComponents(c.mesh);
        QCOMPARE(comp.count, 2);
        const int anchoredPiece = comp.nodeComponent[0];  // node 0 is at the origin, anchored
        const auto centreZ = [&](int piece) {
            double mz = 0, m = 0;
            for (int n = 0; n < c.mesh.nodeCount(); ++n)
                if (comp.nodeComponent[n] == piece) {
                    mz += c.mesh.masses()[n] * c.mesh.pos(n).z();
                    m += c.mesh.masses()[n];
                }
            return mz / m;
        };
        const int freePiece = 1 - anchoredPiece;
        const double z0 = centreZ(freePiece), anchoredZ0 = centreZ(anchoredPiece);
        Simulator sim(c.mesh, Material{}, {});
        QVERIFY(sim.addEffect("deformation").ok());
        QVERIFY(sim.addEffect("gravity").ok());
        EffectSettings settings;
        settings.fixed.box = c.fixedBox;
        QVERIFY(sim.addEffect("fixed", settings).ok());
        const double dt = sim.stableTimeStep();
        const int steps = 2000;
        for (int i = 0; i < steps; ++i)
            QVERIFY(sim.step(dt).ok());
        const double t = steps * dt;
        const double drop = z0 - centreZ(freePiece);
        QVERIFY2(std::abs(drop - 0.5 * 9810 * t * t) <= 0.05 * 0.5 * 9810 * t * t,
                 qPrintable(QString("dropped %1 mm, free fall %2 mm").arg(drop).arg(0.5 * 9810 * t * t)));
        QVERIFY(std::abs(anchoredZ0 - centreZ(anchoredPiece)) < 0.2 * drop);
        QCOMPARE(invertedTets(c.mesh), 0);
    }
};

QTEST_GUILESS_MAIN(TestSimStability)
#include "test_sim_stability.moc"
