// `resect bench realtime --quick` end to end on tiny boxes (issue 17, item 5): the CSV has the
// documented columns and one row per mesh and case (projective dynamics at 5 and 1 iterations,
// backward Euler, each at 1 ms and 1/60 s, and the explicit integrator at its own step) for the
// samples, the samples after the scoops and the boxes; real-time factors are positive and
// finite; projective dynamics never diverges, and a cut re-factors it; the markdown
// names the goals. Bad input exits 2 with one line naming the option and writes nothing. The
// plot is drawn by resect-plot (not here, as for `bench resection`: no display needed). Nothing
// is timed.
#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QMap>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace resect::testing;

namespace {

/// One CSV row by column name.
using Row = QMap<QString, QString>;

double number(const Row& row, const QString& column, bool* ok = nullptr) {
    return row[column].toDouble(ok);
}

} // namespace

class TestCliBenchRealtime : public QObject {
    Q_OBJECT
private slots:
    void quickRunOnTinyBoxes() {
        QTemporaryDir dir;
        const QString out = dir.filePath("rt");
        const Run r = runCli({"bench", "realtime", "--quick", "--sizes", "200,400", "--scoops",
                              "3", "--out", out, "--no-plots"});
        QVERIFY2(r.code == 0, qPrintable(r.err));

        const QStringList csv = readLines(out + "/realtime.csv");
        QVERIFY(!csv.isEmpty());
        const QStringList header = csv.front().split(',');
        const QStringList columns{"mesh",        "tets",           "nodes",       "integrator",
                                  "iterations",  "dt",             "steps",       "wall_s",
                                  "realtime_factor", "ms_per_step", "factor_ms",  "peak_rss_mb",
                                  "diverged",    "refactor_ms"};
        for (const QString& column : columns)
            QVERIFY2(header.contains(column), qPrintable(column));

        // mesh -> the cases run on it, as "integrator iterations dt"
        QMap<QString, QSet<QString>> cases;
        for (int i = 1; i < csv.size(); ++i) {
            const QStringList cells = csv[i].split(',');
            QCOMPARE(cells.size(), header.size());
            Row row;
            for (int c = 0; c < header.size(); ++c)
                row[header[c]] = cells[c];
            cases[row["mesh"]].insert(row["integrator"] + " " + row["iterations"] + " " +
                                      (row["integrator"] == "symplectic-euler" ? "stable" : row["dt"]));
            QVERIFY2(row["diverged"] == "0" || row["diverged"] == "1", qPrintable(csv[i]));
            bool ok = false;
            for (const char* column : {"tets", "nodes", "steps", "peak_rss_mb"})
                QVERIFY2(number(row, column, &ok) > 0 && ok, qPrintable(csv[i] + ": " + column));
            // a diverged case stops at the failing step: the factor is that of the steps before
            const double factor = number(row, "realtime_factor", &ok);
            QVERIFY2(ok && std::isfinite(factor) && factor > 0, qPrintable(csv[i]));
            QVERIFY2(number(row, "dt") > 0 && number(row, "ms_per_step") > 0, qPrintable(csv[i]));

            if (row["integrator"] != "projective-dynamics") {
                QVERIFY2(row["factor_ms"].isEmpty() && row["iterations"].isEmpty(), qPrintable(csv[i]));
                continue;
            }
            QVERIFY2(number(row, "factor_ms", &ok) > 0 && ok, qPrintable(csv[i]));
            // stable at any step and iteration count (projective_dynamics.h)
            QVERIFY2(row["diverged"] == "0", qPrintable(csv[i]));
            // the scoop after the run re-factored the system
            QVERIFY2(number(row, "refactor_ms", &ok) > 0 && ok, qPrintable(csv[i]));
        }
        const QSet<QString> expected{"projective-dynamics 5 0.001",  "projective-dynamics 1 0.001",
                                     "backward-euler  0.001",        "projective-dynamics 5 0.0166667",
                                     "projective-dynamics 1 0.0166667", "backward-euler  0.0166667",
                                     "symplectic-euler  stable"};
        const QStringList meshes{"polyp", "polyp-3scoops", "myoma", "myoma-3scoops", "box-200",
                                 "box-400"};
        QCOMPARE(QSet<QString>(cases.keyBegin(), cases.keyEnd()),
                 QSet<QString>(meshes.begin(), meshes.end()));
        for (const QString& mesh : meshes)
            QVERIFY2(cases[mesh] == expected, qPrintable(mesh + ": " + QStringList(cases[mesh].values()).join("; ")));
        QCOMPARE(csv.size(), 1 + meshes.size() * static_cast<int>(expected.size()));

        const QString md = readLines(out + "/realtime.md").join('\n');
        QVERIFY2(md.contains("| box-200 | 162 |"), qPrintable(md));
        QVERIFY(md.contains("samples at 1 ms: >= 20x | polyp |"));
        QVERIFY(md.contains("| 10k tets at 1 ms: >= 1x | box-10000 | not run | not run |"));
        QVERIFY(r.out.contains("| mesh | tets |"));
        // only the two files, no temporaries, no plot with --no-plots
        QCOMPARE(QDir(out).entryList(QDir::Files), QStringList({"realtime.csv", "realtime.md"}));
    }

    void badInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("names");
        QTest::newRow("size too small") << QStringList{"--sizes", "5"} << "--sizes";
        QTest::newRow("size not a number") << QStringList{"--sizes", "1000,many"} << "many";
        QTest::newRow("empty size") << QStringList{"--sizes", "1000,"} << "--sizes";
        QTest::newRow("negative scoops") << QStringList{"--scoops", "-1"} << "--scoops";
        QTest::newRow("too many scoops") << QStringList{"--scoops", "101"} << "--scoops";
        QTest::newRow("unknown option") << QStringList{"--fast"} << "--fast";
        QTest::newRow("stray argument") << QStringList{"mesh.vtu"} << "mesh.vtu";
    }
    void badInput() {
        QFETCH(QStringList, args);
        QFETCH(QString, names);
        QTemporaryDir dir;
        const QString out = dir.filePath("rt");
        const Run r = runCli(QStringList{"bench", "realtime", "--quick", "--no-plots", "--out", out} + args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(names), qPrintable(r.err));
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY2(!QFileInfo::exists(out), "nothing is written on bad input");
    }

    void outMustBeAFolderAndIsRequired() {
        QTemporaryDir dir;
        const QString file = dir.filePath("file");
        QVERIFY(writeFile(file, "x"));
        Run r = runCli({"bench", "realtime", "--quick", "--no-plots", "--out", file});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("--out"), qPrintable(r.err));
        QCOMPARE(sha256(file), QCryptographicHash::hash("x", QCryptographicHash::Sha256));
        r = runCli({"bench", "realtime", "--quick", "--no-plots"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("--out"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliBenchRealtime)
#include "test_cli_bench_realtime.moc"
