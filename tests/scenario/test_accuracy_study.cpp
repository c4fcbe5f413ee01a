// The benchmark study (scenario/accuracy_study.h) on its tiny configuration: every code path
// of `resect bench` runs, and the rows say what the methods promise. Nothing here is timed:
// times are only checked to be finite and non-negative.
#include "scenario/accuracy_study.h"

#include "core/embed/embedded_surface.h"
#include "core/mesh/box_mesh.h"
#include "core/sweep/sweep_surface.h"

#include <QTest>

#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

using namespace resect;

namespace {

/// Number of comma-separated cells of every line; -1 if the lines differ.
int cellsPerLine(const std::string& csv, int& lines) {
    std::stringstream ss(csv);
    std::string line;
    int cells = -2;
    lines = 0;
    while (std::getline(ss, line)) {
        ++lines;
        const int n = 1 + static_cast<int>(std::count(line.begin(), line.end(), ','));
        if (cells == -2)
            cells = n;
        else if (n != cells)
            return -1;
    }
    return cells;
}

bool finiteNonNegative(double v) { return std::isfinite(v) && v >= 0; }

} // namespace

class TestAccuracyStudy : public QObject {
    Q_OBJECT
private:
    std::vector<StudyRow> m_rows;
    std::vector<ScalingRow> m_scaling;
    StudyConfig m_config = tinyConfig();

private slots:
    void initTestCase() {
        int calls = 0;
        double last = -1;
        bool monotone = true;
        const Status s = runAccuracyStudy(m_config, m_rows, [&](double f, const std::string&) {
            ++calls;
            monotone = monotone && f >= last && f <= 1;
            last = f;
            return true;
        });
        QVERIFY2(s.ok(), s.message().c_str());
        QVERIFY(calls > 0);
        QVERIFY(monotone);
        QCOMPARE(last, 1.0);
        const Status t = runScalingStudy(m_config, m_scaling);
        QVERIFY2(t.ok(), t.message().c_str());
    }

    void rowCountIsTheCrossProduct() {
        // subdivision once per d; each hybrid method for every d, snap option and relaxation
        const std::size_t perMesh =
            m_config.dValues.size() *
            (1 + 2 * m_config.snapOptions.size() * m_config.relaxSteps.size());
        QCOMPARE(m_rows.size(), m_config.meshes.size() * perMesh);
    }

    void everyColumnFiniteAndSensible() {
        for (const StudyRow& r : m_rows) {
            const QByteArray where = QString("%1 %2 d=%3 snap=%4 relax=%5")
                                         .arg(QString::fromStdString(r.method)).arg(QString::fromStdString(r.mesh))
                                         .arg(r.d).arg(r.snap).arg(r.relaxSteps).toUtf8();
            QVERIFY2(r.meshTets > 100, where);
            QVERIFY2(r.tets >= r.meshTets, where);  // a cut never removes tets
            QCOMPARE(r.addedTets, r.tets - r.meshTets);
            QVERIFY2(r.cutSurfaceNodes > 0, where);
            QVERIFY2(finiteNonNegative(r.sweepErrorMax) && finiteNonNegative(r.sweepErrorMean), where);
            QVERIFY2(r.sweepErrorMean <= r.sweepErrorMax + 1e-12, where);
            QVERIFY2(r.minRadiusRatio > 0 && r.minRadiusRatio <= 1, where);  // nothing inverted
            QVERIFY2(r.meshMinRadiusRatio > 0 && r.meshMinRadiusRatio <= 1, where);
            QVERIFY2(std::isfinite(r.stableDt) && r.stableDt > 0, where);
            QVERIFY2(finiteNonNegative(r.cutMs) && finiteNonNegative(r.cutMsMin) && r.cutMsMin <= r.cutMs, where);
            QVERIFY2(finiteNonNegative(r.surfaceMs) && finiteNonNegative(r.totalMs), where);
            QVERIFY2(r.surfaceTriangles > 500, where);
            QVERIFY2(std::isfinite(r.simMsPerStep) && r.simMsPerStep > 0, where);
            QVERIFY2(std::abs(r.simMsPerSecond - r.simMsPerStep / r.stableDt) <= 1e-9 * r.simMsPerSecond, where);
        }
    }

    void subdivisionCutsOnTheSweepAndAddsTets() {
        int seen = 0;
        for (const StudyRow& r : m_rows)
            if (r.method == "subdivision") {
                ++seen;
                QVERIFY2(r.sweepErrorMax < 1e-6, qPrintable(QString::number(r.sweepErrorMax)));
                QVERIFY(r.tets > r.meshTets);
                QCOMPARE(r.cutNodes, 0);
                QVERIFY(!r.snap);
                QCOMPARE(r.relaxSteps, 0);
            }
        QCOMPARE(seen, int(m_config.dValues.size()));
    }

    void hybridCutNodesWithinD() {
        for (const StudyRow& r : m_rows) {
            if (r.method == "subdivision")
                continue;
            // Unsnapped cut nodes sit at most d mean edges from the sweep (relaxation moves only
            // nodes on the sweep within it and interior nodes, never a cut node off it).
            if (!r.snap)
                QVERIFY2(r.sweepErrorMax <= r.d + 1e-9,
                         qPrintable(QString("%1 d=%2 relax=%3: %4").arg(QString::fromStdString(r.method))
                                        .arg(r.d).arg(r.relaxSteps).arg(r.sweepErrorMax)));
            if (r.d == 0)
                QVERIFY2(r.sweepErrorMax < 1e-6, qPrintable(QString::number(r.sweepErrorMax)));
        }
    }

    void snappingBringsTheCutOntoTheSweep() {
        std::map<std::tuple<std::string, double, int>, const StudyRow*> off;
        for (const StudyRow& r : m_rows)
            if (r.method != "subdivision" && !r.snap)
                off[{r.method, r.d, r.relaxSteps}] = &r;
        int compared = 0;
        for (const StudyRow& r : m_rows) {
            if (r.method == "subdivision" || !r.snap || r.d == 0)
                continue;
            const StudyRow* o = off.at({r.method, r.d, r.relaxSteps});
            QVERIFY(r.snappedNodes > 0);
            QVERIFY(o->cutNodes > 0 && o->sweepErrorMean > 0);
            // The mean includes the split points (on the sweep either way) and refused snaps.
            QVERIFY2(r.sweepErrorMean < o->sweepErrorMean,
                     qPrintable(QString("%1 d=%2: snapped mean %3, unsnapped %4").arg(QString::fromStdString(r.method))
                                    .arg(r.d).arg(r.sweepErrorMean).arg(o->sweepErrorMean)));
            QVERIFY(r.sweepErrorMax <= r.d + 1e-9);  // refused snaps stay where they were
            ++compared;
        }
        QVERIFY(compared > 0);
    }

    void hybridAddsFewerTetsThanSubdivision() {
        int subdivisionTets = 0;
        for (const StudyRow& r : m_rows)
            if (r.method == "subdivision")
                subdivisionTets = r.tets;
        for (const StudyRow& r : m_rows)
            if (r.method == "hybrid-enhanced" && r.d >= 0.2)
                QVERIFY(r.tets < subdivisionTets);
    }

    void scalingRows() {
        QCOMPARE(m_scaling.size(), m_config.scalingSizes.size());
        for (const ScalingRow& r : m_scaling) {
            QVERIFY(r.meshTets > 0);
            QVERIFY(r.touchedTets > 0 && r.touchedTets < r.meshTets);
            QVERIFY(r.addedTets > 0);
            QVERIFY(finiteNonNegative(r.cutMs) && finiteNonNegative(r.usPerTouchedTet));
            for (double v : {r.stepNsPerTet1, r.stepNsPerTet2, r.stepNsPerTetMin1, r.stepNsPerTetMin2})
                QVERIFY(std::isfinite(v) && v > 0);
            QVERIFY(r.stepNsPerTetMin1 <= r.stepNsPerTet1 && r.stepNsPerTetMin2 <= r.stepNsPerTet2);
            QVERIFY(r.surfaceVertices > 0);
            QVERIFY(finiteNonNegative(r.surfaceUpdateMs) && finiteNonNegative(r.surfaceNsPerVertex));
        }
        // The same local cut on every mesh: the same tets touched.
        QCOMPARE(m_scaling.front().touchedTets, m_scaling.back().touchedTets);
        QVERIFY(m_scaling.front().meshTets < m_scaling.back().meshTets);
    }

    void csvHasEveryRowAndTheIssuesColumns() {
        const std::string a = accuracyCsv(m_rows);
        int lines = 0;
        QVERIFY(cellsPerLine(a, lines) > 10);
        QCOMPARE(lines, int(m_rows.size()) + 1);
        const std::string header = a.substr(0, a.find('\n'));
        for (const char* column : {"method", "d", "snap", "relax_steps", "sweep_error_max", "sweep_error_mean", "tets",
                                   "min_radius_ratio", "stable_dt", "cut_ms", "sim_ms_per_second"})
            QVERIFY2(("," + header + ",").find(std::string(",") + column + ",") != std::string::npos, column);
        const std::string s = scalingCsv(m_scaling);
        QVERIFY(cellsPerLine(s, lines) > 5);
        QCOMPARE(lines, int(m_scaling.size()) + 1);
        const std::string sh = s.substr(0, s.find('\n'));
        for (const char* column : {"mesh_tets", "touched_tets", "cut_ms", "step_ns_per_tet_1t", "step_ns_per_tet_2t",
                                   "surface_vertices", "surface_update_ms"})
            QVERIFY2(("," + sh + ",").find(std::string(",") + column + ",") != std::string::npos, column);
    }

    void targetsAreEvaluated() {
        const std::vector<TargetCheck> checks = evaluateTargets(m_rows, m_scaling);
        QCOMPARE(int(checks.size()), 7);  // 6 from the scaling study, the paper's case on the myoma
        for (const TargetCheck& c : checks) {
            QVERIFY2(std::isfinite(c.value) && c.value > 0, c.name.c_str());
            QCOMPARE(c.met, c.value <= c.limit);
        }
        const std::string md = targetsMarkdown(checks);
        QVERIFY(md.find("paper's case, myoma") != std::string::npos);
        // The myoma's deeper cut has its own limit (issue 20); the cut per touched tet is
        // reported with and without the improvement step.
        for (const TargetCheck& c : checks) {
            if (c.name.find("paper's case, myoma") != std::string::npos)
                QCOMPARE(c.limit, 3.0);
            if (c.name.find("paper's case, polyp") != std::string::npos)
                QCOMPARE(c.limit, 1.0);
        }
        QVERIFY(md.find("without the improvement step") != std::string::npos);
        QVERIFY(md.find("with the improvement step") != std::string::npos);
    }

    void cancelStopsWithAnError() {
        int calls = 0;
        std::vector<StudyRow> rows;
        const Status s = runAccuracyStudy(m_config, rows, [&](double, const std::string&) { return ++calls < 4; });
        QVERIFY(!s.ok());
        QCOMPARE(QString::fromStdString(s.message()), QString("cancelled"));
        QVERIFY(rows.size() < m_rows.size());
        std::vector<ScalingRow> scaling;
        const Status t = runScalingStudy(m_config, scaling, [](double, const std::string&) { return false; });
        QVERIFY(!t.ok());
        QCOMPARE(QString::fromStdString(t.message()), QString("cancelled"));
        QVERIFY(scaling.empty());
    }

    void studyOnAGivenMeshAndSweep() {
        // runAccuracyStudyOn (the studio's open scenario): a 4^3 box cut through by a slanted
        // plane, with and without an embedded surface (the myoma scaled into the box).
        const int n = 4;
        const TetMesh box = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(n), n, n, n);
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromStartEnd({Vec3(-1, -1, 1.63), Vec3(n + 1, -1, 1.71)},
                                           {Vec3(-1, n + 1, 1.79), Vec3(n + 1, n + 1, 1.87)}, sweep)
                    .ok());
        StudyConfig c = m_config;
        c.dValues = {0.0, 0.3};
        c.meshes.clear();  // ignored
        std::vector<StudyRow> rows;
        double last = -1;
        Status s = runAccuracyStudyOn(box, sweep, "box", c, rows, [&](double f, const std::string&) {
            last = f;
            return true;
        });
        QVERIFY2(s.ok(), s.message().c_str());
        QCOMPARE(last, 1.0);
        QCOMPARE(rows.size(), c.dValues.size() * (1 + 2 * c.snapOptions.size() * c.relaxSteps.size()));
        for (const StudyRow& r : rows) {
            QCOMPARE(QString::fromStdString(r.mesh), QString("box"));
            QCOMPARE(r.meshTets, box.tetCount());
            QVERIFY(r.tets >= r.meshTets && r.cutSurfaceNodes > 0);
            QCOMPARE(r.surfaceTriangles, 0);
            QVERIFY(std::isfinite(r.stableDt) && r.stableDt > 0 && r.simMsPerSecond > 0);
            if (r.method == "subdivision" || r.d == 0)
                QVERIFY2(r.sweepErrorMax < 1e-6, qPrintable(QString::number(r.sweepErrorMax)));
            else if (!r.snap)
                QVERIFY(r.sweepErrorMax <= r.d + 1e-9);
        }

        TriangleSurface inner = sampleSurface(Sample::Myoma, 0.01);
        const auto [lo, hi] = boundingBox(inner.positions);
        for (Vec3& p : inner.positions)
            p = Vec3::Constant(0.5 * n) + (0.8 * n / (hi - lo).maxCoeff()) * (p - 0.5 * (lo + hi));
        EmbeddedSurface embedded;
        QVERIFY(embedded.bind(box, inner).ok());
        s = runAccuracyStudyOn(box, sweep, "box", c, rows, {}, &embedded);
        QVERIFY2(s.ok(), s.message().c_str());
        for (const StudyRow& r : rows)
            QCOMPARE(r.surfaceTriangles, int(inner.triangles.size()));

        s = runAccuracyStudyOn(box, sweep, "box", c, rows, [](double, const std::string&) { return false; });
        QCOMPARE(QString::fromStdString(s.message()), QString("cancelled"));
        QVERIFY(rows.empty());
        c.dValues = {0.9};
        QVERIFY(!runAccuracyStudyOn(box, sweep, "box", c, rows).ok());
    }

    void badConfigurationIsRefused() {
        StudyConfig c = m_config;
        c.dValues = {0.7};
        std::vector<StudyRow> rows;
        QVERIFY(!runAccuracyStudy(c, rows).ok());
        c = m_config;
        c.repeats = 0;
        QVERIFY(!runAccuracyStudy(c, rows).ok());
        c = m_config;
        c.scalingSizes = {3};
        std::vector<ScalingRow> scaling;
        QVERIFY(!runScalingStudy(c, scaling).ok());
    }

    void configurationsCoverTheIssue() {
        for (const StudyConfig& c : {quickConfig(), fullConfig()}) {
            QCOMPARE(int(c.meshes.size()), 3);
            QCOMPARE(int(c.methods.size()), 3);
            QVERIFY(c.dValues.size() >= 6 && c.dValues.front() == 0 && c.dValues.back() == 0.5);
            QCOMPARE(int(c.snapOptions.size()), 2);
            QCOMPARE(c.relaxSteps, std::vector<int>({0, 10, 30}));
            QVERIFY(c.scalingSizes.front() <= 10000 && c.scalingSizes.back() >= 1000000);
        }
    }
};

QTEST_GUILESS_MAIN(TestAccuracyStudy)
#include "test_accuracy_study.moc"
