// Force kernels and the deformation model: forces are the negative gradient of the energy,
// the differentials are the Hessian at rest and symmetric elsewhere, a mesh at rest feels no
// force, the stiffnesses follow Eq. 4, and the model linearised at rest is exactly the one
// stable_time_step.h estimates (with and without the area term).
#include "sim_test_mesh.h"

#include "core/mesh/stable_time_step.h"
#include "core/mesh/topology.h"
#include "core/sim/deformation_effect.h"
#include "core/sim/simulator.h"

#include <QTest>

#include <cmath>

using namespace resect;
using resect::testing::perturb;
using resect::testing::simBox;

namespace {

DeformationTerms only(const QString& which) {
    DeformationTerms t;
    t.distance = which == "all" || which == "distance";
    t.volume = which == "all" || which == "volume";
    t.area = which == "all" || which == "area";
    return t;
}

std::vector<Vec3> forcesAt(DeformationEffect& e, std::vector<Vec3> x, double* energy = nullptr) {
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    SimState s;
    s.x = x;
    const double en = e.addForces(s, f);
    if (energy)
        *energy = en;
    return f;
}

double maxNorm(const std::vector<Vec3>& v) {
    double m = 0;
    for (const Vec3& x : v)
        m = std::max(m, x.norm());
    return m;
}

} // namespace

class TestSimForces : public QObject {
    Q_OBJECT
private slots:
    void forceIsNegativeEnergyGradient_data() {
        QTest::addColumn<QString>("terms");
        QTest::addColumn<int>("threads");
        for (const char* t : {"distance", "volume", "area", "all"}) {
            QTest::newRow(qPrintable(QString("%1, 1 thread").arg(t))) << QString(t) << 1;
            QTest::newRow(qPrintable(QString("%1, 2 threads").arg(t))) << QString(t) << 2;
        }
    }
    void forceIsNegativeEnergyGradient() {
        QFETCH(QString, terms);
        QFETCH(int, threads);
        TetMesh m = simBox(2, 2, 2, 0.2, 3);
        perturb(m, 0.15);
        DeformationEffect e(m, Material{}, {only(terms), threads, 1}); // grain 1: really threaded
        DeformationEffect serial(m, Material{}, {only(terms), 1, 1});  // for the many energies
        std::vector<Vec3> x(m.positions().begin(), m.positions().end());
        const std::vector<Vec3> f = forcesAt(e, x);
        const double scale = maxNorm(f);
        QVERIFY(scale > 0);
        const double eps = 1e-6;
        double worst = 0;
        for (std::size_t i = 0; i < x.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                std::vector<Vec3> xp = x, xm = x;
                xp[i][c] += eps;
                xm[i][c] -= eps;
                const double g = (serial.energy(xp) - serial.energy(xm)) / (2 * eps);
                worst = std::max(worst, std::abs(f[i][c] + g));
            }
        QVERIFY2(worst < 1e-5 * scale,
                 qPrintable(QString("|f + dE/dx| = %1, |f| = %2").arg(worst).arg(scale)));
    }

    void differentialIsHessianAtRest_data() {
        QTest::addColumn<QString>("terms");
        for (const char* t : {"distance", "volume", "area", "all"})
            QTest::newRow(t) << QString(t);
    }
    void differentialIsHessianAtRest() {
        // At rest C = C0, so the dropped second-derivative terms vanish: the Gauss-Newton
        // differential is the exact force derivative.
        QFETCH(QString, terms);
        TetMesh m = simBox(2, 2, 2, 0.2, 4);
        DeformationEffect e(m, Material{}, {only(terms), 1});
        std::vector<Vec3> x(m.positions().begin(), m.positions().end());
        std::vector<Vec3> dx(x.size());
        perturb(m, 1.0, 11);
        for (std::size_t i = 0; i < x.size(); ++i)
            dx[i] = m.positions()[i] - x[i];
        std::vector<Vec3> df(x.size(), Vec3::Zero());
        SimState s;
        s.x = x;
        e.addForceDifferential(s, dx, df);
        const double eps = 1e-6;
        std::vector<Vec3> xp = x, xm = x;
        for (std::size_t i = 0; i < x.size(); ++i) {
            xp[i] += eps * dx[i];
            xm[i] -= eps * dx[i];
        }
        const auto fp = forcesAt(e, xp), fm = forcesAt(e, xm);
        double worst = 0;
        for (std::size_t i = 0; i < x.size(); ++i)
            worst = std::max(worst, (df[i] - (fp[i] - fm[i]) / (2 * eps)).norm());
        QVERIFY2(worst < 1e-6 * maxNorm(df),
                 qPrintable(QString("%1 vs %2").arg(worst).arg(maxNorm(df))));
    }

    void differentialIsSymmetricNegativeSemiDefinite() {
        TetMesh m = simBox(3, 2, 2, 0.2, 5);
        perturb(m, 0.3);
        DeformationEffect e(m, Material{}, {only("all"), 2, 1});
        SimState s;
        s.x = m.positions();
        std::vector<Vec3> a(m.nodeCount()), b(m.nodeCount());
        std::mt19937 rng(3);
        std::normal_distribution<double> g;
        for (int i = 0; i < m.nodeCount(); ++i) {
            a[i] = Vec3(g(rng), g(rng), g(rng));
            b[i] = Vec3(g(rng), g(rng), g(rng));
        }
        std::vector<Vec3> ka(m.nodeCount(), Vec3::Zero()), kb(m.nodeCount(), Vec3::Zero());
        e.addForceDifferential(s, a, ka);
        e.addForceDifferential(s, b, kb);
        double bka = 0, akb = 0, aka = 0, scale = 0;
        for (int i = 0; i < m.nodeCount(); ++i) {
            bka += b[i].dot(ka[i]);
            akb += a[i].dot(kb[i]);
            aka += a[i].dot(ka[i]);
            scale += std::abs(a[i].dot(ka[i]));
        }
        QVERIFY2(std::abs(bka - akb) < 1e-12 * scale,
                 qPrintable(QString("%1 vs %2").arg(bka).arg(akb)));
        QVERIFY(aka <= 0);
        // The diagonal the preconditioner uses is the diagonal of -K.
        std::vector<Vec3> diag(m.nodeCount(), Vec3::Zero());
        e.addSystemDiagonal(s, 1.0, diag);
        for (int i : {0, 7, m.nodeCount() - 1})
            for (int c = 0; c < 3; ++c) {
                std::vector<Vec3> unit(m.nodeCount(), Vec3::Zero()),
                    col(m.nodeCount(), Vec3::Zero());
                unit[i][c] = 1;
                e.addForceDifferential(s, unit, col);
                QVERIFY(std::abs(diag[i][c] + col[i][c]) <= 1e-12 * diag[i][c]);
            }
    }

    void meshAtRestFeelsNoForce() {
        TetMesh m = simBox(3, 3, 3, 0.3, 6);
        Simulator sim(m, Material{});
        QVERIFY(sim.addEffect("deformation").ok());
        std::vector<Vec3> f(m.nodeCount());
        QCOMPARE(sim.computeForces(f), 0.0);
        for (const Vec3& v : f)
            QVERIFY(v == Vec3::Zero());
    }

    void stiffnessesFollowEq4() {
        const TetMesh m = simBox(2, 2, 1, 0.2, 8);
        Material mat;
        mat.stiffness = 3e5;
        const DeformationModel model(m, mat, DeformationTerms{});
        const auto mass = m.masses();
        QCOMPARE(model.liveEdgeCount(), static_cast<int>(uniqueEdges(m).size()));
        QCOMPARE(model.liveTriangleCount(), static_cast<int>(boundaryFaces(m).size()));
        for (std::size_t s = 0; s < model.edges().size(); ++s) {
            const auto [a, b] = model.edges()[s];
            const double l0 = (m.ref(a) - m.ref(b)).norm();
            QVERIFY(std::abs(model.edgeRestLength()[s] - l0) < 1e-15 * l0);
            QVERIFY(std::abs(model.edgeStiffness()[s] -
                             mat.stiffness * (mass[a] + mass[b]) / (l0 * l0)) <
                    1e-12 * model.edgeStiffness()[s]);
        }
        for (int t = 0; t < m.tetCount(); ++t) {
            const double v0 = m.referenceVolume(t);
            double ms = 0;
            for (int v : m.tet(t))
                ms += mass[v];
            QVERIFY(std::abs(model.tetRestVolume6()[t] / 6 - v0) < 1e-12 * v0);
            const double kv = 36 * model.tetStiffness36()[t];
            QVERIFY(std::abs(kv - mat.stiffness * ms / (v0 * v0)) < 1e-10 * kv);
        }
        for (std::size_t s = 0; s < model.triangles().size(); ++s) {
            const Tri& q = model.triangles()[s];
            const double a0 =
                0.5 * (m.ref(q[1]) - m.ref(q[0])).cross(m.ref(q[2]) - m.ref(q[0])).norm();
            QVERIFY(std::abs(model.triangleStiffness()[s] -
                             mat.stiffness * (mass[q[0]] + mass[q[1]] + mass[q[2]]) / (a0 * a0)) <
                    1e-12 * model.triangleStiffness()[s]);
        }
    }

    void linearisedModelIsTheStableTimeStepModel_data() {
        QTest::addColumn<bool>("area");
        QTest::newRow("edges and tets") << false;
        QTest::newRow("with area") << true;
    }
    void linearisedModelIsTheStableTimeStepModel() {
        // f(ref + eps u) / eps -> -K u, with K the operator of stable_time_step.h.
        QFETCH(bool, area);
        TetMesh m = simBox(3, 2, 2, 0.25, 9);
        DeformationTerms terms;
        terms.area = area;
        DeformationEffect e(m, Material{}, {terms, 1});
        std::vector<Vec3> u(m.nodeCount());
        std::mt19937 rng(5);
        std::normal_distribution<double> g;
        for (Vec3& p : u)
            p = Vec3(g(rng), g(rng), g(rng));
        std::vector<Vec3> ku(m.nodeCount());
        applyRestStiffness(m, Material{}, u, ku, area);
        const double eps = 1e-7;
        std::vector<Vec3> xp(m.nodeCount()), xm(m.nodeCount());
        for (int i = 0; i < m.nodeCount(); ++i) {
            xp[i] = m.ref(i) + eps * u[i];
            xm[i] = m.ref(i) - eps * u[i];
        }
        const auto fp = forcesAt(e, xp), fm = forcesAt(e, xm);
        double worst = 0, scale = 0;
        for (int i = 0; i < m.nodeCount(); ++i) {
            worst = std::max(worst, ((fp[i] - fm[i]) / (2 * eps) + ku[i]).norm());
            scale = std::max(scale, ku[i].norm());
        }
        QVERIFY2(worst < 1e-5 * scale, qPrintable(QString("%1 vs %2").arg(worst).arg(scale)));
    }

    void areaTermLowersTheStableStep() {
        const TetMesh m = simBox(4, 3, 2, 0.2, 10);
        StableTimeStepOptions withArea;
        withArea.areaTerm = true;
        const StableTimeStep a = stableTimeStep(m, Material{}, withArea);
        const StableTimeStep b = stableTimeStep(m, Material{});
        QVERIFY(a.lambdaMax >= b.lambdaMax * (1 - 1e-6));
        QVERIFY(a.lambdaMax <= a.gershgorinBound);
        QVERIFY(a.dt > 0.5 * b.dt); // the area term is of the same order as the others
    }
};

QTEST_GUILESS_MAIN(TestSimForces)
#include "test_sim_forces.moc"
