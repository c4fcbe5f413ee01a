// Integrators and the stable time step: energy conservation (velocity Verlet), a mesh at rest
// stays at rest, symplectic Euler stays bounded at the stable estimate and diverges at three
// times it given explicitly (reported, with the last good state kept), strongly stretched
// boxes stay bounded at the default step (stable stepping, test_sim_stable_stepping.cpp),
// backward Euler at ten times it stays finite and dissipates, and results are reproducible
// for a given thread count.
#include "sim_test_mesh.h"

#include "core/sim/simulator.h"

#include <QTest>

#include <cmath>

using namespace resect;
using resect::testing::countInvertedTets;
using resect::testing::perturb;
using resect::testing::simBox;

Q_DECLARE_METATYPE(resect::Integrator)

namespace {

/// A free box stretched by `strain` along x about its centre (a smooth initial deformation).
TetMesh stretchedBox(double strain, unsigned seed = 2) {
    TetMesh m = simBox(6, 4, 3, 0.2, seed);
    for (int i = 0; i < m.nodeCount(); ++i)
        m.positions()[i].x() = 3 + (1 + strain) * (m.ref(i).x() - 3);
    return m;
}

/// With options.dt = dtFactor x the stable estimate: steps taken as given (no stable stepping).
/// threads > 1 runs threaded even on these small meshes (grain 1).
std::unique_ptr<Simulator> deformable(TetMesh& m, Integrator integrator, double dtFactor,
                                      int threads = 1) {
    SimulatorOptions o;
    o.integrator = integrator;
    o.threads = threads;
    o.grain = threads > 1 ? 1 : o.grain;
    auto sim = std::make_unique<Simulator>(m, Material{}, o);
    if (!sim->addEffect("deformation").ok())
        qFatal("deformation");
    const double dt = dtFactor * sim->stableTimeStep();
    o.dt = dt;
    sim = std::make_unique<Simulator>(m, Material{}, o);
    if (!sim->addEffect("deformation").ok())
        qFatal("deformation");
    return sim;
}

} // namespace

class TestSimIntegrators : public QObject {
    Q_OBJECT
private slots:
    void restStaysAtRest_data() {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<double>("dtFactor");
        QTest::newRow("symplectic Euler") << Integrator::SymplecticEuler << 1.0;
        QTest::newRow("velocity Verlet") << Integrator::VelocityVerlet << 1.0;
        QTest::newRow("backward Euler, 10x") << Integrator::BackwardEuler << 10.0;
    }
    void restStaysAtRest() {
        QFETCH(Integrator, integrator);
        QFETCH(double, dtFactor);
        TetMesh m = simBox(5, 4, 3, 0.3, 4);
        auto sim = deformable(m, integrator, dtFactor, 2);
        for (int s = 0; s < 300; ++s)
            QVERIFY(sim->step().ok());
        for (int i = 0; i < m.nodeCount(); ++i) {
            QVERIFY(m.pos(i) == m.ref(i));
            QVERIFY(m.velocities()[i] == Vec3::Zero());
        }
    }

    void verletConservesEnergy() {
        // Undamped free box, stretched 1 % and released. Velocity Verlet conserves a shadow
        // energy: the total energy oscillates by O((h omega)^2) around its initial value and
        // does not drift. Stated tolerances over 5000 steps (about 40 periods of the slowest
        // mode): within 15 % at the stable step (h omega_max = 1.9), 4 % at half of it, drift
        // of the mean below 1 %; and the error is second order in h.
        double worst[3] = {};
        const double factors[3] = {1.0, 0.5, 0.25};
        for (int k = 0; k < 3; ++k) {
            TetMesh m = stretchedBox(0.01);
            auto sim = deformable(m, Integrator::VelocityVerlet, factors[k]);
            const double e0 = sim->totalEnergy();
            QVERIFY(e0 > 0);
            double first = 0, last = 0;
            int n = 0;
            for (int s = 1; s <= 5000; ++s) {
                QVERIFY(sim->step().ok());
                if (s % 25 == 0) {
                    const double e = sim->totalEnergy();
                    worst[k] = std::max(worst[k], std::abs(e - e0) / e0);
                    if (s <= 1000)
                        first += e, ++n;
                    if (s > 4000)
                        last += e;
                }
            }
            const double drift = (last - first) / n / e0;
            qInfo("Verlet, 5000 steps at %.2f x the stable dt: max |E - E0| / E0 = %.3g, drift of "
                  "the mean %.2g",
                  factors[k], worst[k], drift);
            QVERIFY2(std::abs(drift) < 0.01, qPrintable(QString::number(drift)));
            QVERIFY(sim->lastStep().kineticEnergy > 0); // it did move
        }
        QVERIFY2(worst[0] < 0.15, qPrintable(QString::number(worst[0])));
        QVERIFY2(worst[1] < 0.04, qPrintable(QString::number(worst[1])));
        const double order = worst[1] / worst[2];
        QVERIFY2(order > 3 && order < 5, qPrintable(QString::number(order)));
    }

    void largeStrainStaysBoundedAtTheDefaultStep_data() {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<double>("strain");
        QTest::newRow("Verlet, 5 %") << Integrator::VelocityVerlet << 0.05;
        QTest::newRow("Verlet, 10 %") << Integrator::VelocityVerlet << 0.10;
        QTest::newRow("Verlet, 20 %") << Integrator::VelocityVerlet << 0.20;
        QTest::newRow("symplectic Euler, 10 %") << Integrator::SymplecticEuler << 0.10;
    }
    void largeStrainStaysBoundedAtTheDefaultStep() {
        // The rest estimate is about the model linearised at rest. Strained tissue is stiffer in
        // some directions (tension adds transverse spring stiffness, the area and volume terms'
        // gradients turn), and a box stretched 5 % or more and released diverges at a fixed step
        // at the estimate (after about a thousand steps at 5 %, checked here so that the case
        // is hard enough). At the default step the simulator sub-steps as the configuration
        // needs (simulator.h, "Time step"): bounded over 10000 steps, energy conserved within
        // 15 % (measured 3 % with Verlet, 9 % with symplectic Euler), no inverted tet.
        QFETCH(Integrator, integrator);
        QFETCH(double, strain);
        {
            TetMesh m = stretchedBox(strain);
            auto fixed = deformable(m, integrator, 1.0); // options.dt: taken as given
            Status st;
            int s = 0;
            for (; s < 10000 && st.ok(); ++s)
                st = fixed->step();
            QVERIFY2(!st.ok(), "a fixed step at the estimate stayed bounded");
            qInfo("%.0f %% stretch at a fixed step at the estimate: diverged after %d steps",
                  100 * strain, s);
        }
        TetMesh m = stretchedBox(strain);
        SimulatorOptions o;
        o.integrator = integrator;
        o.threads = 1;
        Simulator sim(m, Material{}, o);
        QVERIFY(sim.addEffect("deformation").ok());
        QVERIFY(sim.stableStepping());
        const double e0 = sim.totalEnergy();
        double worst = 0;
        for (int s = 1; s <= 10000; ++s) {
            const Status st = sim.step();
            QVERIFY2(st.ok(), st.message().c_str());
            if (s % 50 == 0)
                worst = std::max(worst, std::abs(sim.totalEnergy() - e0) / e0);
        }
        qInfo("%.0f %% stretch at the default step: %lld sub-steps for 10000 steps, %d estimates, "
              "max |E - E0| / E0 = %.3g",
              100 * strain, sim.substepsTaken(), sim.stableEstimates(), worst);
        QVERIFY2(worst < 0.15, qPrintable(QString::number(worst)));
        QVERIFY(sim.substepsTaken() > 10000);
        QCOMPARE(countInvertedTets(m), 0);
    }

    void symplecticEulerStableAtEstimate_data() {
        QTest::addColumn<Integrator>("integrator");
        QTest::newRow("symplectic Euler") << Integrator::SymplecticEuler;
        QTest::newRow("velocity Verlet") << Integrator::VelocityVerlet;
    }
    void symplecticEulerStableAtEstimate() {
        // A random perturbation excites the highest modes, the ones the estimate is about.
        QFETCH(Integrator, integrator);
        TetMesh m = simBox(5, 4, 3, 0.3, 5);
        perturb(m, 0.01);
        auto sim = deformable(m, integrator, 1.0);
        const double e0 = sim->totalEnergy();
        double emax = e0;
        for (int s = 0; s < 3000; ++s) {
            const Status st = sim->step();
            QVERIFY2(st.ok(), st.message().c_str());
            if (s % 10 == 0)
                emax = std::max(emax, sim->totalEnergy());
        }
        QVERIFY2(emax < 60 * e0, qPrintable(QString("energy grew %1x").arg(emax / e0)));
        QCOMPARE(countInvertedTets(m), 0);
    }

    void explicitDivergesAboveEstimateAndSaysSo_data() { symplecticEulerStableAtEstimate_data(); }
    void explicitDivergesAboveEstimateAndSaysSo() {
        QFETCH(Integrator, integrator);
        TetMesh m = simBox(5, 4, 3, 0.3, 5);
        perturb(m, 0.01);
        auto sim = deformable(m, integrator, 3.0);
        std::vector<Vec3> x, v;
        Status st;
        int steps = 0;
        for (; steps < 2000 && st.ok(); ++steps) {
            x.assign(m.positions().begin(), m.positions().end());
            v.assign(m.velocities().begin(), m.velocities().end());
            st = sim->step();
        }
        QVERIFY2(!st.ok(), "no divergence reported at 3x the stable step");
        qInfo("%s", st.message().c_str());
        QVERIFY(steps < 200);
        QVERIFY(QString::fromStdString(st.message()).contains("too large for the explicit"));
        QVERIFY(QString::fromStdString(st.message()).contains("stable estimate"));
        // The last good state is kept: exactly the state before the failing step.
        for (int i = 0; i < m.nodeCount(); ++i) {
            QVERIFY(m.pos(i) == x[i]);
            QVERIFY(m.velocities()[i] == v[i]);
            QVERIFY(m.pos(i).allFinite());
        }
        QCOMPARE(sim->stepsTaken(), steps - 1);
    }

    void implicitAtTenTimesStableStepIsFiniteAndDissipative() {
        TetMesh m = stretchedBox(0.05, 3);
        perturb(m, 0.02);
        auto sim = deformable(m, Integrator::BackwardEuler, 10.0);
        const double e0 = sim->totalEnergy();
        double previous = e0, emax = e0;
        int increases = 0;
        for (int s = 0; s < 300; ++s) {
            const Status st = sim->step();
            QVERIFY2(st.ok(), st.message().c_str());
            const double e = sim->totalEnergy();
            QVERIFY(std::isfinite(e));
            emax = std::max(emax, e);
            increases += e > previous * (1 + 1e-9);
            previous = e;
        }
        qInfo("backward Euler at 10x the stable dt: E %.4g -> %.4g, max %.4g, %d increases, %d CG "
              "iterations in the last step",
              e0, previous, emax, increases, sim->lastStep().solverIterations);
        QVERIFY(emax <= e0 * (1 + 1e-6));
        QVERIFY(previous < 0.1 * e0);
        QCOMPARE(countInvertedTets(m), 0);
        QVERIFY(sim->lastStep().solverIterations > 0);
    }

    void sameThreadCountGivesIdenticalResults() {
        std::vector<std::vector<Vec3>> results;
        for (int threads : {2, 2, 1}) {
            TetMesh m = stretchedBox(0.01, 6);
            auto sim = deformable(m, Integrator::SymplecticEuler, 1.0, threads);
            QVERIFY(sim->addEffect("gravity").ok());
            for (int s = 0; s < 30; ++s) {
                const Status st = sim->step();
                QVERIFY2(st.ok(), st.message().c_str());
            }
            results.emplace_back(m.positions().begin(), m.positions().end());
        }
        QVERIFY(results[0] == results[1]); // bit-identical
        double diff = 0;
        for (std::size_t i = 0; i < results[0].size(); ++i)
            diff = std::max(diff, (results[0][i] - results[2][i]).norm());
        QVERIFY2(diff < 1e-9, qPrintable(QString::number(diff))); // rounding only
    }
};

QTEST_GUILESS_MAIN(TestSimIntegrators)
#include "test_sim_integrators.moc"
