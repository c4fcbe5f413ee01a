// `resect bench` end to end on the hidden --tiny configuration: the CSVs and the summary are
// written with every row, bad options exit 2 with one line naming the option, the old bench
// subcommands still work, and without any way to draw the plots the command exits 1 with the
// CSVs written and a message saying why (it never crashes). The plots themselves are checked
// by test_cli_bench_plots (label display). Nothing is timed.
#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTest>

using namespace resect::testing;

namespace {

Run runWithEnv(const QStringList& args, const QProcessEnvironment& env) {
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(RESECT_CLI, args);
    Run r;
    if (!p.waitForFinished(600000)) {
        p.kill();
        r.err = "timed out";
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QStringList lines(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

} // namespace

class TestCliBench : public QObject {
    Q_OBJECT
private slots:
    void tinyStudyWritesTheCsvs() {
        QTemporaryDir dir;
        const QString out = dir.filePath("bench");
        const Run r = runCli({"bench", "--tiny", "--no-plots", "--out", out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QStringList accuracy = lines(out + "/accuracy_time.csv");
        QVERIFY(accuracy.size() > 20);
        const QStringList header = accuracy.front().split(',');
        for (const char* column : {"method", "d", "snap", "relax_steps", "sweep_error_max", "sweep_error_mean", "tets",
                                   "min_radius_ratio", "stable_dt", "cut_ms", "sim_ms_per_second"})
            QVERIFY2(header.contains(column), column);
        QStringList methods;
        for (int i = 1; i < accuracy.size(); ++i) {
            const QStringList cells = accuracy[i].split(',');
            QCOMPARE(cells.size(), header.size());
            const QString method = cells[header.indexOf("method")];
            if (!methods.contains(method))
                methods << method;
            bool ok = false;
            QVERIFY(cells[header.indexOf("stable_dt")].toDouble(&ok) > 0 && ok);
        }
        methods.sort();
        QCOMPARE(methods, QStringList({"hybrid-enhanced", "hybrid-standard", "subdivision"}));
        const QStringList scaling = lines(out + "/scaling.csv");
        QCOMPARE(scaling.size(), 3);  // header and the two tiny meshes
        const QStringList sh = scaling.front().split(',');
        for (const char* column : {"mesh_tets", "touched_tets", "cut_ms", "step_ns_per_tet_1t", "step_ns_per_tet_2t",
                                   "surface_vertices", "surface_update_ms"})
            QVERIFY2(sh.contains(column), column);
        const QStringList summary = lines(out + "/summary.md");
        QVERIFY(summary.join('\n').contains("paper's case"));
        QVERIFY(r.out.contains("| target |"));
        // no temporaries left behind
        QCOMPARE(QDir(out).entryList(QDir::Files).size(), 3);
    }

    void withoutADisplayTheCsvsStayAndTheMessageSaysWhy() {
        QTemporaryDir dir;
        const QString out = dir.filePath("bench");
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.insert("PATH", dir.filePath("empty"));  // no xvfb-run
        const Run r = runWithEnv({"bench", "--tiny", "--out", out}, env);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains("no plots") && r.err.contains("xvfb-run"), qPrintable(r.err));
        QVERIFY(QFile::exists(out + "/accuracy_time.csv"));
        QVERIFY(QFile::exists(out + "/scaling.csv"));
        QVERIFY(!QFile::exists(out + "/scaling.png"));
    }

    void badInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("names");
        QTest::newRow("no out") << QStringList{"bench", "--tiny"} << "--out";
        QTest::newRow("quick and tiny") << QStringList{"bench", "--tiny", "--quick", "--out", "x"} << "--quick";
        QTest::newRow("unknown study") << QStringList{"bench", "bogus", "--out", "x"} << "bogus";
        QTest::newRow("unknown option") << QStringList{"bench", "--fast", "--out", "x"} << "--fast";
    }
    void badInput() {
        QFETCH(QStringList, args);
        QFETCH(QString, names);
        QTemporaryDir dir;
        for (QString& a : args)
            if (a == "x")
                a = dir.filePath("x");
        const Run r = runCli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(names), qPrintable(r.err));
        QCOMPARE(r.err.count('\n'), 1);
    }

    void outIsAFile() {
        QTemporaryDir dir;
        const QString file = dir.filePath("file");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("x");
        f.close();
        const Run r = runCli({"bench", "--tiny", "--out", file});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains("--out"));
        QCOMPARE(sha256(file), QCryptographicHash::hash("x", QCryptographicHash::Sha256));
    }

    void oldSubcommandsStillWork() {
        QTemporaryDir dir;
        const QString csv = dir.filePath("cut.csv");
        Run r = runCli({"bench", "cut-scaling", "--sizes", "750", "--repeats", "1", "--out", csv});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(lines(csv).size(), 2);
        r = runCli({"bench", "sim", "--sizes", "750", "--threads", "1", "--steps", "2"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains("ns_tet_med"));
    }
};

QTEST_GUILESS_MAIN(TestCliBench)
#include "test_cli_bench.moc"
