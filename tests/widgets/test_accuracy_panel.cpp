// AccuracyPanel and AccuracyChart (widgets/accuracy_panel.h, accuracy_chart.h) under the
// offscreen platform, on a 3^3 box cut through by a slanted plane: Run starts the study on a
// worker thread (the panel stays responsive, progress arrives on the GUI thread), the rows
// shown are the configuration's cross product, a click on a point selects its row and Adopt
// (or a double click) asks for that row's cut settings, keeping the other settings; Cancel
// right after Run ends the study as cancelled and the panel runs again afterwards; destroying
// a running panel cancels and joins. The chart maps cost monotonically, finds no row in
// empty space, computes each method's Pareto front and paints offscreen.
#include "widgets/accuracy_chart.h"
#include "widgets/accuracy_panel.h"

#include "core/mesh/box_mesh.h"
#include "core/sweep/sweep_surface.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

#include <algorithm>
#include <set>

using namespace resect;

namespace {

constexpr int kTimeoutMs = 120'000;
constexpr int kBoxCells = 3;

TetMesh box() {
    return makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(kBoxCells), kBoxCells, kBoxCells, kBoxCells);
}

SweepSurface plane() {
    const double n = kBoxCells;
    SweepSurface sweep;
    const Status s =
        SweepSurface::fromStartEnd({Vec3(-1, -1, 1.23), Vec3(n + 1, -1, 1.31)},
                                   {Vec3(-1, n + 1, 1.39), Vec3(n + 1, n + 1, 1.47)}, sweep);
    Q_ASSERT(s.ok());
    return sweep;
}

/// Two d values, one repeat, snapping on, no relaxation: 2 * (1 + 2) rows.
StudyConfig smallConfig() {
    StudyConfig c = tinyConfig();
    c.dValues = {0.1, 0.3};
    c.snapOptions = {true};
    c.relaxSteps = {0};
    c.repeats = 1;
    c.simSteps = 1;
    return c;
}

StudyRow fakeRow(const std::string& method, double d, double error, double simMs, double cutMs) {
    StudyRow r;
    r.mesh = "fake";
    r.method = method;
    r.d = d;
    r.sweepErrorMax = error;
    r.sweepErrorMean = error / 2;
    r.simMsPerSecond = simMs;
    r.cutMs = cutMs;
    r.tets = 100;
    return r;
}

template <class T> T* child(QWidget& w, const char* name) {
    T* c = w.findChild<T*>(QString::fromLatin1(name));
    if (!c)
        qFatal("no child %s", name);
    return c;
}

} // namespace

class TestAccuracyPanel : public QObject {
    Q_OBJECT
private slots:
    void runSelectAndAdopt() {
        AccuracyPanel panel;
        QCOMPARE(panel.objectName(), QString("accuracyPanel"));
        auto* run = child<QPushButton>(panel, "runStudy");
        auto* cancel = child<QPushButton>(panel, "cancelStudy");
        auto* adopt = child<QPushButton>(panel, "adoptSettings");
        auto* progress = child<QProgressBar>(panel, "studyProgress");
        QVERIFY(!run->isEnabled()); // no tissue yet
        panel.resize(900, 640);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));

        panel.setTissue(box(), plane(), "box");
        const StudyConfig config = smallConfig();
        panel.setCustomConfig(config);
        CutSettings base;
        base.wSpring = 0.7;
        base.rings = 3;
        panel.setBaseCutSettings(base);
        QVERIFY(run->isEnabled());
        QVERIFY(!cancel->isEnabled());
        QVERIFY(!adopt->isEnabled());

        QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
        QList<int> values;
        bool onGuiThread = true;
        connect(progress, &QProgressBar::valueChanged, this, [&](int v) {
            values << v;
            onGuiThread = onGuiThread && QThread::currentThread() == qApp->thread();
        });
        QTest::mouseClick(run, Qt::LeftButton);
        QVERIFY(panel.isRunning()); // run() did not wait for the study
        QVERIFY(!run->isEnabled());
        QVERIFY(cancel->isEnabled());
        panel.run(); // ignored while running
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        QTest::qWait(50);
        QCOMPARE(finished.count(), 1); // the second Run started nothing
        const QList<QVariant> result = finished.takeFirst();
        QVERIFY2(result[0].toBool(), qPrintable(result[1].toString()));
        QVERIFY(!panel.isRunning());
        QVERIFY(run->isEnabled());
        QVERIFY(!cancel->isEnabled());
        QVERIFY(onGuiThread);
        QVERIFY(!values.isEmpty());
        QCOMPARE(progress->value(), progress->maximum());

        // The rows shown: every method for every d (hybrid with the one snap and relax option).
        const std::vector<StudyRow>& rows = panel.rows();
        QCOMPARE(rows.size(), config.dValues.size() * config.methods.size());
        QCOMPARE(panel.chart()->rows().size(), rows.size());
        std::set<std::pair<std::string, double>> seen;
        for (const StudyRow& r : rows) {
            QCOMPARE(QString::fromStdString(r.mesh), QString("box"));
            QCOMPARE(r.snap, r.method != "subdivision"); // subdivision: never snapped
            QCOMPARE(r.relaxSteps, 0);
            seen.insert({r.method, r.d});
        }
        for (StudyMethod m : config.methods)
            for (double d : config.dValues)
                QVERIFY2(seen.count({studyMethodName(m), d}), studyMethodName(m));

        // The x axis follows the cost (log scale: monotone), the y axis the error (lower: higher
        // up).
        AccuracyChart* chart = panel.chart();
        for (std::size_t a = 0; a < rows.size(); ++a)
            for (std::size_t b = 0; b < rows.size(); ++b) {
                if (rows[a].simMsPerSecond < rows[b].simMsPerSecond)
                    QVERIFY(chart->dataPosition(int(a)).x() <= chart->dataPosition(int(b)).x());
                if (rows[a].sweepErrorMax < rows[b].sweepErrorMax)
                    QVERIFY(chart->dataPosition(int(a)).y() >= chart->dataPosition(int(b)).y());
            }

        // Click a point: rows whose point is its own nearest (coincident points go to the
        // lowest index) can be clicked.
        std::vector<int> pickable;
        for (int r = 0; r < int(rows.size()); ++r)
            if (chart->rowAt(chart->pointPosition(r).toPoint()) == r)
                pickable.push_back(r);
        QVERIFY(!pickable.empty());
        const int picked = pickable.back();
        QSignalSpy selected(&panel, &AccuracyPanel::rowSelected);
        QTest::mouseClick(chart, Qt::LeftButton, {}, chart->pointPosition(picked).toPoint());
        QCOMPARE(panel.selectedRow(), picked);
        QCOMPARE(chart->selectedRow(), picked);
        QCOMPARE(selected.count(), 1);
        QVERIFY(adopt->isEnabled());
        const StudyRow& row = rows[std::size_t(picked)];
        const QString summary = child<QLabel>(panel, "selectedSettings")->text();
        QVERIFY2(summary.contains(AccuracyChart::methodLabel(row.method)), qPrintable(summary));

        QList<CutSettings> adopted;
        connect(&panel, &AccuracyPanel::adoptRequested, this,
                [&](const CutSettings& s) { adopted << s; });
        QTest::mouseClick(adopt, Qt::LeftButton);
        QCOMPARE(adopted.size(), 1);
        QCOMPARE(adopted[0].method,
                 row.method == "subdivision" ? CutMethod::Subdivision : CutMethod::Hybrid);
        if (row.method != "subdivision")
            QCOMPARE(adopted[0].triangulation, row.method == "hybrid-standard"
                                                   ? FaceTriangulation::Standard
                                                   : FaceTriangulation::Enhanced);
        QCOMPARE(adopted[0].d, row.d);
        QCOMPARE(adopted[0].snap, row.snap);
        QCOMPARE(adopted[0].relaxSteps, row.relaxSteps);
        QCOMPARE(adopted[0].wSpring, 0.7); // the other settings are kept
        QCOMPARE(adopted[0].rings, 3);

        // A double click on another point adopts it at once.
        const int other = pickable.front();
        QTest::mouseDClick(chart, Qt::LeftButton, {}, chart->pointPosition(other).toPoint());
        QVERIFY(adopted.size() >= 2);
        QCOMPARE(panel.selectedRow(), other);
        QCOMPARE(adopted.last(), AccuracyPanel::cutSettingsForRow(rows[std::size_t(other)], base));

        // Empty space clears nothing and selects nothing.
        QCOMPARE(chart->rowAt(QPointF(2, 2)), -1);
        QTest::mouseClick(chart, Qt::LeftButton, {}, QPoint(2, 2));
        QCOMPARE(panel.selectedRow(), other);

        // The cost axis combo switches the chart to the cut time.
        auto* axis = child<QComboBox>(panel, "costAxis");
        axis->setCurrentIndex(axis->findData(int(AccuracyChart::CostAxis::CutMs)));
        QCOMPARE(chart->costAxis(), AccuracyChart::CostAxis::CutMs);
        QVERIFY(!chart->grab().isNull());
    }

    void cancelRightAfterRun() {
        AccuracyPanel panel;
        panel.setTissue(box(), plane(), "box");
        StudyConfig config = tinyConfig(); // 27 rows: far more than the cancel lets through
        config.repeats = 3;
        panel.setCustomConfig(config);
        QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
        QTest::mouseClick(child<QPushButton>(panel, "runStudy"), Qt::LeftButton);
        QTest::mouseClick(child<QPushButton>(panel, "cancelStudy"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        QList<QVariant> result = finished.takeFirst();
        QVERIFY(!result[0].toBool());
        QVERIFY2(result[1].toString().contains("cancelled"), qPrintable(result[1].toString()));
        QVERIFY(!panel.isRunning());
        QVERIFY(panel.rows().size() < 27);
        QVERIFY(child<QPushButton>(panel, "runStudy")->isEnabled());
        QVERIFY(!child<QPushButton>(panel, "cancelStudy")->isEnabled());

        // Usable again.
        panel.setCustomConfig(smallConfig());
        QTest::mouseClick(child<QPushButton>(panel, "runStudy"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        result = finished.takeFirst();
        QVERIFY2(result[0].toBool(), qPrintable(result[1].toString()));
        QCOMPARE(panel.rows().size(), std::size_t(6));
    }

    void destroyingARunningPanelCancelsIt() {
        auto* panel = new AccuracyPanel;
        panel->setTissue(box(), plane(), "box");
        panel->setCustomConfig(tinyConfig());
        panel->run();
        QVERIFY(panel->isRunning());
        delete panel; // cancels and joins; the queued result is dropped
        QTest::qWait(20);
    }

    void noTissueNoRun() {
        AccuracyPanel panel;
        QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
        panel.run();
        QVERIFY(!panel.isRunning());
        panel.setTissue(box(), plane(), "box");
        panel.clearTissue();
        QVERIFY(!panel.hasTissue());
        QVERIFY(!child<QPushButton>(panel, "runStudy")->isEnabled());
        panel.run();
        QVERIFY(!panel.isRunning());
        QCOMPARE(finished.count(), 0);
        // Presets: tiny and quick are the library's configurations.
        auto* preset = child<QComboBox>(panel, "studyPreset");
        preset->setCurrentIndex(preset->findData("quick"));
        QCOMPARE(panel.studyConfig().label, std::string("quick"));
        preset->setCurrentIndex(preset->findData("tiny"));
        QCOMPARE(panel.studyConfig().label, std::string("tiny"));
    }

    void cutSettingsForEachMethod() {
        CutSettings base;
        base.triangulation = FaceTriangulation::Standard;
        base.damping = 3;
        StudyRow r = fakeRow("subdivision", 0.25, 0, 1, 1);
        CutSettings s = AccuracyPanel::cutSettingsForRow(r, base);
        QCOMPARE(s.method, CutMethod::Subdivision);
        QCOMPARE(s.d, 0.25);
        QVERIFY(!s.snap);
        QCOMPARE(s.relaxSteps, 0);
        QCOMPARE(s.damping, 3.0);
        r = fakeRow("hybrid-enhanced", 0.1, 0, 1, 1);
        r.snap = true;
        r.relaxSteps = 30;
        s = AccuracyPanel::cutSettingsForRow(r, base);
        QCOMPARE(s.method, CutMethod::Hybrid);
        QCOMPARE(s.triangulation, FaceTriangulation::Enhanced);
        QVERIFY(s.snap);
        QCOMPARE(s.relaxSteps, 30);
        r = fakeRow("hybrid-standard", 0.1, 0, 1, 1);
        s = AccuracyPanel::cutSettingsForRow(r, CutSettings{});
        QCOMPARE(s.triangulation, FaceTriangulation::Standard);
    }

    void coincidentPointsAreSpreadAndClickable() {
        // Issue 19: settings with the same cost and error piled up on one pixel. Spread, each
        // is drawn apart from the others, near its data position, and can be clicked.
        AccuracyChart chart;
        chart.resize(500, 360);
        std::vector<StudyRow> rows;
        for (int i = 0; i < 5; ++i)
            rows.push_back(fakeRow("hybrid-enhanced", 0.1 + 0.05 * i, 0.2, 20, 1));
        rows.push_back(fakeRow("subdivision", 0.1, 0.0, 4000, 4));
        chart.setRows(rows);
        for (int i = 0; i < 5; ++i) {
            QCOMPARE(chart.dataPosition(i), chart.dataPosition(0));
            const QPointF p = chart.pointPosition(i);
            const QPointF d = p - chart.dataPosition(i);
            QVERIFY(std::hypot(d.x(), d.y()) <= 12.0);
            for (int j = 0; j < i; ++j) {
                const QPointF q = p - chart.pointPosition(j);
                QVERIFY2(std::hypot(q.x(), q.y()) >= 8.0, qPrintable(QString("%1 %2").arg(i).arg(j)));
            }
            QCOMPARE(chart.rowAt(p), i);
        }
        QCOMPARE(chart.pointPosition(5), chart.dataPosition(5)); // alone: not moved
    }

    void dragZoomsAndDoubleClickShowsAll() {
        // Two clusters four decades apart: zooming into one spreads its points over the plot.
        AccuracyChart chart;
        chart.resize(500, 360);
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        std::vector<StudyRow> rows{fakeRow("hybrid-enhanced", 0.1, 0.20, 1000, 1),
                                   fakeRow("hybrid-enhanced", 0.2, 0.18, 1100, 1),
                                   fakeRow("hybrid-standard", 0.1, 0.19, 1200, 1),
                                   fakeRow("subdivision", 0.1, 0.0, 1e7, 4)};
        chart.setRows(rows);
        const auto spread = [&] { return std::abs(chart.pointPosition(2).x() - chart.pointPosition(0).x()); };
        const double before = spread();
        QVERIFY(!chart.isZoomed());
        // Drag a rectangle around the first three points, starting on empty space.
        QRectF box;
        for (int i = 0; i < 3; ++i)
            box = box.isNull() ? QRectF(chart.pointPosition(i), QSizeF(1, 1)) : box.united(QRectF(chart.pointPosition(i), QSizeF(1, 1)));
        box = box.adjusted(-20, -20, 20, 20).intersected(chart.plotRect().adjusted(1, 1, -1, -1));
        QCOMPARE(chart.rowAt(box.topLeft()), -1);
        QTest::mousePress(&chart, Qt::LeftButton, {}, box.topLeft().toPoint());
        QMouseEvent move(QEvent::MouseMove, box.center(), chart.mapToGlobal(box.center()), Qt::NoButton, Qt::LeftButton, {});
        QApplication::sendEvent(&chart, &move);
        QTest::mouseRelease(&chart, Qt::LeftButton, {}, box.bottomRight().toPoint());
        QVERIFY(chart.isZoomed());
        QVERIFY2(spread() > 5 * before, qPrintable(QString("%1 -> %2").arg(before).arg(spread())));
        for (int i = 0; i < 3; ++i)
            QVERIFY(chart.plotRect().contains(chart.pointPosition(i)));
        // The subdivision point, outside the zoom, is neither on the axes nor pickable.
        QVERIFY(!chart.plotRect().adjusted(-10, -10, 10, 10).contains(chart.pointPosition(3)));
        QCOMPARE(chart.rowAt(chart.pointPosition(3)), -1);
        QVERIFY(!chart.grab().isNull());
        // A click on empty space does not zoom; a double click shows all again.
        const QPoint empty = (chart.plotRect().topLeft() + QPointF(3, 30)).toPoint();
        QTest::mouseClick(&chart, Qt::LeftButton, {}, empty);
        QVERIFY(chart.isZoomed());
        QTest::mouseDClick(&chart, Qt::LeftButton, {}, empty);
        QVERIFY(!chart.isZoomed());
        QCOMPARE(spread(), before);
    }

    void costLabelsAreReadable() {
        const QLocale c(QLocale::English, QLocale::UnitedStates);
        QCOMPARE(AccuracyChart::costLabel(0, c), QString("1"));
        QCOMPARE(AccuracyChart::costLabel(std::log10(5.0), c), QString("5"));
        QCOMPARE(AccuracyChart::costLabel(3, c), QString("1,000"));
        QCOMPARE(AccuracyChart::costLabel(4 + std::log10(2.0), c), QString("20,000"));
        QCOMPARE(AccuracyChart::costLabel(-2, c), QString("0.01"));
        QCOMPARE(AccuracyChart::costLabel(6, c), QString::fromUtf8("10\u2076"));
        QCOMPARE(AccuracyChart::costLabel(7 + std::log10(2.0), c), QString::fromUtf8("2\u00d710\u2077"));
        QCOMPARE(AccuracyChart::costLabel(-5, c), QString::fromUtf8("10\u207b\u2075"));
        // Zoomed-in ticks are not all round.
        QCOMPARE(AccuracyChart::costLabel(std::log10(2.5), c), QString("2.5"));
        QCOMPARE(AccuracyChart::costLabel(std::log10(1.25e7), c), QString::fromUtf8("1.25\u00d710\u2077"));
        for (int k = -6; k <= 9; ++k)
            QVERIFY(!AccuracyChart::costLabel(k, c).contains('e'));
    }

    void panelFitsANarrowDock() {
        // Issue 19: in a dock a third of a 1280-pixel window wide, Cancel and Adopt were cut off.
        AccuracyPanel panel;
        QVERIFY2(panel.minimumSizeHint().width() <= 380, qPrintable(QString::number(panel.minimumSizeHint().width())));
        panel.resize(390, 600);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        for (const char* name : {"runStudy", "cancelStudy", "adoptSettings", "studyPreset", "costAxis"}) {
            QWidget* w = child<QWidget>(panel, name);
            const QRect inPanel(w->mapTo(&panel, QPoint(0, 0)), w->size());
            QVERIFY2(panel.rect().contains(inPanel), name);
        }
    }

    void chartGeometryFrontAndPainting() {
        AccuracyChart chart;
        chart.resize(500, 360);
        QVERIFY(!chart.grab().isNull()); // empty chart paints
        QCOMPARE(chart.rowAt(QPointF(250, 180)), -1);
        QCOMPARE(chart.pointPosition(0), QPointF(-1, -1));

        std::vector<StudyRow> rows{fakeRow("hybrid-enhanced", 0.1, 0.30, 10, 1),
                                   fakeRow("hybrid-enhanced", 0.2, 0.10, 20, 2),
                                   fakeRow("hybrid-enhanced", 0.3, 0.20, 30, 0.5),
                                   fakeRow("subdivision", 0.1, 0.0, 400, 4),
                                   fakeRow("hybrid-standard", 0.1, 0.25, 15, 1)};
        chart.setRows(rows);
        const std::vector<int> front = chart.paretoFront("hybrid-enhanced");
        QCOMPARE(front, std::vector<int>({0, 1})); // row 2 is dearer and worse than row 1
        QCOMPARE(chart.paretoFront("subdivision"), std::vector<int>({3}));
        QVERIFY(chart.paretoFront("none").empty());

        const QRectF plot = chart.plotRect();
        for (int i = 0; i < int(rows.size()); ++i) {
            const QPointF p = chart.pointPosition(i);
            QVERIFY(plot.adjusted(-1, -1, 1, 1).contains(p));
            QCOMPARE(chart.rowAt(p), i);
            QCOMPARE(chart.rowAt(p + QPointF(2, 1)), i);
            QVERIFY(chart.rowToolTip(i).contains("d = "));
        }
        QVERIFY(chart.pointPosition(0).x() < chart.pointPosition(1).x());
        QVERIFY(chart.pointPosition(1).y() > chart.pointPosition(0).y()); // lower error: lower down
        QCOMPARE(chart.rowAt(QPointF(plot.right() - 2, plot.top() + 2)), -1);
        QCOMPARE(chart.rowAt(chart.pointPosition(0) + QPointF(0, 20)), -1);
        QVERIFY(chart.rowToolTip(-1).isEmpty());

        // Painted offscreen: the points show in their method's colour.
        const QImage image = chart.grab().toImage();
        QVERIFY(!image.isNull());
        const QPoint p = chart.pointPosition(3).toPoint() * image.devicePixelRatio();
        const QColor c = image.pixelColor(p);
        QVERIFY2(c.red() > c.green() + 40, qPrintable(c.name())); // subdivision is red

        // Clicking selects and signals.
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        QSignalSpy clicked(&chart, &AccuracyChart::rowClicked);
        QTest::mouseClick(&chart, Qt::LeftButton, {}, chart.pointPosition(2).toPoint());
        QCOMPARE(clicked.count(), 1);
        QCOMPARE(clicked.first().first().toInt(), 2);
        QCOMPARE(chart.selectedRow(), 2);
        QTest::mouseClick(&chart, Qt::LeftButton, {}, QPoint(3, 3));
        QCOMPARE(clicked.count(), 1);

        // The cut-time axis orders the points by cut time.
        chart.setCostAxis(AccuracyChart::CostAxis::CutMs);
        QVERIFY(chart.pointPosition(2).x() < chart.pointPosition(0).x());
        QCOMPARE(chart.paretoFront("hybrid-enhanced"), std::vector<int>({2, 1}));
        QVERIFY(!chart.grab().isNull());
        chart.setRows({});
        QCOMPARE(chart.selectedRow(), -1);
    }
};

QTEST_MAIN(TestAccuracyPanel)
#include "test_accuracy_panel.moc"
