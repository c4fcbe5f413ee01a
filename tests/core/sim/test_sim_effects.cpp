// Every effect acts when asked and is absent when not: gravity accelerates by g, fixed nodes
// do not move, the tool pushes surface nodes out of its capsules, damping removes energy; the
// step report lists exactly the requested effects; an effect with nothing to do leaves the
// results bit-identical; the registry rejects bad declarations and takes new effects.
#include "sim_test_mesh.h"

#include "core/mesh/topology.h"
#include "core/sim/gravity_effect.h"
#include "core/sim/simulator.h"
#include "core/sim/tool_contact_effect.h"

#include <QTest>

#include <cmath>

using namespace resect;
using resect::testing::simBox;

Q_DECLARE_METATYPE(resect::Integrator)

namespace {

std::unique_ptr<Simulator> make(TetMesh& m, const std::vector<std::string>& effects,
                                const EffectSettings& settings = {},
                                Integrator integrator = Integrator::SymplecticEuler,
                                double dtFactor = 1.0) {
    SimulatorOptions o;
    o.integrator = integrator;
    o.threads = 2;
    auto sim = std::make_unique<Simulator>(m, Material{}, o);
    for (const auto& name : effects) {
        const Status s = sim->addEffect(name, settings);
        if (!s.ok())
            qFatal("%s", s.message().c_str());
    }
    if (dtFactor != 1.0) {
        o.dt = dtFactor * sim->stableTimeStep();
        auto again = std::make_unique<Simulator>(m, Material{}, o);
        for (const auto& name : effects)
            (void)again->addEffect(name, settings);
        return again;
    }
    return sim;
}

Status run(Simulator& sim, int steps) {
    for (int s = 0; s < steps; ++s)
        if (Status st = sim.step(); !st.ok())
            return st;
    return Status::success();
}

std::vector<Vec3> positions(const TetMesh& m) {
    return {m.positions().begin(), m.positions().end()};
}

/// Adds a constant force per unit mass along +x: a minimal effect registered from outside.
class WindEffect : public Effect {
public:
    explicit WindEffect(double a) : m_a(a) {}
    std::string name() const override { return "wind"; }
    double addForces(const SimState& s, std::span<Vec3> f) override {
        for (std::size_t i = 0; i < f.size(); ++i)
            f[i].x() += s.mass[i] * m_a;
        return 0;
    }

private:
    double m_a;
};

} // namespace

class TestSimEffects : public QObject {
    Q_OBJECT
private slots:
    void gravityAcceleratesByG() {
        // Symplectic Euler from rest under uniform g: v_n = n h g, x_n = x_0 + n(n+1)/2 h^2 g,
        // and the body does not deform.
        TetMesh m = simBox(4, 3, 2);
        EffectSettings settings;
        settings.gravity = Vec3(100, -200, -9810);
        auto sim = make(m, {"deformation", "gravity"}, settings);
        const auto x0 = positions(m);
        const double e0 = sim->totalEnergy();
        const double h = sim->timeStep();
        const int n = 200;
        QVERIFY(run(*sim, n).ok());
        const Vec3 v = n * h * settings.gravity;
        const Vec3 dx = 0.5 * n * (n + 1) * h * h * settings.gravity;
        for (int i = 0; i < m.nodeCount(); ++i) {
            QVERIFY2((m.velocities()[i] - v).norm() < 1e-9 * v.norm(),
                     qPrintable(QString("node %1: %2").arg(i).arg((m.velocities()[i] - v).norm())));
            QVERIFY((m.pos(i) - x0[i] - dx).norm() < 1e-9 * dx.norm());
        }
        // Its potential makes the monitored energy of the fall constant.
        // (symplectic Euler's energy error under constant force: 1/2 m (h g)^2 n, small)
        QVERIFY(std::abs(sim->totalEnergy() - e0) < 1e-2 * sim->lastStep().kineticEnergy);
    }

    void noGravityWhenNotAsked() {
        TetMesh m = simBox(4, 3, 2);
        auto sim = make(m, {"deformation"});
        QVERIFY(run(*sim, 200).ok());
        QVERIFY(positions(m) ==
                std::vector<Vec3>(m.referencePositions().begin(), m.referencePositions().end()));
        QVERIFY(sim->findEffect("gravity") == nullptr);
    }

    void movedAnchorsAreHeldWhereTheyAre() {
        // The improvement may move an anchored node within the anchored box
        // (ImproveOptions::moveAnchored) and then hands the simulation the touched nodes
        // without a rebuild: the node is held where it is now. An anchored node the change did
        // not touch is still held where it was.
        TetMesh m = simBox(6, 2, 2, 0.2, 3);
        EffectSettings settings;
        settings.fixed.box = std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(0, 3, 3)};
        auto sim = make(m, {"deformation", "gravity", "fixed"}, settings);
        const std::vector<int> anchored = static_cast<FixedNodesEffect*>(sim->findEffect("fixed"))->nodes();
        QVERIFY(anchored.size() >= 4);
        const int moved = anchored[1], other = anchored[2];
        const Vec3 to = m.pos(moved) + Vec3(0, 0.01, 0.01), otherBefore = m.pos(other);
        const Vec3 stale = otherBefore + Vec3(0, 0.01, 0);
        m.positions()[moved] = to;
        m.referencePositions()[moved] = to;
        m.positions()[other] = stale;  // (not reported as touched)
        CutChanges changes;
        changes.firstNewNode = m.nodeCount();
        changes.firstNewTet = m.tetCount();
        changes.touchedNodes = {moved};
        sim->applyCut(changes);
        QVERIFY(run(*sim, 20).ok());
        QCOMPARE(m.pos(moved), to);
        QCOMPARE(m.velocities()[moved], Vec3::Zero());
        QCOMPARE(m.pos(other), otherBefore);
    }

    void fixedNodesDoNotMove_data() {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<double>("dtFactor");
        QTest::addColumn<bool>("box");
        QTest::newRow("explicit, box") << Integrator::SymplecticEuler << 1.0 << true;
        QTest::newRow("explicit, node list") << Integrator::VelocityVerlet << 1.0 << false;
        QTest::newRow("implicit 10x, box") << Integrator::BackwardEuler << 10.0 << true;
    }
    void fixedNodesDoNotMove() {
        // A cantilever: the x = 0 face is anchored, gravity bends the rest.
        QFETCH(Integrator, integrator);
        QFETCH(double, dtFactor);
        QFETCH(bool, box);
        TetMesh m = simBox(6, 2, 2, 0.2, 3);
        EffectSettings settings;
        std::vector<int> anchored;
        for (int i = 0; i < m.nodeCount(); ++i)
            if (m.ref(i).x() <= 0)
                anchored.push_back(i);
        if (box)
            settings.fixed.box = std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(0, 3, 3)};
        else
            settings.fixed.nodes = anchored;
        settings.damping = 200.0;
        auto sim =
            make(m, {"deformation", "gravity", "fixed", "damping"}, settings, integrator, dtFactor);
        QCOMPARE(static_cast<FixedNodesEffect*>(sim->findEffect("fixed"))->nodes(), anchored);
        const auto x0 = positions(m);
        const Status st = run(*sim, 400);
        QVERIFY2(st.ok(), st.message().c_str());
        double sag = 0;
        for (int i = 0; i < m.nodeCount(); ++i) {
            if (std::binary_search(anchored.begin(), anchored.end(), i)) {
                QVERIFY(m.pos(i) == x0[i]);
                QVERIFY(m.velocities()[i] == Vec3::Zero());
            } else {
                sag = std::max(sag, x0[i].z() - m.pos(i).z());
            }
        }
        QVERIFY2(sag > 1e-3, qPrintable(QString::number(sag)));
        // The anchors run last, whatever the order of declaration.
        QCOMPARE(sim->effectNames().back(), std::string("fixed"));

        // Without the effect the same nodes fall with the rest.
        TetMesh free = simBox(6, 2, 2, 0.2, 3);
        auto loose = make(free, {"deformation", "gravity"}, settings, integrator, dtFactor);
        QVERIFY(run(*loose, 50).ok());
        QVERIFY(free.pos(anchored[0]).z() < x0[anchored[0]].z());
    }

    void toolVelocitySpansTheWholeStep() {
        // A step split into two sub-steps: the tool moved 0.2 mm down between whole steps, so
        // in both sub-steps a node it pushes gets the tool's speed, 0.2 mm per whole step
        // (0.2 / 2 ms = 100 mm/s), not twice that in the first and nothing in the second.
        TetMesh m = simBox(2, 2, 1, 0.0, 1);
        Tool t;
        t.points = {Vec3(1, 1, 2.9)};
        t.radius = 1.0;
        ToolContactEffect tool(m, t);
        QVERIFY(tool.setPose(std::vector<Vec3>{Vec3(1, 1, 2.7)}).ok());
        const int top = [&] {
            for (int n = 0; n < m.nodeCount(); ++n)
                if (m.ref(n) == Vec3(1, 1, 1))
                    return n;
            return -1;
        }();
        QVERIFY(top >= 0);
        for (int sub = 0; sub < 2; ++sub) {
            for (Vec3& v : m.velocities())
                v.setZero();
            SimState s;
            s.x = m.positions();
            s.v = m.velocities();
            s.mass = m.masses();
            s.dt = 1e-3;
            s.stepDt = 2e-3;
            s.lastSubstep = sub == 1;
            m.positions()[top] = Vec3(1, 1, 1.75); // inside the sphere (centre z 2.7, radius 1)
            QVERIFY(tool.afterStep(s));
            QVERIFY(std::abs(m.pos(top).z() - 1.7) < 1e-12);
            QVERIFY2(std::abs(m.velocities()[top].z() + 100) < 1e-9,
                     qPrintable(QString("sub-step %1: %2").arg(sub).arg(m.velocities()[top].z())));
        }
    }

    void toolPushesSurfaceNodesOut() {
        // A capsule touching the top face (z = 2) of a box held at its bottom, pressed 0.8 mm
        // down over 200 steps and held.
        TetMesh m = simBox(6, 4, 2, 0.2, 4);
        EffectSettings settings;
        settings.tool.points = {Vec3(1.5, 2, 3), Vec3(4.5, 2, 3)};
        settings.tool.radius = 1.0;
        settings.fixed.box = std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(7, 5, 0)};
        auto sim = make(m, {"deformation", "fixed", "tool-contact"}, settings);
        auto* tool = static_cast<ToolContactEffect*>(sim->findEffect("tool-contact"));
        QVERIFY(tool);
        std::vector<int> surface = tool->surfaceNodes();
        std::sort(surface.begin(), surface.end());
        std::vector<int> expected;
        for (const BoundaryFace& f : boundaryFaces(m))
            expected.insert(expected.end(), f.nodes.begin(), f.nodes.end());
        std::sort(expected.begin(), expected.end());
        expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
        QCOMPARE(surface, expected);

        int pushed = 0;
        for (int s = 0; s < 300; ++s) {
            const double z = 3 - 0.8 * std::min(1.0, s / 200.0);
            const std::vector<Vec3> pose{Vec3(1.5, 2, z), Vec3(4.5, 2, z)};
            QVERIFY(tool->setPose(pose).ok());
            const Status st = sim->step();
            QVERIFY2(st.ok(), st.message().c_str());
            pushed += tool->lastContacts();
            for (int n : surface) {
                const double d = (m.pos(n) - tool->closestPoint(m.pos(n))).norm();
                QVERIFY2(
                    d >= settings.tool.radius * (1 - 1e-12),
                    qPrintable(
                        QString("step %1: node %2 at %3 inside the tool").arg(s).arg(n).arg(d)));
            }
        }
        QVERIFY(pushed > 0);
        // The top face under the tool is pressed down, by at least 0.5 of the 0.8 mm. (How far
        // depends on the step: the nodes under the tool's axis slide off it to either side,
        // where the capsule is higher; 1.00 at a fixed step at the estimate, 1.41 with the
        // sub-steps the compressed box gets at the default step, 1.38 at half the step.)
        double lowest = 2;
        for (int n : surface)
            if (m.ref(n).z() == 2)
                lowest = std::min(lowest, m.pos(n).z());
        QVERIFY2(lowest < 1.5, qPrintable(QString::number(lowest)));
        QCOMPARE(resect::testing::countInvertedTets(m), 0);
        QVERIFY(
            tool->setPose(std::vector<Vec3>{Vec3::Zero()}).message().find("expected 2 points") !=
            std::string::npos);
    }

    void noContactWhenNotAsked() {
        // The same tool pose without the effect: the surface stays inside the capsule.
        TetMesh m = simBox(6, 4, 2, 0.2, 4);
        auto sim = make(m, {"deformation"});
        ToolContactEffect probe(m, Tool{{Vec3(1.5, 2, 2.4), Vec3(4.5, 2, 2.4)}, 1.0});
        QVERIFY(run(*sim, 20).ok());
        int inside = 0;
        for (int n : probe.surfaceNodes())
            inside += (m.pos(n) - probe.closestPoint(m.pos(n))).norm() < 1.0;
        QVERIFY(inside > 0);
    }

    void dampingRemovesEnergy_data() {
        QTest::addColumn<Integrator>("integrator");
        QTest::addColumn<double>("dtFactor");
        QTest::newRow("Verlet") << Integrator::VelocityVerlet << 1.0;
        QTest::newRow("backward Euler") << Integrator::BackwardEuler << 5.0;
    }
    void dampingRemovesEnergy() {
        QFETCH(Integrator, integrator);
        QFETCH(double, dtFactor);
        double finalEnergy[2] = {};
        for (int damped = 0; damped < 2; ++damped) {
            TetMesh m = simBox(6, 4, 3, 0.2, 2);
            for (int i = 0; i < m.nodeCount(); ++i)
                m.positions()[i].x() = 3 + 1.01 * (m.ref(i).x() - 3);
            EffectSettings settings;
            settings.damping = 100.0; // 1/s: e-folding of the kinetic energy in 5 ms
            auto sim = damped ? make(m, {"deformation", "damping"}, settings, integrator, dtFactor)
                              : make(m, {"deformation"}, settings, integrator, dtFactor);
            const double e0 = sim->totalEnergy();
            const double t = 0.05;
            while (sim->time() < t)
                QVERIFY(sim->step().ok());
            finalEnergy[damped] = sim->totalEnergy() / e0;
        }
        qInfo("energy after 50 ms: %.3g undamped, %.3g damped", finalEnergy[0], finalEnergy[1]);
        QVERIFY(finalEnergy[1] < 0.05);
        QVERIFY(finalEnergy[1] < 0.1 * finalEnergy[0]);
    }

    void reportListsOnlyRequestedEffects() {
        TetMesh m = simBox(3, 3, 3);
        EffectSettings settings;
        settings.fixed.nodes = {0, 1};
        settings.damping = 1.0;
        auto sim = make(m, {"fixed", "gravity", "damping"}, settings);
        QVERIFY(run(*sim, 10).ok());
        std::vector<std::string> names;
        for (const EffectTime& e : sim->lastStep().effects) {
            names.push_back(e.name);
            QVERIFY(e.ms >= 0);
        }
        QCOMPARE(names, (std::vector<std::string>{"gravity", "damping", "fixed"}));
        QCOMPARE(sim->totalTimes().size(), std::size_t(3));
        QVERIFY(sim->findEffect("deformation") == nullptr);
        QVERIFY(sim->findEffect("tool-contact") == nullptr);
        // No deformation: the step is still the tissue model's natural time scale.
        QVERIFY(sim->stableTimeStep() > 0 && std::isfinite(sim->stableTimeStep()));
    }

    void effectWithNothingToDoChangesNothing() {
        // A tool far away and an empty anchor box: bit-identical results.
        std::vector<Vec3> results[2];
        for (int with = 0; with < 2; ++with) {
            TetMesh m = simBox(4, 3, 3, 0.2, 6);
            for (int i = 0; i < m.nodeCount(); ++i)
                m.positions()[i].y() = 1.5 + 1.02 * (m.ref(i).y() - 1.5);
            EffectSettings settings;
            settings.tool = Tool{{Vec3(50, 50, 50), Vec3(60, 50, 50)}, 1.0};
            settings.fixed.box = std::array<Vec3, 2>{Vec3(20, 20, 20), Vec3(21, 21, 21)};
            auto sim = with ? make(m, {"deformation", "gravity", "tool-contact", "fixed"}, settings)
                            : make(m, {"deformation", "gravity"}, settings);
            QVERIFY(run(*sim, 300).ok());
            results[with] = positions(m);
        }
        QVERIFY(results[0] == results[1]);
    }

    void registryRejectsBadDeclarations_data() {
        QTest::addColumn<QString>("list");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown") << "deformation,wobble"
                                 << "unknown effect 'wobble'";
        QTest::newRow("twice") << "gravity,gravity"
                               << "given twice";
        QTest::newRow("empty item") << "gravity,,fixed"
                                    << "empty effect name";
        QTest::newRow("trailing comma") << "gravity,"
                                        << "empty";
        QTest::newRow("empty") << ""
                               << "empty";
    }
    void registryRejectsBadDeclarations() {
        QFETCH(QString, list);
        QFETCH(QString, message);
        std::vector<std::string> names;
        const Status s = EffectRegistry::withBuiltins().parseList(list.toStdString(), names);
        QVERIFY(!s.ok());
        QVERIFY2(QString::fromStdString(s.message()).contains(message), s.message().c_str());
    }

    void registryRejectsBadParameters() {
        TetMesh m = simBox(2, 2, 2);
        Simulator sim(m, Material{});
        EffectSettings s;
        QVERIFY(sim.addEffect("fixed", s).message().find("nodes or a box") != std::string::npos);
        s.fixed.nodes = {m.nodeCount()};
        QVERIFY(sim.addEffect("fixed", s).message().find("not in the mesh") != std::string::npos);
        QVERIFY(sim.addEffect("tool-contact", s).message().find("at least one point") !=
                std::string::npos);
        s.tool.points = {Vec3::Zero()};
        s.tool.radius = -1;
        QVERIFY(sim.addEffect("tool-contact", s).message().find("radius") != std::string::npos);
        QVERIFY(sim.addEffect("damping", s).message().find("positive") != std::string::npos);
        s.gravity = Vec3(0, 0, NAN);
        QVERIFY(sim.addEffect("gravity", s).message().find("finite") != std::string::npos);
        QVERIFY(sim.addEffect("deformation").ok());
        QVERIFY(sim.addEffect("deformation").message().find("twice") != std::string::npos);
        QCOMPARE(sim.effectNames(), std::vector<std::string>{"deformation"});
    }

    void registryTakesNewEffects() {
        EffectRegistry registry = EffectRegistry::withBuiltins();
        registry.add("wind", [](const TetMesh&, const Material&, const EffectSettings& s,
                                std::unique_ptr<Effect>& out) {
            out = std::make_unique<WindEffect>(s.extra.count("wind") ? s.extra.at("wind") : 1000.0);
            return Status::success();
        });
        std::vector<std::string> names;
        QVERIFY(registry.parseList("deformation,wind", names).ok());
        TetMesh m = simBox(2, 2, 2);
        Simulator sim(m, Material{});
        EffectSettings s;
        s.extra["wind"] = 500;
        for (const auto& n : names)
            QVERIFY(sim.addEffect(n, s, registry).ok());
        QVERIFY(run(sim, 10).ok());
        for (const Vec3& v : m.velocities())
            QVERIFY(std::abs(v.x() - 10 * sim.timeStep() * 500) < 1e-9);
    }
};

QTEST_GUILESS_MAIN(TestSimEffects)
#include "test_sim_effects.moc"
