// Tests of the stable explicit time step: it bounds the spectrum, scales with size, and an
// explicit run of the linearised mass-spring model is stable at it and unstable above it.
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/stable_time_step.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace resect;

namespace {

TetMesh jitteredBox(double scale, unsigned seed, double jitter) {
    TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(4, 3, 2) * scale, 4, 3, 2);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter * scale, jitter * scale);
    for (int n = 0; n < m.nodeCount(); ++n) {
        const Vec3 p = m.ref(n);
        const bool interior = p.x() > 0 && p.y() > 0 && p.z() > 0 && p.x() < 4 * scale &&
                              p.y() < 3 * scale && p.z() < 2 * scale;
        if (interior) {
            m.referencePositions()[n] += Vec3(u(rng), u(rng), u(rng));
            m.positions()[n] = m.ref(n);
        }
    }
    computeLumpedMasses(m, Material{}.density);
    return m;
}

struct Run {
    double energyGrowth = 0;  ///< max of E = 1/2 v'Mv + 1/2 x'Kx over the run / initial E
    double shadowDrift = 0;   ///< relative change of the integrator's conserved form
};

/// Symplectic Euler (v += -h M^-1 K x; x += h v) on M x'' = -K x from a random displacement.
/// For this scheme Q = v'Mv + x'Kx - h v'Kx is conserved exactly for any h; it is positive
/// definite, and so the motion bounded, iff h * omega_max < 2. The plain energy E then
/// oscillates within a factor (1 + h w / 2) / (1 - h w / 2) (39 at h w = 1.9) but never
/// grows; above the limit it grows exponentially.
Run simulate(const TetMesh& m, const Material& mat, double dt, int steps) {
    const int n = m.nodeCount();
    std::vector<Vec3> x(n), v(n, Vec3::Zero()), f(n);
    std::mt19937 rng(7);
    std::normal_distribution<double> g(0.0, 1e-3);
    for (auto& p : x)
        p = Vec3(g(rng), g(rng), g(rng));
    const auto mass = m.masses();
    auto forms = [&](double& energy, double& shadow) {
        applyRestStiffness(m, mat, x, f);
        energy = 0;
        shadow = 0;
        for (int i = 0; i < n; ++i) {
            energy += 0.5 * mass[i] * v[i].squaredNorm() + 0.5 * x[i].dot(f[i]);
            shadow += mass[i] * v[i].squaredNorm() + x[i].dot(f[i]) - dt * v[i].dot(f[i]);
        }
    };
    double e0 = 0, q0 = 0;
    forms(e0, q0);
    Run run;
    double emax = e0;
    for (int s = 0; s < steps; ++s) {
        applyRestStiffness(m, mat, x, f);
        for (int i = 0; i < n; ++i) {
            v[i] -= dt * f[i] / mass[i];
            x[i] += dt * v[i];
        }
        double e = 0, q = 0;
        forms(e, q);
        emax = std::max(emax, e);
        run.shadowDrift = std::max(run.shadowDrift, std::abs(q - q0) / q0);
        if (!std::isfinite(emax) || emax > 1e12 * e0)
            break;
    }
    run.energyGrowth = emax / e0;
    return run;
}

} // namespace

class TestStableTimeStep : public QObject {
    Q_OBJECT
private slots:
    void estimateIsBelowGershgorin() {
        const TetMesh m = jitteredBox(1.0, 1, 0.2);
        const StableTimeStep s = stableTimeStep(m, Material{});
        QVERIFY(s.dt > 0);
        QVERIFY(s.lambdaMax > 0);
        QVERIFY(s.lambdaMax <= s.gershgorinBound);
        QVERIFY(s.iterations > 1);
        QVERIFY(std::abs(s.dt - 0.95 * 2 / std::sqrt(s.lambdaMax)) < 1e-12 * s.dt);
    }

    void scalesLinearlyWithSize_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1e3") << 1e3;
    }
    void scalesLinearlyWithSize() {
        // k_s = k (m_a + m_b) / l^2 and m ~ L^3: omega^2 ~ k / L^2, so dt ~ L / sqrt(k).
        QFETCH(double, scale);
        const double dt1 = stableTimeStep(jitteredBox(1.0, 3, 0.2), Material{}).dt;
        const double dts = stableTimeStep(jitteredBox(scale, 3, 0.2), Material{}).dt;
        QVERIFY2(std::abs(dts / dt1 - scale) < 1e-6 * scale,
                 qPrintable(QString("%1 vs %2").arg(dts / dt1).arg(scale)));
    }

    void stiffnessAndDensityEnterAsExpected() {
        const TetMesh m = jitteredBox(1.0, 5, 0.2);
        Material stiff;
        stiff.stiffness *= 4;
        const double dt = stableTimeStep(m, Material{}).dt;
        QVERIFY(std::abs(stableTimeStep(m, stiff).dt - dt / 2) < 1e-6 * dt);
        // Density cancels: masses and stiffnesses both scale with it (Eq. 3 and 4).
        TetMesh heavy = m;
        computeLumpedMasses(heavy, 10 * Material{}.density);
        QVERIFY(std::abs(stableTimeStep(heavy, Material{}).dt - dt) < 1e-6 * dt);
    }

    void explicitRunStableAtEstimateUnstableAbove_data() {
        QTest::addColumn<double>("jitter");
        QTest::addColumn<unsigned>("seed");
        QTest::newRow("regular") << 0.0 << 1u;
        QTest::newRow("jittered") << 0.25 << 2u;
        QTest::newRow("strongly jittered") << 0.4 << 3u;
    }
    void explicitRunStableAtEstimateUnstableAbove() {
        QFETCH(double, jitter);
        QFETCH(unsigned, seed);
        const TetMesh m = jitteredBox(1.0, seed, jitter);
        const Material mat;
        const StableTimeStep s = stableTimeStep(m, mat);
        const Run at = simulate(m, mat, s.dt, 3000);
        QVERIFY2(at.energyGrowth < 60, qPrintable(QString("energy grew %1x at dt").arg(at.energyGrowth)));
        QVERIFY2(at.shadowDrift < 1e-6, qPrintable(QString("drift %1").arg(at.shadowDrift)));
        const Run above = simulate(m, mat, 1.2 * 2 / std::sqrt(s.lambdaMax), 3000);
        QVERIFY2(above.energyGrowth > 1e6,
                 qPrintable(QString("energy grew only %1x above dt").arg(above.energyGrowth)));
    }

    void sliverMeshHasSmallerStep() {
        // Pushing one interior node close to its neighbour shrinks an edge ten-fold and
        // flattens the tets around it: the stable step must drop accordingly.
        TetMesh m = jitteredBox(1.0, 9, 0.0);
        const double dt = stableTimeStep(m, Material{}).dt;
        const int node = 1 + 5 * (1 + 4 * 1);  // interior node (1, 1, 1)
        QVERIFY(m.ref(node).isApprox(Vec3(1, 1, 1)));
        m.referencePositions()[node] += Vec3(0.9, 0, 0);
        m.positions()[node] = m.ref(node);
        for (int t = 0; t < m.tetCount(); ++t)
            QVERIFY(m.referenceVolume(t) > 0);
        computeLumpedMasses(m, Material{}.density);
        const double squashed = stableTimeStep(m, Material{}).dt;
        QVERIFY2(squashed < 0.3 * dt, qPrintable(QString("%1 vs %2").arg(squashed).arg(dt)));
    }

    void oneTetStepIsTheMeshStep_data() {
        QTest::addColumn<bool>("areaTerm");
        QTest::newRow("springs and volume") << false;
        QTest::newRow("with the area term") << true;
    }
    void oneTetStepIsTheMeshStep() {
        // A mesh of one tet: its own terms are the whole model, so its step is the mesh's.
        QFETCH(bool, areaTerm);
        TetMesh m;
        m.addNode(Vec3(0, 0, 0), Vec3(0, 0, 0));
        m.addNode(Vec3(1.3, 0.1, 0), Vec3(1.3, 0.1, 0));
        m.addNode(Vec3(0.2, 0.9, 0.1), Vec3(0.2, 0.9, 0.1));
        m.addNode(Vec3(0.3, 0.2, 0.7), Vec3(0.3, 0.2, 0.7));
        m.addTet({0, 1, 2, 3});
        computeLumpedMasses(m, Material{}.density);
        StableTimeStepOptions options;
        options.areaTerm = areaTerm;
        options.relativeTolerance = 1e-12;
        options.maxIterations = 5000;
        const double dt = stableTimeStep(m, Material{}, options).dt;
        const std::vector<double> steps = tetStableTimeSteps(m, Material{}, options);
        QCOMPARE(steps.size(), std::size_t(1));
        QVERIFY2(std::abs(steps[0] - dt) <= 1e-6 * dt, qPrintable(QString("%1 vs %2").arg(steps[0]).arg(dt)));
    }

    void sliverTetsHaveTheSmallestSteps() {
        // The squashed node of sliverMeshHasSmallerStep: the tets with the smallest own step
        // are around it, and the smallest is within a small factor of the mesh's step.
        TetMesh m = jitteredBox(1.0, 9, 0.0);
        const int node = 1 + 5 * (1 + 4 * 1);
        m.referencePositions()[node] += Vec3(0.9, 0, 0);
        m.positions()[node] = m.ref(node);
        computeLumpedMasses(m, Material{}.density);
        const std::vector<double> steps = tetStableTimeSteps(m, Material{});
        QCOMPARE(steps.size(), std::size_t(m.tetCount()));
        const int worst = static_cast<int>(std::min_element(steps.begin(), steps.end()) - steps.begin());
        const Tet& q = m.tet(worst);
        QVERIFY(std::find(q.begin(), q.end(), node) != q.end());
        const double dt = stableTimeStep(m, Material{}).dt;
        QVERIFY2(steps[worst] > 0.2 * dt && steps[worst] < 5 * dt,
                 qPrintable(QString("%1 vs %2").arg(steps[worst]).arg(dt)));
        // Tets away from the node keep the step of the regular box (about 10x larger).
        const double regular = stableTimeStep(jitteredBox(1.0, 9, 0.0), Material{}).dt;
        int far = 0;
        for (int t = 0; t < m.tetCount(); ++t) {
            const Tet& r = m.tet(t);
            if (std::find(r.begin(), r.end(), node) != r.end())
                continue;
            QVERIFY2(steps[t] > 3 * steps[worst], qPrintable(QString("tet %1: %2").arg(t).arg(steps[t])));
            QVERIFY(steps[t] > 0.3 * regular);
            ++far;
        }
        QVERIFY(far > 0);
    }
};

QTEST_GUILESS_MAIN(TestStableTimeStep)
#include "test_stable_time_step.moc"
