// CutPanel's mesh-improvement controls (step 7 of a cut, CutOptions::improve...), driven as an
// author drives them: the checkbox and the three factors edit the document's cut settings as
// undoable edits (the checkbox one step per click, a factor's consecutive changes one merged
// step), the document stays modified until undone, the panel follows undo and redo, the
// factors are disabled while the improvement is off, and no value outside CutLimits' ranges
// can be entered; a change of them re-derives the document's cuts. The preview shows what the
// improvement did and the resected chips, as a Tissue cut directly reports them.

#include "widgets/cut_panel.h"
#include "widgets/cut_preview.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include "core/mesh/stable_time_step.h"
#include "scenario/scenario_load.h"
#include "tests/widgets/sweep_fixtures.h"
#include "tests/widgets/tissue_compare.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLocale>
#include <QPushButton>
#include <QSignalSpy>
#include <QStyle>
#include <QStyleOptionButton>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <memory>

using namespace resect;
using resect::test::planeSweep;
using resect::test::tissueDifference;

namespace {

constexpr int kWaitMs = 120'000;

/// A document, its session, preview and cut panel (shown, offscreen), on `scenario`.
struct Scene {
    ScenarioDocument doc;
    TissueSession session{doc};
    CutPreview preview{doc, session};
    CutPanel panel{doc, session, preview};

    Scene(const QString& dir, Scenario scenario) {
        doc.setAutosaveDirectory(dir);
        doc.replace(std::move(scenario));
        panel.show();
        idle();
    }
    bool idle() { return preview.waitForIdle(kWaitMs); }
    QCheckBox* improve() { return panel.findChild<QCheckBox*>(QStringLiteral("improve")); }
    QDoubleSpinBox* box(const char* name) { return panel.findChild<QDoubleSpinBox*>(QLatin1String(name)); }
};

Scenario sample() {
    Scenario s;
    if (!ScenarioDocument::sampleScenario(QStringLiteral("polyp"), s))
        qFatal("no polyp sample");
    return s;
}

/// The bundled polyp resection without its strokes: the base of the stalk anchored, pieces
/// cut off it resected as rigid chips.
Scenario anchoredPolyp() {
    Scenario s;
    QString error;
    if (!ScenarioDocument::readScenario(QStringLiteral(RESECT_SOURCE_DIR "/resources/scenarios/polyp-resection.json"),
                                        s, &error))
        qFatal("%s", qPrintable(error));
    s.strokes.clear();
    s.simulation.resectedPieces = "rigid";
    return s;
}

SweepSurface surfaceOf(const SweepSpec& spec) {
    SweepSurface s;
    if (!SweepSurface::fromCurves(spec.curves, s).ok())
        qFatal("bad test sweep");
    return s;
}

QString number(double v) { return QLocale().toString(v, 'g', 3); }

/// Where a click toggles a check box: its indicator (the widget may be wider than its text).
QPoint indicatorCentre(QCheckBox* box) {
    QStyleOptionButton option;
    option.initFrom(box);
    return box->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, box).center();
}

} // namespace

class TestCutPanel : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void controlsShowTheDocumentsSettings() {
        Scene s(m_dir.path(), sample());
        QVERIFY(s.improve() && s.box("improveQuality") && s.box("improveShortEdge") && s.box("improveCoarsen"));
        const CutOptions defaults;
        QCOMPARE(s.improve()->isChecked(), defaults.improve);
        QCOMPARE(s.box("improveQuality")->value(), defaults.improveQuality);
        QCOMPARE(s.box("improveShortEdge")->value(), defaults.improveShortEdge);
        QCOMPARE(s.box("improveCoarsen")->value(), defaults.improveCoarsen);
        QCOMPARE(s.improve()->text(), QStringLiteral("Improve mesh after cut"));

        // A document with other values (as a file would bring them) is shown as it is.
        Scenario other = sample();
        other.cut.improve = false;
        other.cut.improveQuality = 2.25;
        other.cut.improveShortEdge = 0.35;
        other.cut.improveCoarsen = 0.8;
        s.doc.replace(other);
        QVERIFY(s.idle());
        QCOMPARE(s.improve()->isChecked(), false);
        QCOMPARE(s.box("improveQuality")->value(), 2.25);
        QCOMPARE(s.box("improveShortEdge")->value(), 0.35);
        QCOMPARE(s.box("improveCoarsen")->value(), 0.8);
        QVERIFY(!s.box("improveQuality")->isEnabled());
        QCOMPARE(s.doc.undoStack()->count(), 0); // showing a document edits nothing
    }

    void toggleIsAnUndoableEdit() {
        Scene s(m_dir.path(), sample());
        QCheckBox* improve = s.improve();
        QVERIFY(improve->isChecked());
        QVERIFY(!s.doc.isModified());
        QCOMPARE(s.session.current()->applied.options.improve, true);
        QSignalSpy settings(&s.doc, &ScenarioDocument::cutSettingsChanged);

        QTest::mouseClick(improve, Qt::LeftButton, {}, indicatorCentre(improve));
        QCOMPARE(s.doc.scenario().cut.improve, false);
        QCOMPARE(settings.count(), 1);
        QCOMPARE(s.doc.undoStack()->count(), 1);
        QVERIFY(s.doc.isModified());
        for (const char* name : {"improveQuality", "improveShortEdge", "improveCoarsen"})
            QVERIFY2(!s.box(name)->isEnabled(), name);
        // The tissue is derived again with the improvement off.
        QVERIFY(s.idle());
        QCOMPARE(s.session.current()->applied.options.improve, false);

        // Each click is its own step (a checkbox does not merge).
        QTest::mouseClick(improve, Qt::LeftButton, {}, indicatorCentre(improve));
        QCOMPARE(s.doc.scenario().cut.improve, true);
        QCOMPARE(s.doc.undoStack()->count(), 2);
        QVERIFY(s.box("improveQuality")->isEnabled());

        // Undo both: the document is clean again and the panel follows; redo one.
        s.doc.undoStack()->undo();
        QCOMPARE(s.doc.scenario().cut.improve, false);
        QVERIFY(!improve->isChecked());
        s.doc.undoStack()->undo();
        QCOMPARE(s.doc.scenario().cut.improve, true);
        QVERIFY(improve->isChecked());
        QVERIFY(!s.doc.isModified());
        s.doc.undoStack()->redo();
        QVERIFY(!improve->isChecked());
        QVERIFY(!s.box("improveCoarsen")->isEnabled());
        QVERIFY(s.doc.isModified());
        QCOMPARE(settings.count(), 5);
        QVERIFY(s.idle());
        QCOMPARE(s.session.current()->applied.options.improve, false);
    }

    // Regression: the improvement's settings were not among those sameCutOptions compares, so
    // a change of them alone kept the tissue cut with the old ones (nothing re-derived).
    void improvementSettingsReDeriveTheCuts_data() {
        QTest::addColumn<QString>("field");
        QTest::newRow("improve") << "improve";
        QTest::newRow("quality") << "improveQuality";
        QTest::newRow("short edge") << "improveShortEdge";
        QTest::newRow("coarsen") << "improveCoarsen";
    }
    void improvementSettingsReDeriveTheCuts() {
        QFETCH(QString, field);
        Scene s(m_dir.path(), sample());
        const SweepSpec sweep = planeSweep(s.session.base()->mesh(), 0.6, 1e-3);
        s.doc.addSweep(sweep);
        QVERIFY(s.idle());
        const auto before = s.session.current();
        QCOMPARE(before->cuts(), 1);

        CutOptions changed = before->applied.options;
        if (field == QLatin1String("improve")) {
            QTest::mouseClick(s.improve(), Qt::LeftButton, {}, indicatorCentre(s.improve()));
            changed.improve = false;
        } else {
            // Strict: every tet counts as bad, every edge as short (the upper limits).
            QDoubleSpinBox* box = s.box(field.toLatin1().constData());
            box->setValue(box->maximum());
            (field == QLatin1String("improveQuality")     ? changed.improveQuality
             : field == QLatin1String("improveShortEdge") ? changed.improveShortEdge
                                                           : changed.improveCoarsen) = box->maximum();
        }
        QVERIFY(sameCutOptions(changed, toCutOptions(s.doc.scenario().cut, s.doc.scenario().tissues[0].material)));
        QVERIFY(!sameCutOptions(changed, before->applied.options));
        QVERIFY(s.idle());
        const auto after = s.session.current();
        QVERIFY(after != before);
        QVERIFY(sameCutOptions(after->applied.options, changed));
        // The cut is made again with the new settings: as on a copy of the base directly.
        Tissue direct(s.session.base()->tissue);
        QVERIFY(direct.cut(surfaceOf(sweep), changed).ok());
        direct.updateSurface();
        QCOMPARE(tissueDifference(after->tissue, direct), QString());
        QVERIFY2(tissueDifference(after->tissue, before->tissue) != QString(),
                 "the setting changes nothing on this cut: the test proves nothing");
    }

    void factorEditsMergeAndUndo_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("first");
        QTest::addColumn<double>("second");
        QTest::newRow("quality") << "improveQuality" << 2.5 << 1.75;
        QTest::newRow("short edge") << "improveShortEdge" << 1.2 << 0.3;
        QTest::newRow("coarsen") << "improveCoarsen" << 0.25 << 0.75;
    }
    void factorEditsMergeAndUndo() {
        QFETCH(QString, name);
        QFETCH(double, first);
        QFETCH(double, second);
        Scene s(m_dir.path(), sample());
        QDoubleSpinBox* box = s.box(name.toLatin1().constData());
        const CutSettings before = s.doc.scenario().cut;
        const auto value = [&](const CutSettings& c) {
            return name == QLatin1String("improveQuality")     ? c.improveQuality
                   : name == QLatin1String("improveShortEdge") ? c.improveShortEdge
                                                                : c.improveCoarsen;
        };
        // Typed in as an author would, then changed again: one undo step.
        box->selectAll();
        QTest::keyClicks(box, QLocale().toString(first));
        QTest::keyClick(box, Qt::Key_Enter);
        QCOMPARE(value(s.doc.scenario().cut), first);
        box->setValue(second);
        QCOMPARE(value(s.doc.scenario().cut), second);
        QCOMPARE(s.doc.undoStack()->count(), 1);
        QVERIFY(s.doc.isModified());
        // Only this field changed.
        CutSettings expected = before;
        (name == QLatin1String("improveQuality")     ? expected.improveQuality
         : name == QLatin1String("improveShortEdge") ? expected.improveShortEdge
                                                      : expected.improveCoarsen) = second;
        QVERIFY(s.doc.scenario().cut == expected);
        QVERIFY(s.idle());
        QCOMPARE(s.session.error(), QString());

        s.doc.undoStack()->undo();
        QVERIFY(s.doc.scenario().cut == before);
        QCOMPARE(box->value(), value(before));
        QVERIFY(!s.doc.isModified());
        s.doc.undoStack()->redo();
        QCOMPARE(box->value(), second);
    }

    void outOfRangeValuesAreImpossible_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("limit");
        QTest::newRow("quality") << "improveQuality" << CutLimits::kMaxImproveQuality;
        QTest::newRow("short edge") << "improveShortEdge" << CutLimits::kMaxImproveShortEdge;
        QTest::newRow("coarsen") << "improveCoarsen" << CutLimits::kMaxImproveCoarsen;
    }
    void outOfRangeValuesAreImpossible() {
        QFETCH(QString, name);
        QFETCH(double, limit);
        Scene s(m_dir.path(), sample());
        QDoubleSpinBox* box = s.box(name.toLatin1().constData());
        QCOMPARE(box->minimum(), 0.0);
        QCOMPARE(box->maximum(), limit);
        // The tooltip says what the factor means and its range, from CutLimits.
        QVERIFY2(box->toolTip().contains(QStringLiteral("from 0 to ") + number(limit)), qPrintable(box->toolTip()));
        QVERIFY2(box->toolTip().contains(QStringLiteral("0: off")), qPrintable(box->toolTip()));

        const auto inRange = [&] {
            const CutSettings& c = s.doc.scenario().cut;
            const double v = name == QLatin1String("improveQuality")     ? c.improveQuality
                             : name == QLatin1String("improveShortEdge") ? c.improveShortEdge
                                                                          : c.improveCoarsen;
            return v >= 0 && v <= limit;
        };
        box->setValue(10 * limit + 1);
        QCOMPARE(box->value(), limit);
        QVERIFY(inRange());
        box->setValue(-1);
        QCOMPARE(box->value(), 0.0);
        QVERIFY(inRange());
        // Typing a number beyond the limit or a minus sign gets nowhere near the document.
        for (const QString& typed : {QStringLiteral("99"), QStringLiteral("-0.5"), QLocale().toString(limit + 0.5)}) {
            box->selectAll();
            QTest::keyClicks(box, typed);
            QTest::keyClick(box, Qt::Key_Enter);
            QVERIFY2(box->value() >= 0 && box->value() <= limit, qPrintable(typed));
            QVERIFY2(inRange(), qPrintable(typed));
        }
        // Whatever was entered, the document is one a file could hold.
        ScenarioDiagnostics diag;
        QVERIFY2(validateScenario(s.doc.scenario(), diag).ok(), diag.format("doc").c_str());
        QVERIFY(s.idle());
        QCOMPARE(s.session.error(), QString());
    }

    // The preview reports the improvement and the chips of the pending cut as Tissue::cut does
    // for the same cut on a copy of the current tissue.
    void previewShowsTheImprovementAndTheChips_data() {
        QTest::addColumn<bool>("improve");
        QTest::newRow("improvement on") << true;
        QTest::newRow("improvement off") << false;
    }
    void previewShowsTheImprovementAndTheChips() {
        QFETCH(bool, improve);
        Scenario scenario = anchoredPolyp();
        scenario.cut.improve = improve;
        Scene s(m_dir.path(), scenario);
        const auto current = s.session.current();
        QVERIFY(current);
        QCOMPARE(s.panel.previewValue(QStringLiteral("chips")), QString());

        // Through the head, well above the anchored base: the head comes off as a chip.
        const SweepSpec sweep = planeSweep(current->mesh(), 0.7, 1e-3);
        s.preview.setPendingSweep(sweep);
        QVERIFY(s.idle());
        QVERIFY2(s.preview.error().isEmpty(), qPrintable(s.preview.error()));
        const auto preview = s.preview.preview();
        QVERIFY(preview);

        Tissue direct(current->tissue);
        TissueCut cut;
        QVERIFY(direct.cut(surfaceOf(sweep), current->applied.options, &cut).ok());
        direct.updateSurface();
        QCOMPARE(tissueDifference(preview->tissue, direct), QString());
        QCOMPARE(cut.resectedPieces, 1);
        if (improve)
            QVERIFY(cut.collapsedEdges + cut.smoothedNodes > 0);
        else
            QCOMPARE(cut.collapsedEdges + cut.smoothedNodes + cut.removedTets, 0);

        QCOMPARE(s.panel.previewValue(QStringLiteral("collapsed_edges")), QString::number(cut.collapsedEdges));
        QCOMPARE(s.panel.previewValue(QStringLiteral("smoothed_nodes")), QString::number(cut.smoothedNodes));
        QCOMPARE(s.panel.previewValue(QStringLiteral("removed_tets")), QString::number(cut.removedTets));
        QCOMPARE(s.panel.previewValue(QStringLiteral("chips")), QStringLiteral("0 → 1"));
        QCOMPARE(s.panel.previewValue(QStringLiteral("resected_volume")),
                 QStringLiteral("0 → ") + number(cut.resectedVolume));
        QCOMPARE(s.panel.previewValue(QStringLiteral("resected_mass")),
                 QStringLiteral("0 → ") + number(cut.resectedMass));
        QVERIFY(cut.resectedVolume > 0 && cut.resectedMass > 0);
        QVERIFY(!s.panel.previewValue(QStringLiteral("improve_ms")).isEmpty());
        // Tets: the cut's added ones less those the collapses removed.
        QCOMPARE(s.panel.previewValue(QStringLiteral("tets")),
                 QStringLiteral("%1 → %2").arg(current->mesh().tetCount()).arg(direct.mesh().tetCount()));
    }

    // Issue 19 item 4: a preview that divides the stable time step by more than
    // kStepDropWarning warns in the preview area, and the tets that limit the step are one
    // click away; a preview that does not, does not warn.
    void aCutThatDropsTheStableStepWarns_data() {
        QTest::addColumn<bool>("subdivision");
        QTest::addColumn<double>("height");
        QTest::addColumn<bool>("warns");
        // Subdivision without the improvement step leaves slivers (README: up to 5e13x).
        QTest::newRow("subdivision, slivers") << true << 0.7 << true;
        // The hybrid cut with its defaults keeps the step.
        QTest::newRow("hybrid") << false << 0.6 << false;
    }
    void aCutThatDropsTheStableStepWarns() {
        QFETCH(bool, subdivision);
        QFETCH(double, height);
        QFETCH(bool, warns);
        Scene s(m_dir.path(), sample());
        if (subdivision) {
            s.doc.setMethod(CutMethod::Subdivision);
            s.doc.setImprove(false);
            QVERIFY(s.idle());
        }
        QSignalSpy inspect(&s.panel, &CutPanel::inspectTetRequested);
        s.preview.setPendingSweep(planeSweep(s.session.base()->mesh(), height));
        QVERIFY(s.idle());
        const auto current = s.session.current();
        const auto preview = s.preview.preview();
        QVERIFY(current && preview);
        // The condition, measured independently of the panel.
        const double drop = current->stableDt / preview->stableDt;
        QVERIFY2((drop > CutPreview::kStepDropWarning) == warns, qPrintable(QString::number(drop)));
        auto* frame = s.panel.findChild<QWidget*>(QStringLiteral("previewWarning"));
        auto* button = s.panel.findChild<QPushButton*>(QStringLiteral("inspectWorstTet"));
        QVERIFY(frame && button);
        if (!warns) {
            QVERIFY2(s.panel.warning().isEmpty(), qPrintable(s.panel.warning()));
            QVERIFY(frame->isHidden());
            QVERIFY(preview->stepLimitingTets.empty());
            return;
        }
        QVERIFY(frame->isVisible());
        QVERIFY2(s.panel.warning().contains(QStringLiteral("times smaller")), qPrintable(s.panel.warning()));
        // The worst tets are those whose own step is smallest, worst first.
        const std::vector<double> steps = tetStableTimeSteps(preview->mesh(), preview->tissue.material());
        const auto& worst = preview->stepLimitingTets;
        QCOMPARE(int(worst.size()), CutPreview::kStepLimitingTets);
        QCOMPARE(worst.front(), int(std::min_element(steps.begin(), steps.end()) - steps.begin()));
        for (std::size_t i = 1; i < worst.size(); ++i)
            QVERIFY(steps[worst[i - 1]] <= steps[worst[i]]);
        // The worst tet limits the step: its own step is within a small factor of the mesh's.
        QVERIFY2(steps[worst.front()] < 5 * preview->stableDt,
                 qPrintable(QString("%1 vs %2").arg(steps[worst.front()]).arg(preview->stableDt)));
        QVERIFY(s.panel.warning().contains(QString::number(worst.front())));
        // One click: the worst; the next click: the next.
        QVERIFY(button->isEnabled());
        QTest::mouseClick(button, Qt::LeftButton);
        QCOMPARE(inspect.count(), 1);
        QCOMPARE(inspect.last().first().toInt(), worst[0]);
        QTest::mouseClick(button, Qt::LeftButton);
        QCOMPARE(inspect.last().first().toInt(), worst[1]);
        // Discarding the cut takes the warning away.
        s.preview.discard();
        QVERIFY(s.panel.warning().isEmpty());
        QVERIFY(frame->isHidden());
    }

    // Snapping that refuses every cut node warns too (the hybrid cut then keeps its cut nodes
    // where the sweep crossed the edges).
    void snappingThatRefusesEveryNodeWarns() {
        Scene s(m_dir.path(), sample());
        s.preview.setPendingSweep(planeSweep(s.session.base()->mesh(), 0.3));
        QVERIFY(s.idle());
        const auto preview = s.preview.preview();
        QVERIFY(preview);
        const CutStats& c = preview->cutStats;
        QVERIFY2(c.refusedSnaps > 0 && c.snappedNodes == 0,
                 qPrintable(QString("%1 snapped, %2 refused").arg(c.snappedNodes).arg(c.refusedSnaps)));
        QVERIFY(s.preview.warnings().snapsAllRefused);
        QVERIFY2(s.panel.warning().contains(QStringLiteral("Snapping refused every cut node")),
                 qPrintable(s.panel.warning()));
        QVERIFY(!preview->stepLimitingTets.empty());
        // Without snapping there is nothing to refuse: no warning (the step is kept).
        s.doc.setSnap(false);
        QVERIFY(s.idle());
        QVERIFY(!s.preview.warnings().snapsAllRefused);
        QVERIFY(!s.preview.warnings().stepDropped);
        QVERIFY2(s.panel.warning().isEmpty(), qPrintable(s.panel.warning()));
    }
};

QTEST_MAIN(TestCutPanel)
#include "test_cut_panel.moc"
