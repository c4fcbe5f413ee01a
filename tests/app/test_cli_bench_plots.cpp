// `resect bench --tiny` draws its plots (resect-plot, VTK charts; under xvfb-run when there is
// no DISPLAY): every PNG exists, has the size asked for and is not blank. Label display: it
// fails, rather than skips, when no display can be had. Also resect-plot's own bad input.
#include "cli_runner.h"

#include <QDebug>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

using namespace resect::testing;

class TestCliBenchPlots : public QObject {
    Q_OBJECT
private slots:
    void plotsAreDrawn() {
        QTemporaryDir dir;
        const QString out = dir.filePath("bench");
        const Run r = runCli({"bench", "--tiny", "--out", out});
        if (r.code != 0)
            qWarning().noquote() << r.err;  // whole: QVERIFY2 cuts its message short
        QVERIFY2(r.code == 0, qPrintable(r.err.right(800)));
        const struct {
            const char* name;
            int width;
        } pngs[] = {{"cost_myoma.png", 1400}, {"d_myoma.png", 1800}, {"scaling.png", 1400}};
        for (const auto& png : pngs) {
            const QImage image(out + "/" + png.name);
            QVERIFY2(!image.isNull(), png.name);
            QCOMPARE(image.width(), png.width);
            QCOMPARE(image.height(), 560);
            QSet<QRgb> colours;
            int white = 0;
            for (int y = 0; y < image.height(); y += 2)
                for (int x = 0; x < image.width(); x += 2) {
                    const QRgb c = image.pixel(x, y) & 0xffffff;
                    colours.insert(c);
                    white += c == 0xffffff;
                }
            const double whiteShare = white / (image.width() * image.height() / 4.0);
            QVERIFY2(colours.size() > 50, qPrintable(QString("%1: %2 colours").arg(png.name).arg(colours.size())));
            QVERIFY2(whiteShare > 0.5 && whiteShare < 0.99, qPrintable(QString("%1: white %2").arg(png.name).arg(whiteShare)));
        }
        QCOMPARE(QDir(out).entryList({"*.png"}, QDir::Files).size(), 3);
    }

    void plotterBadInput() {
        const QString plotter = QFileInfo(RESECT_CLI).absolutePath() + "/resect-plot";
        QTemporaryDir dir;
        QProcess p;
        p.start(plotter, {"--accuracy", dir.filePath("missing.csv"), "--out", dir.path()});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains("missing.csv"));
    }
};

QTEST_GUILESS_MAIN(TestCliBenchPlots)
#include "test_cli_bench_plots.moc"
