// Projective dynamics (core/sim/projective_dynamics.h), the product's implicit integrator:
// its equilibrium is the tissue model's, it is stable at any step, held nodes stay, the
// result does not depend on the thread count, and it follows a cut.
#include "sim_test_mesh.h"

#include "core/cut/hybrid_cutter.h"
#include "core/mesh/topology.h"
#include "core/sim/simulator.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <random>

using namespace resect;
using namespace resect::testing;

namespace {

constexpr double kGravity = 9810; // mm/s^2

/// A simulator of m with deformation, the given effects and the nodes in `fixedBox` held.
std::unique_ptr<Simulator> scene(TetMesh& m, Integrator integrator, double dt, int iterations, bool gravity,
                                 std::optional<std::array<Vec3, 2>> fixedBox, double damping = 0, int threads = 1) {
    SimulatorOptions o;
    o.integrator = integrator;
    o.dt = dt;
    o.threads = threads;
    o.projective.iterations = iterations;
    auto sim = std::make_unique<Simulator>(m, Material{}, o);
    EffectSettings s;
    if (fixedBox)
        s.fixed.box = *fixedBox;
    if (damping > 0)
        s.damping = damping;
    if (!sim->addEffect("deformation", s).ok())
        qFatal("deformation");
    if (gravity && !sim->addEffect("gravity", s).ok())
        qFatal("gravity");
    if (fixedBox && !sim->addEffect("fixed", s).ok())
        qFatal("fixed");
    if (damping > 0 && !sim->addEffect("damping", s).ok())
        qFatal("damping");
    return sim;
}

/// A horizontal bar along x, 8 x 2 x 2 mm, its x = 0 end held: a cantilever under gravity.
TetMesh cantilever() {
    return simBox(8, 2, 2, 0.15, 3);
}
const std::array<Vec3, 2> kCantileverBase{Vec3(-1, -1, -1), Vec3(0.01, 3, 3)};

/// Lowest displacement in z of the nodes at the free end (x = 8).
double tipSag(const TetMesh& m) {
    double sum = 0;
    int count = 0;
    for (int n = 0; n < m.nodeCount(); ++n)
        if (m.ref(n).x() > 7.99) {
            sum += m.pos(n).z() - m.ref(n).z();
            ++count;
        }
    return sum / count;
}

} // namespace

class TestProjectiveDynamics : public QObject {
    Q_OBJECT
private slots:
    void equilibriumIsTheModels() {
        // The cantilever settles (damped) to the sag of the tissue model: at the settled state
        // the model's own forces (forces.h, not the projections) balance gravity on every free
        // node, and backward Euler settles to the same sag.
        TetMesh pd = cantilever();
        auto sim = scene(pd, Integrator::ProjectiveDynamics, 1e-3, 20, true, kCantileverBase, 20);
        for (int i = 0; i < 3000; ++i)
            QVERIFY(sim->step().ok());
        QVERIFY(sim->projectiveStats() && sim->projectiveStats()->factorizations == 1);
        const double sag = tipSag(pd);
        QVERIFY2(sag < -0.05, qPrintable(QString::number(sag)));

        std::vector<Vec3> f(pd.nodeCount(), Vec3::Zero());
        for (Vec3& v : pd.velocities())
            v.setZero(); // damping off the balance
        sim->computeForces(f);
        double worst = 0, weight = 0;
        for (int n = 0; n < pd.nodeCount(); ++n) {
            weight = std::max(weight, pd.masses()[n] * kGravity);
            worst = std::max(worst, f[n].norm());
        }
        qInfo("cantilever: projective dynamics sag %.4f mm, largest residual force %.3g of the largest weight", sag,
              worst / weight);
        QVERIFY2(worst < 0.05 * weight, qPrintable(QString("residual %1, weight %2").arg(worst).arg(weight)));

        TetMesh be = cantilever();
        auto reference = scene(be, Integrator::BackwardEuler, 1e-3, 0, true, kCantileverBase, 20);
        for (int i = 0; i < 3000; ++i)
            QVERIFY(reference->step().ok());
        qInfo("cantilever: backward Euler sag %.4f mm", tipSag(be));
        QVERIFY2(std::abs(sag - tipSag(be)) <= 0.03 * std::abs(tipSag(be)),
                 qPrintable(QString("%1 vs %2").arg(sag).arg(tipSag(be))));
    }

    void stableAtAnyStep_data() {
        QTest::addColumn<double>("dt");
        QTest::addColumn<int>("iterations");
        QTest::newRow("1 ms, 1 iteration") << 1e-3 << 1;
        QTest::newRow("1 ms, 5 iterations") << 1e-3 << 5;
        QTest::newRow("1/60 s, 5 iterations") << 1.0 / 60 << 5;
        QTest::newRow("0.1 s, 5 iterations") << 0.1 << 5;
    }
    void stableAtAnyStep() {
        // Free (no gravity, nothing held), every node with a random 5 cm/s velocity and a
        // random 10 % displacement: the energy never exceeds what it was at the start (the
        // step dissipates; it may trade a little between steps, never pump energy in), it
        // ends lower, nothing inverts and the motion stays finite.
        QFETCH(double, dt);
        QFETCH(int, iterations);
        TetMesh m = simBox(4, 4, 4, 0.2, 5);
        perturb(m, 0.1);
        std::mt19937 rng(3);
        std::normal_distribution<double> g(0, 50 / std::sqrt(3.0));
        for (Vec3& v : m.velocities())
            v = Vec3(g(rng), g(rng), g(rng));
        auto sim = scene(m, Integrator::ProjectiveDynamics, dt, iterations, false, std::nullopt);
        QVERIFY(sim->stableTimeStep() < dt / 5); // beyond the explicit limit
        const double first = sim->totalEnergy(); // the model's (forces.h), kinetic included
        double energy = first;
        for (int i = 0; i < 200; ++i) {
            const Status st = sim->step();
            QVERIFY2(st.ok(), st.message().c_str());
            energy = sim->totalEnergy();
            QVERIFY2(energy <= first * (1 + 1e-6), qPrintable(QString("step %1: %2, at the start %3").arg(i).arg(energy).arg(first)));
        }
        QVERIFY(energy < 0.5 * first);
        QCOMPARE(countInvertedTets(m), 0);
        for (const Vec3& p : m.positions())
            QVERIFY(p.allFinite());
    }

    void heldNodesStayAndTheRestHangs() {
        TetMesh m = simBox(3, 3, 6, 0.2, 9);
        const std::array<Vec3, 2> base{Vec3(-1, -1, -1), Vec3(4, 4, 0.01)};
        auto sim = scene(m, Integrator::ProjectiveDynamics, 1e-3, 5, true, base);
        for (int i = 0; i < 300; ++i)
            QVERIFY(sim->step().ok());
        double lowest = 0;
        for (int n = 0; n < m.nodeCount(); ++n) {
            if (m.ref(n).z() <= 0.01)
                QCOMPARE(m.pos(n), m.ref(n)); // held: exactly where it was
            else
                lowest = std::min(lowest, m.pos(n).z() - m.ref(n).z());
        }
        QVERIFY(lowest < 0);
        QCOMPARE(countInvertedTets(m), 0);
        // The system has only the free nodes.
        int held = 0;
        for (int n = 0; n < m.nodeCount(); ++n)
            held += m.ref(n).z() <= 0.01;
        QCOMPARE(sim->projectiveStats()->unknowns, m.nodeCount() - held);
    }

    void deterministicForAThreadCount() {
        // Large enough for two threads in the force kernels and the right-hand side: a run is
        // bit-identical to itself for a thread count, and other thread counts differ only by
        // the rounding of their summation order.
        std::vector<Vec3> result[3];
        for (int run = 0; run < 3; ++run) {
            const int threads = run == 0 ? 1 : 2;
            TetMesh m = simBox(16, 16, 16, 0.2, 4);
            auto sim = scene(m, Integrator::ProjectiveDynamics, 1e-3, 3, true,
                             std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(17, 17, 0.01)}, 0, threads);
            QCOMPARE(sim->threads(), threads);
            for (int i = 0; i < 5; ++i)
                QVERIFY(sim->step().ok());
            result[run].assign(m.positions().begin(), m.positions().end());
        }
        QVERIFY(result[1] == result[2]);
        double worst = 0;
        for (std::size_t i = 0; i < result[0].size(); ++i)
            worst = std::max(worst, (result[0][i] - result[1][i]).norm());
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
    }

    void followsACut() {
        // After a cut the system is factored again for the new nodes and terms, and the two
        // pieces move apart: the lower one held, the upper one falling.
        TetMesh m = simBox(4, 4, 4, 0.2, 13);
        auto sim = scene(m, Integrator::ProjectiveDynamics, 1e-3, 5, true,
                         std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(5, 5, 0)});
        for (int i = 0; i < 5; ++i)
            QVERIFY(sim->step().ok());
        QCOMPARE(sim->projectiveStats()->factorizations, 1);
        const int unknownsBefore = sim->projectiveStats()->unknowns;
        HybridCutter cutter(m);
        cutter.refreshSpatialIndex();
        CutResult result;
        QVERIFY(cutter
                    .cut(quad(Vec3(-1, -1, 2.43), Vec3(5, -1, 2.51), Vec3(-1, 5, 2.47), Vec3(5, 5, 2.55)), CutOptions{},
                         result)
                    .ok());
        sim->applyCut(result.changes);
        QCOMPARE(connectedComponents(m).count, 2);
        for (int i = 0; i < 50; ++i)
            QVERIFY(sim->step().ok());
        QCOMPARE(sim->projectiveStats()->factorizations, 2);
        QVERIFY(sim->projectiveStats()->unknowns > unknownsBefore); // the cut's new nodes
        double top = 0;
        for (int n = 0; n < m.nodeCount(); ++n)
            if (m.ref(n).z() > 3.5)
                top = std::min(top, m.pos(n).z() - m.ref(n).z());
        // Free fall for 55 ms is 15 mm; the upper piece fell most of that.
        QVERIFY2(top < -5, qPrintable(QString::number(top)));
        QCOMPARE(countInvertedTets(m), 0);
    }

    void aChangedStepRefactors() {
        TetMesh m = simBox(3, 3, 3, 0.2, 2);
        auto sim = scene(m, Integrator::ProjectiveDynamics, 0, 5, true,
                         std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(4, 4, 0.01)});
        QVERIFY(sim->step(1e-3).ok());
        QVERIFY(sim->step(1e-3).ok());
        QCOMPARE(sim->projectiveStats()->factorizations, 1);
        QVERIFY(sim->step(2e-3).ok());
        QCOMPARE(sim->projectiveStats()->factorizations, 2);
    }
};

QTEST_GUILESS_MAIN(TestProjectiveDynamics)
#include "test_projective_dynamics.moc"
