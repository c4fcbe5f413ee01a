// End-to-end tests of `resect simulate`: the report keys, effects as declared, the default
// (stable) time step, divergence (exit 1, report with finite = false, no output), the
// implicit integrator at large steps, and bad input (exit 2, one line naming the option).
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/topology.h"
#include "scenario/mesh_io.h"

#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace resect;
using resect::testing::Run;
using resect::testing::runCli;
using resect::testing::readJsonFile;
using resect::testing::sha256;

namespace {

QStringList effectNames(const QJsonObject& report) {
    QStringList names;
    for (const QJsonValue& e : report["effects"].toArray()) {
        names << e.toObject()["name"].toString();
        if (!(e.toObject()["time_ms"].toDouble(-1) >= 0))
            names << "<bad time_ms>";
    }
    return names;
}

} // namespace

class TestCliSimulate : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& n) const { return m_dir.filePath(n); }

private slots:
    void initTestCase() {
        // A 6 x 2 x 2 mm bar with cells of 0.5 mm.
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(6, 2, 2), 12, 4, 4);
        computeLumpedMasses(m, 1e-3);
        QVERIFY(writeVtu(path("bar.vtu").toStdString(), m).ok());
    }

    void cantileverUnderGravity() {
        const QByteArray before = sha256(path("bar.vtu"));
        const Run r = runCli({"simulate", path("bar.vtu"), "--steps", "300", "--effects",
                              "deformation,gravity", "--fix-box", "-1", "-1", "-1", "0.01", "3",
                              "3", "--out", path("bent.vtu"), "--report", path("bent.json")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(sha256(path("bar.vtu")), before);
        const QJsonObject rep = readJsonFile(path("bent.json"));
        for (const char* key : {"steps", "dt", "stable_dt", "integrator", "effects", "finite",
                                "max_speed", "kinetic_energy", "inverted"})
            QVERIFY2(rep.contains(key), key);
        QCOMPARE(rep["steps"].toInt(), 300);
        QCOMPARE(rep["integrator"].toString(), QString("symplectic-euler"));
        QCOMPARE(rep["dt"].toDouble(), rep["stable_dt"].toDouble()); // the default
        QVERIFY(rep["dt"].toDouble() > 0);
        QCOMPARE(effectNames(rep), (QStringList{"deformation", "gravity", "fixed"}));
        QCOMPARE(rep["finite"].toBool(), true);
        QCOMPARE(rep["inverted"].toInt(), 0);
        QVERIFY(!rep.contains("error"));
        const QJsonObject ke = rep["kinetic_energy"].toObject();
        QCOMPARE(ke["initial"].toDouble(), 0.0);
        QVERIFY(ke["max"].toDouble() >= ke["final"].toDouble());
        QVERIFY(ke["final"].toDouble() > 0);
        QVERIFY(rep["max_speed"].toDouble() > 0);

        TetMesh in, out;
        QVERIFY(readTetMesh(path("bar.vtu").toStdString(), in).ok());
        QVERIFY(readTetMesh(path("bent.vtu").toStdString(), out).ok());
        QCOMPARE(out.nodeCount(), in.nodeCount());
        double tip = 0;
        for (int i = 0; i < out.nodeCount(); ++i) {
            if (in.ref(i).x() <= 0.01)
                QVERIFY(out.pos(i) == in.pos(i)); // anchored
            else
                tip = std::max(tip, in.pos(i).z() - out.pos(i).z());
        }
        QVERIFY2(tip > 0, qPrintable(QString::number(tip)));
    }

    void onlyDeclaredEffectsRun() {
        // Deformation alone on a mesh at rest: nothing moves, and the report lists only it.
        const Run r = runCli({"simulate", path("bar.vtu"), "--steps", "50", "--out",
                              path("rest.vtu"), "--report", path("rest.json")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject rep = readJsonFile(path("rest.json"));
        QCOMPARE(effectNames(rep), QStringList{"deformation"});
        QCOMPARE(rep["max_speed"].toDouble(), 0.0);
        QCOMPARE(rep["kinetic_energy"].toObject()["max"].toDouble(), 0.0);
    }

    void divergenceIsReportedAndNothingWritten() {
        QFile::remove(path("boom.vtu"));
        const Run probe = runCli({"simulate", path("bar.vtu"), "--steps", "1", "--out",
                                  path("probe.vtu"), "--report", path("probe.json")});
        QCOMPARE(probe.code, 0);
        const double stable = readJsonFile(path("probe.json"))["stable_dt"].toDouble();
        const Run r =
            runCli({"simulate", path("bar.vtu"), "--steps", "2000", "--dt",
                    QString::number(3 * stable, 'g', 17), "--effects", "deformation,gravity",
                    "--out", path("boom.vtu"), "--report", path("boom.json")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains("too large for the explicit"), qPrintable(r.err));
        QCOMPARE(r.err.trimmed().count('\n'), 0);
        QVERIFY(!QFile::exists(path("boom.vtu")));
        const QJsonObject rep = readJsonFile(path("boom.json"));
        QCOMPARE(rep["finite"].toBool(true), false);
        QVERIFY(rep["steps"].toInt() < 2000);
        QCOMPARE(rep["requested_steps"].toInt(), 2000);
        QVERIFY(rep["error"].toString().contains("stable estimate"));
    }

    void implicitTakesLargeSteps() {
        const Run probe = runCli({"simulate", path("bar.vtu"), "--steps", "1", "--out",
                                  path("probe.vtu"), "--report", path("probe.json")});
        QCOMPARE(probe.code, 0);
        const double stable = readJsonFile(path("probe.json"))["stable_dt"].toDouble();
        const Run r = runCli({"simulate",
                              path("bar.vtu"),
                              "--steps",
                              "40",
                              "--dt",
                              QString::number(10 * stable, 'g', 17),
                              "--integrator",
                              "implicit",
                              "--effects",
                              "deformation,gravity,damping",
                              "--damping",
                              "20",
                              "--fix-box",
                              "-1",
                              "-1",
                              "-1",
                              "0.01",
                              "3",
                              "3",
                              "--out",
                              path("implicit.vtu"),
                              "--report",
                              path("implicit.json")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject rep = readJsonFile(path("implicit.json"));
        // "implicit" is projective dynamics: factored once, 5 local-global iterations a step.
        QCOMPARE(rep["integrator"].toString(), QString("projective-dynamics"));
        QCOMPARE(rep["finite"].toBool(), true);
        QCOMPARE(rep["inverted"].toInt(), 0);
        QCOMPARE(rep["factorizations"].toInt(), 1);
        QCOMPARE(rep["iterations"].toInt(), 5);
        QVERIFY(rep["halvings"].isDouble() && rep["restarts"].isDouble());
        QVERIFY(rep["realtime_factor"].toDouble() > 0);
        QVERIFY(rep["wall_s"].toDouble() > 0);
        QCOMPARE(effectNames(rep), (QStringList{"deformation", "gravity", "damping", "fixed"}));
    }

    void backwardEulerStaysForComparison() {
        const Run probe = runCli({"simulate", path("bar.vtu"), "--steps", "1", "--out", path("probe.vtu"), "--report",
                                  path("probe.json")});
        QCOMPARE(probe.code, 0);
        const double stable = readJsonFile(path("probe.json"))["stable_dt"].toDouble();
        const Run r = runCli({"simulate", path("bar.vtu"), "--steps", "20", "--dt", QString::number(10 * stable, 'g', 17),
                              "--integrator", "backward-euler", "--effects", "deformation,gravity", "--fix-box", "-1", "-1",
                              "-1", "0.01", "3", "3", "--out", path("be.vtu"), "--report", path("be.json")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject rep = readJsonFile(path("be.json"));
        QCOMPARE(rep["integrator"].toString(), QString("backward-euler"));
        QCOMPARE(rep["inverted"].toInt(), 0);
        QVERIFY(!rep.contains("factorizations"));
    }

    void iterationsAreChecked() {
        const Run r = runCli({"simulate", path("bar.vtu"), "--steps", "2", "--integrator", "implicit", "--iterations", "0",
                              "--out", path("it.vtu")});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("--iterations"), qPrintable(r.err));
    }

    void toolContact() {
        const Run r = runCli({"simulate",
                              path("bar.vtu"),
                              "--steps",
                              "100",
                              "--effects",
                              "deformation,tool-contact",
                              "--tool",
                              "2,1,2.8,4,1,2.8",
                              "--tool-radius",
                              "1",
                              "--fix-box",
                              "-1",
                              "-1",
                              "-1",
                              "7",
                              "3",
                              "0",
                              "--out",
                              path("pressed.vtu"),
                              "--report",
                              path("pressed.json")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject rep = readJsonFile(path("pressed.json"));
        QCOMPARE(effectNames(rep), (QStringList{"deformation", "tool-contact", "fixed"}));
        QVERIFY(rep["max_speed"].toDouble() > 0); // the tool pushed the top face in
    }

    void resectedPieces_data() {
        QTest::addColumn<QString>("policy");
        QTest::newRow("rigid (default)") << QString();
        QTest::newRow("remove") << "remove";
        QTest::newRow("deformable") << "deformable";
    }
    void resectedPieces() {
        // A cut bar in two pieces, fixed at its left end: the right piece is resected. Rigid
        // (the default) it falls as one body and is written with the tissue; removed it
        // leaves; deformable it is simulated with the rest. Mass is accounted for.
        QFETCH(QString, policy);
        TetMesh bar = makeBoxTetMesh(Vec3::Zero(), Vec3(6, 2, 2), 12, 4, 4);
        // Split at x = 4: the tets right of it get their own copies of the nodes on x = 4.
        std::vector<int> copyOf(bar.nodeCount(), -1);
        for (int t = 0; t < bar.tetCount(); ++t) {
            Tet q = bar.tet(t);
            Vec3 centre = Vec3::Zero();
            for (int v : q)
                centre += bar.ref(v) / 4;
            if (centre.x() < 4)
                continue;
            for (int& v : q)
                if (bar.ref(v).x() == 4) {
                    if (copyOf[v] < 0)
                        copyOf[v] = bar.addNode(bar.ref(v), bar.pos(v));
                    v = copyOf[v];
                }
            bar.replaceTet(t, q);
        }
        // The right piece floats 1 mm above the floor (the bar's bottom, z = 0) and 1 mm off
        // the left piece's end (above the tissue it would land on the tissue).
        {
            const Components pieces = connectedComponents(bar);
            const int right = pieces.nodeComponent[copyOf[std::find_if(copyOf.begin(), copyOf.end(), [](int c) { return c >= 0; }) - copyOf.begin()]];
            for (int n = 0; n < bar.nodeCount(); ++n)
                if (pieces.nodeComponent[n] == right)
                    bar.setNodePosition(n, bar.ref(n) + Vec3(1, 0, 1), bar.pos(n) + Vec3(1, 0, 1));
        }
        computeLumpedMasses(bar, 1e-3);
        QCOMPARE(connectedComponents(bar).count, 2);
        QVERIFY(writeVtu(path("split.vtu").toStdString(), bar).ok());
        QStringList args{"simulate", path("split.vtu"), "--steps", "2000", "--dt", "1e-4", "--integrator", "implicit",
                         "--effects", "deformation,gravity", "--fix-box", "-1", "-1", "-1", "0.01", "3", "3",
                         "--out", path("s.vtu"), "--report", path("s.json")};
        if (!policy.isEmpty())
            args << "--resected" << policy;
        const Run r = runCli(args);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        if (policy == "deformable") {
            // Simulated as tissue: with nothing holding it, it falls freely (below the floor).
            TetMesh out;
            QVERIFY(readTetMesh(path("s.vtu").toStdString(), out).ok());
            double highest = -1e9;
            for (int n = 0; n < out.nodeCount(); ++n)
                if (out.ref(n).z() > 0.999 && out.ref(n).x() > 4.999)
                    highest = std::max(highest, out.pos(n).z());
            QVERIFY2(highest < -100, qPrintable(QString::number(highest)));
        }
        const QJsonObject resected = readJsonFile(path("s.json"))["resected"].toObject();
        const bool deformable = policy == "deformable";
        QCOMPARE(resected["policy"].toString(), policy.isEmpty() ? QString("rigid") : (deformable ? QString("keep") : policy));
        QCOMPARE(resected["pieces"].toInt(), deformable ? 0 : 1);
        const double mass = resected["mass_before"].toDouble();
        QVERIFY(mass > 0);
        QVERIFY(std::abs(resected["mass_remaining"].toDouble() + resected["mass"].toDouble() - mass) <= 1e-9 * mass);
        TetMesh out;
        QVERIFY(readTetMesh(path("s.vtu").toStdString(), out).ok());
        QCOMPARE(connectedComponents(out).count, policy == "remove" ? 1 : 2);
        if (policy.isEmpty()) {
            // The chip fell for 0.2 s (g t^2 / 2 = 196 mm): from 1 mm above the floor onto it.
            double lowest = 1e9;
            for (int n = 0; n < out.nodeCount(); ++n)
                if (out.ref(n).z() > 0.999 && out.ref(n).x() > 4.999)
                    lowest = std::min(lowest, out.pos(n).z());
            QVERIFY2(lowest > -0.05 && lowest < 0.05, qPrintable(QString::number(lowest)));
        }
    }

    void badInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QStringList base{"--steps", "5", "--out", "x.vtu"};
        QTest::newRow("no mesh") << (QStringList{"simulate"} + base) << "MESH";
        QTest::newRow("missing mesh")
            << (QStringList{"simulate", "/nonexistent/m.vtu"} + base) << "/nonexistent/m.vtu";
        QTest::newRow("no steps") << QStringList{"simulate", "bar.vtu", "--out", "x.vtu"}
                                  << "--steps";
        QTest::newRow("zero steps")
            << QStringList{"simulate", "bar.vtu", "--steps", "0", "--out", "x.vtu"} << "--steps";
        QTest::newRow("steps text")
            << QStringList{"simulate", "bar.vtu", "--steps", "many", "--out", "x.vtu"} << "--steps";
        QTest::newRow("no out") << QStringList{"simulate", "bar.vtu", "--steps", "5"} << "--out";
        QTest::newRow("dt nan") << (QStringList{"simulate", "bar.vtu", "--dt", "nan"} + base)
                                << "--dt";
        QTest::newRow("dt zero") << (QStringList{"simulate", "bar.vtu", "--dt", "0"} + base)
                                 << "--dt";
        QTest::newRow("dt negative")
            << (QStringList{"simulate", "bar.vtu", "--dt", "-1e-5"} + base) << "--dt";
        QTest::newRow("unknown effect")
            << (QStringList{"simulate", "bar.vtu", "--effects", "deformation,magic"} + base)
            << "magic";
        QTest::newRow("effect twice")
            << (QStringList{"simulate", "bar.vtu", "--effects", "gravity,gravity"} + base)
            << "--effects";
        QTest::newRow("unknown integrator")
            << (QStringList{"simulate", "bar.vtu", "--integrator", "rk4"} + base) << "--integrator";
        QTest::newRow("fix-box short")
            << (QStringList{"simulate", "bar.vtu", "--fix-box", "0", "0", "0", "1", "1"} + base)
            << "--fix-box";
        QTest::newRow("fix-box nan")
            << (QStringList{"simulate", "bar.vtu", "--fix-box", "0", "0", "nan", "1", "1", "1"} +
                base)
            << "--fix-box";
        QTest::newRow("fix-box inverted")
            << (QStringList{"simulate", "bar.vtu", "--fix-box", "1", "0", "0", "0", "1", "1"} +
                base)
            << "--fix-box";
        QTest::newRow("fixed without box")
            << (QStringList{"simulate", "bar.vtu", "--effects", "deformation,fixed"} + base)
            << "--fix-box";
        QTest::newRow("damping without effect")
            << (QStringList{"simulate", "bar.vtu", "--damping", "3"} + base) << "--damping";
        QTest::newRow("damping without value")
            << (QStringList{"simulate", "bar.vtu", "--effects", "damping"} + base) << "--damping";
        QTest::newRow("tool without shape")
            << (QStringList{"simulate", "bar.vtu", "--effects", "tool-contact"} + base) << "--tool";
        QTest::newRow("tool bad numbers")
            << (QStringList{"simulate", "bar.vtu", "--effects", "tool-contact", "--tool", "1,2,x",
                            "--tool-radius", "1"} +
                base)
            << "--tool";
        QTest::newRow("tool radius zero")
            << (QStringList{"simulate", "bar.vtu", "--effects", "tool-contact", "--tool", "1,2,3",
                            "--tool-radius", "0"} +
                base)
            << "--tool-radius";
        QTest::newRow("unknown option")
            << (QStringList{"simulate", "bar.vtu", "--bogus"} + base) << "--bogus";
        QTest::newRow("resected keep")
            << (QStringList{"simulate", "bar.vtu", "--fix-box", "-1", "-1", "-1", "0.01", "3", "3", "--resected", "keep"} + base)
            << "--resected";
        QTest::newRow("resected without box")
            << (QStringList{"simulate", "bar.vtu", "--resected", "remove"} + base) << "--fix-box";
        QTest::newRow("out is input")
            << QStringList{"simulate", "bar.vtu", "--steps", "5", "--out", "bar.vtu"} << "input";
    }
    void badInput() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QDir::setCurrent(m_dir.path());
        const QByteArray before = sha256(path("bar.vtu"));
        const Run r = runCli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(r.err.trimmed().count('\n'), 0);
        QVERIFY(!QFile::exists(path("x.vtu")));
        QCOMPARE(sha256(path("bar.vtu")), before);
    }
};

QTEST_GUILESS_MAIN(TestCliSimulate)
#include "test_cli_simulate.moc"
