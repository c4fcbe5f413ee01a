// `resect bench resection` end to end (issue 16) on three passes over the polyp: the CSV has
// one row per method and pass with finite values, subdivision ends with more tets than
// hybrid, hybrid with the improvement keeps the worst radius ratio at least half the input's
// after every pass, no pass leaves the tissue overlapping itself, and the markdown summary is
// written; bad input exits 2 with one line
// naming the option and writes nothing. The plot is drawn by resect-plot (not here: no display
// needed). Nothing is timed.
#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QMap>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace resect::testing;

namespace {

/// One CSV row by column name.
using Row = QMap<QString, QString>;

} // namespace

class TestCliBenchResection : public QObject {
    Q_OBJECT
private slots:
    void threePassesOnThePolyp() {
        QTemporaryDir dir;
        const QString out = dir.filePath("res");
        const Run r = runCli({"bench", "resection", "--sample", "polyp", "--passes", "3", "--out",
                              out, "--no-plots"});
        QVERIFY2(r.code == 0, qPrintable(r.err));

        const QStringList csv = readLines(out + "/resection.csv");
        QCOMPARE(csv.size(), 1 + 3 * 3); // header, 3 passes x 3 methods
        // The message column is the last and empty when the cut succeeded: keep empty cells.
        const QStringList header = csv.front().split(',');
        const QStringList numeric{"pass",
                                  "tets",
                                  "worst_ratio",
                                  "shortest_edge",
                                  "stable_dt",
                                  "ms",
                                  "chips",
                                  "tets_rel",
                                  "worst_ratio_rel",
                                  "shortest_edge_rel",
                                  "stable_dt_rel",
                                  "input_tets",
                                  "input_worst_ratio",
                                  "input_shortest_edge",
                                  "input_stable_dt",
                                  "overlap",
                                  "overlap_rel"};
        for (const QString& column : numeric + QStringList{"mesh", "method", "status", "message"})
            QVERIFY2(header.contains(column), qPrintable(column));
        QMap<QString, QList<Row>> byMethod;
        for (int i = 1; i < csv.size(); ++i) {
            const QStringList cells = csv[i].split(',');
            QCOMPARE(cells.size(), header.size());
            Row row;
            for (int c = 0; c < header.size(); ++c)
                row[header[c]] = cells[c];
            QCOMPARE(row["mesh"], QString("polyp"));
            QCOMPARE(row["status"], QString("ok"));
            for (const QString& column : numeric) {
                bool ok = false;
                const double v = row[column].toDouble(&ok);
                QVERIFY2(ok && std::isfinite(v) && v >= 0, qPrintable(csv[i] + ": " + column));
            }
            QVERIFY(row["worst_ratio"].toDouble() > 0 && row["stable_dt"].toDouble() > 0);
            byMethod[row["method"]].append(row);
        }
        QCOMPARE(byMethod.keys(), QStringList({"hybrid", "hybrid+improve", "subdivision"}));
        for (const QList<Row>& rows : byMethod) {
            QCOMPARE(rows.size(), 3);
            for (int k = 0; k < 3; ++k) {
                QCOMPARE(rows[k]["pass"].toInt(), k + 1);
                QCOMPARE(rows[k]["input_tets"], rows[0]["input_tets"]);
                // the ratio columns are the values over the input's
                // The polyp's scoops leave no overlap, with or without the improvement
                // (test_resection_quality asserts it over 20 passes): 0 up to rounding.
                QVERIFY2(rows[k]["overlap_rel"].toDouble() <= 1e-9, qPrintable(rows[k]["method"] + ": " + rows[k]["overlap_rel"]));
                QVERIFY(std::abs(rows[k]["worst_ratio_rel"].toDouble() *
                                     rows[k]["input_worst_ratio"].toDouble() -
                                 rows[k]["worst_ratio"].toDouble()) <=
                        1e-4 * rows[k]["worst_ratio"].toDouble());
            }
            QVERIFY(rows[2]["chips"].toInt() >= 1); // the scoops take chips off the polyp
        }
        // Subdivision adds tets the hybrid method avoids (section 4, Table 1).
        QVERIFY2(byMethod["subdivision"][2]["tets"].toInt() > byMethod["hybrid"][2]["tets"].toInt(),
                 qPrintable(byMethod["subdivision"][2]["tets"] + " vs " +
                            byMethod["hybrid"][2]["tets"]));
        // The product's defaults keep the tissue healthy
        // (tests/core/tissue/test_resection_quality).
        for (const Row& row : byMethod["hybrid+improve"])
            QVERIFY2(row["worst_ratio_rel"].toDouble() >= 0.5,
                     qPrintable(row["pass"] + ": " + row["worst_ratio_rel"]));

        const QString md = readLines(out + "/resection.md").join('\n');
        QVERIFY(md.contains("| polyp | subdivision | 3 |"));
        QVERIFY(md.contains("| polyp | hybrid+improve | min over 3 |"));
        QVERIFY(r.out.contains("| mesh | method | pass |"));
        // only the two files, no temporaries, no plot with --no-plots
        QCOMPARE(QDir(out).entryList(QDir::Files), QStringList({"resection.csv", "resection.md"}));
    }

    void badInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("names");
        QTest::newRow("unknown sample") << QStringList{"--sample", "polyp,uterus"} << "uterus";
        QTest::newRow("missing surface")
            << QStringList{"--surface", "missing.off"} << "missing.off";
        QTest::newRow("unreadable surface")
            << QStringList{"--surface", "garbage.off"} << "--surface";
        QTest::newRow("open surface") << QStringList{"--surface", "open.off"} << "--surface";
        QTest::newRow("no passes") << QStringList{"--passes", "0"} << "--passes";
        QTest::newRow("too many passes") << QStringList{"--passes", "101"} << "--passes";
        QTest::newRow("passes not a number") << QStringList{"--passes", "many"} << "--passes";
        QTest::newRow("no mesh") << QStringList{"--sample", "none"} << "--surface";
        QTest::newRow("unknown option") << QStringList{"--fast"} << "--fast";
    }
    void badInput() {
        QFETCH(QStringList, args);
        QFETCH(QString, names);
        QTemporaryDir dir;
        QFile garbage(dir.filePath("garbage.off"));
        QVERIFY(garbage.open(QIODevice::WriteOnly));
        garbage.write("OFF\nthis is not a mesh\n");
        garbage.close();
        QFile open(dir.filePath("open.off")); // one triangle: not closed
        QVERIFY(open.open(QIODevice::WriteOnly));
        open.write("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        open.close();
        for (QString& a : args)
            if (a.endsWith(".off"))
                a = dir.filePath(a);
        const QString out = dir.filePath("res");
        const Run r = runCli(QStringList{"bench", "resection", "--no-plots", "--out", out} + args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(names), qPrintable(r.err));
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY2(!QFileInfo::exists(out), "nothing is written on bad input");
    }

    void outMustBeAFolderAndIsRequired() {
        QTemporaryDir dir;
        const QString file = dir.filePath("file");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("x");
        f.close();
        Run r = runCli({"bench", "resection", "--no-plots", "--out", file});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("--out"), qPrintable(r.err));
        QCOMPARE(sha256(file), QCryptographicHash::hash("x", QCryptographicHash::Sha256));
        r = runCli({"bench", "resection", "--no-plots"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("--out"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliBenchResection)
#include "test_cli_bench_resection.moc"
