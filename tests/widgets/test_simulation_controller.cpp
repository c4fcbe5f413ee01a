// SimulationController: the simulation runs on a copy of the current tissue and follows new
// cuts of the document locally (Tissue::cut on the running, deformed tissue: the time goes
// on); anything else rebuilds it at time 0. On the example polyp scenario (gravity, an
// anchored stalk, tool contact, damping).

#include "core/mesh/validity.h"
#include "widgets/scenario_document.h"
#include "widgets/simulation_controller.h"
#include "widgets/tissue_session.h"

#include "tests/widgets/sweep_fixtures.h"
#include "tests/widgets/tissue_compare.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <vector>

using namespace resect;
using resect::test::meshDifference;
using resect::test::planeSweep;

namespace {

/// Surface triangles of the tissue and of its chips (a cut's caps add to their sum).
int allSurfaceTriangles(const Tissue& t) {
    int n = t.surface().surface().triangleCount();
    for (const Chip& c : t.chips())
        n += c.surface.triangleCount();
    return n;
}

/// Tets of the tissue and of the chips resected from it (a cut adds to their sum).
int allTets(const Tissue& t) {
    int n = t.mesh().tetCount();
    for (const Chip& c : t.chips())
        n += c.mesh.tetCount();
    return n;
}


constexpr int kWaitMs = 120'000;

const QString kPolypScenario =
    QStringLiteral(RESECT_SOURCE_DIR "/resources/scenarios/polyp-resection.json");

/// The document, its session and the controller on the example polyp scenario.
struct Scene {
    ScenarioDocument doc;
    TissueSession session{doc};
    SimulationController controller{doc, session};
    explicit Scene(const QString& dir) {
        doc.setAutosaveDirectory(dir);
        if (doc.open(kPolypScenario))
            session.waitForIdle(kWaitMs);
    }
};

/// The largest distance of a node from its rest position (mm).
double maxDisplacement(const TetMesh& mesh) {
    double d = 0;
    for (int n = 0; n < mesh.nodeCount(); ++n)
        d = std::max(d, (mesh.pos(n) - mesh.ref(n)).norm());
    return d;
}

/// Empty if the surface handed out is exactly where its binding puts it on the tissue's
/// tets; else the first vertex that is not.
QString surfaceLag(const Tissue& tissue) {
    std::vector<Vec3> bound;
    tissue.surface().binding().apply(tissue.mesh(), bound);
    const std::vector<Vec3>& shown = tissue.surface().surface().positions;
    if (bound.size() != shown.size())
        return QStringLiteral("%1 bound vertices, %2 shown").arg(bound.size()).arg(shown.size());
    for (std::size_t v = 0; v < bound.size(); ++v)
        if (bound[v] != shown[v])
            return QStringLiteral("vertex %1").arg(v);
    return {};
}

} // namespace

class TestSimulationController : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void runsACopyOfTheCurrentTissue() {
        Scene s(m_dir.path());
        QVERIFY(s.session.current());
        QVERIFY2(s.controller.isReady(), qPrintable(s.controller.error()));
        QCOMPARE(s.controller.effectNames().size(), std::size_t(5));
        QCOMPARE(s.controller.steps(), 0LL);
        QCOMPARE(s.controller.tissue().cutCount(), 3);
        QCOMPARE(meshDifference(s.controller.mesh(), s.session.current()->mesh()), QString());
        QVERIFY(&s.controller.mesh() != &s.session.current()->mesh());
        // The tissue's anchors (the stalk) hold in the fixed effect.
        QVERIFY(!s.controller.tissue().anchors().empty());
    }

    void theSurfaceHandedOutFollowsTheTets() {
        Scene s(m_dir.path());
        QVERIFY(s.controller.isReady());
        const std::vector<Vec3> rest = s.controller.surface().surface().positions;
        for (int i = 0; i < 20; ++i)
            QVERIFY2(s.controller.step(), qPrintable(s.controller.error()));
        QVERIFY(maxDisplacement(s.controller.mesh()) > 0);
        QVERIFY(s.controller.surface().surface().positions != rest); // it moved with the tets
        QCOMPARE(surfaceLag(s.controller.tissue()), QString());
    }

    void aCutAddedWhileSimulatingIsFollowedWithoutAReset() {
        Scene s(m_dir.path());
        QVERIFY(s.controller.isReady());
        for (int i = 0; i < 30; ++i)
            QVERIFY2(s.controller.step(), qPrintable(s.controller.error()));
        const double time = s.controller.time();
        const long long steps = s.controller.steps();
        const int tets = allTets(s.controller.tissue());
        const int triangles = allSurfaceTriangles(s.controller.tissue());
        const double moved = maxDisplacement(s.controller.mesh());
        QVERIFY(time > 0 && moved > 0);

        QSignalSpy followed(&s.controller, &SimulationController::cutsFollowed);
        QSignalSpy rebuilt(&s.controller, &SimulationController::resetDone);
        // Through the stalk below the detached head: the anchored base keeps the rest.
        s.doc.addSweep(planeSweep(s.session.base()->mesh(), 0.25, 1e-3));
        QVERIFY(s.session.waitForIdle(kWaitMs));
        QVERIFY2(s.session.error().isEmpty(), qPrintable(s.session.error()));
        QCOMPARE(s.session.current()->cuts(), 4);

        QCOMPARE(followed.count(), 1);
        QCOMPARE(rebuilt.count(), 0);
        QCOMPARE(s.controller.time(), time); // no reset: the time goes on
        QCOMPARE(s.controller.steps(), steps);
        QCOMPARE(s.controller.tissue().cutCount(), 4);
        QVERIFY(allTets(s.controller.tissue()) > tets); // the cut's tets (the head left as a chip)
        QVERIFY(allSurfaceTriangles(s.controller.tissue()) > triangles);
        QVERIFY(maxDisplacement(s.controller.mesh()) > 0.5 * moved); // still deformed
        QVERIFY(checkValidity(s.controller.mesh()).empty());
        QCOMPARE(surfaceLag(s.controller.tissue()), QString());
        // The simulation goes on with the cut (a smaller stable step).
        QVERIFY(s.controller.timeStep() > 0);
        QVERIFY2(s.controller.step(), qPrintable(s.controller.error()));
        QVERIFY(s.controller.time() > time);

        // Undo removes the cut: rebuilt from the current tissue at time 0.
        s.doc.undoStack()->undo();
        QVERIFY(s.session.waitForIdle(kWaitMs));
        QCOMPARE(rebuilt.count(), 1);
        QCOMPARE(s.controller.time(), 0.0);
        QCOMPARE(s.controller.steps(), 0LL);
        QCOMPARE(s.controller.tissue().cutCount(), 3);
        QCOMPARE(meshDifference(s.controller.mesh(), s.session.current()->mesh()), QString());

        // Redo at rest: the local cut gives exactly the session's current tissue.
        s.doc.undoStack()->redo();
        QVERIFY(s.session.waitForIdle(kWaitMs));
        QCOMPARE(followed.count(), 2);
        QCOMPARE(rebuilt.count(), 1);
        QCOMPARE(meshDifference(s.controller.mesh(), s.session.current()->mesh()), QString());
    }

    void otherChangesRebuild() {
        Scene s(m_dir.path());
        QVERIFY(s.controller.isReady());
        for (int i = 0; i < 5; ++i)
            QVERIFY(s.controller.step());
        QSignalSpy rebuilt(&s.controller, &SimulationController::resetDone);

        // Other cut settings change the existing cuts.
        s.doc.setD(0.3);
        QVERIFY(s.session.waitForIdle(kWaitMs));
        QCOMPARE(rebuilt.count(), 1);
        QCOMPARE(s.controller.steps(), 0LL);
        QCOMPARE(meshDifference(s.controller.mesh(), s.session.current()->mesh()), QString());

        // Effects.
        QVERIFY(s.controller.step());
        QVERIFY(s.doc.toggleEffect(QStringLiteral("gravity")));
        QCOMPARE(rebuilt.count(), 2);
        QCOMPARE(s.controller.steps(), 0LL);
        QCOMPARE(s.controller.effectNames().size(), std::size_t(4));

        // A new document with the same tissue and cuts is still another document: rebuilt
        // once, when the session publishes its tissue.
        QVERIFY(s.controller.step());
        QVERIFY(s.doc.open(kPolypScenario));
        QCOMPARE(rebuilt.count(), 2);
        QVERIFY(s.session.waitForIdle(kWaitMs));
        QCOMPARE(rebuilt.count(), 3);
        QCOMPARE(s.controller.steps(), 0LL);
        QCOMPARE(s.controller.effectNames().size(), std::size_t(5));
    }

    void settingsThatChangeNoCutKeepTheSimulation() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        SimulationController controller(doc, session);
        QVERIFY(doc.newFromSample(QStringLiteral("myoma")));
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY(controller.isReady());
        for (int i = 0; i < 5; ++i)
            QVERIFY(controller.step());
        const double time = controller.time();
        const auto before = session.current();
        QSignalSpy rebuilt(&controller, &SimulationController::resetDone);
        // No cuts yet: other settings give the same tissue. The session publishes a new
        // current state; the simulation goes on.
        doc.setD(0.3);
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY(session.current() != before);
        QCOMPARE(session.current()->applied.options.d, 0.3);
        QCOMPARE(rebuilt.count(), 0);
        QCOMPARE(controller.time(), time);
        QCOMPARE(controller.steps(), 5LL);
    }
};

QTEST_MAIN(TestSimulationController)
#include "test_simulation_controller.moc"
