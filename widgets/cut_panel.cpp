#include "widgets/cut_panel.h"

#include "widgets/cut_preview.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFrame>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

namespace resect {

namespace {

QDoubleSpinBox* numberBox(const QString& name, double min, double max, double step, int decimals) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(name);
    box->setRange(min, max);
    box->setSingleStep(step);
    box->setDecimals(decimals);
    box->setKeyboardTracking(false);
    return box;
}

QString number(double v, int precision = 3) { return QLocale().toString(v, 'g', precision); }

QString beforeAfter(const QString& before, const QString& after) {
    return CutPanel::tr("%1 → %2").arg(before, after);
}

} // namespace

CutPanel::CutPanel(ScenarioDocument& document, TissueSession& session, CutPreview& preview, QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session), m_preview(preview) {
    setObjectName(QStringLiteral("cutPanel"));
    auto* layout = new QVBoxLayout(this);
    m_notice = new QLabel(this);
    m_notice->setObjectName(QStringLiteral("cutNotice"));
    m_notice->setWordWrap(true);
    m_notice->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notice->setStyleSheet(QStringLiteral("QLabel { color: #a40000; font-weight: bold; }"));
    m_notice->hide();
    layout->addWidget(m_notice);

    auto* settings = new QGroupBox(tr("Method"), this);
    auto* form = new QFormLayout(settings);
    m_method = new QComboBox;
    m_method->setObjectName(QStringLiteral("method"));
    m_method->addItem(tr("Hybrid"), int(CutMethod::Hybrid));
    m_method->addItem(tr("Subdivision"), int(CutMethod::Subdivision));
    form->addRow(tr("Cutting method"), m_method);
    m_triangulation = new QComboBox;
    m_triangulation->setObjectName(QStringLiteral("triangulation"));
    m_triangulation->addItem(tr("Enhanced (symmetric)"), int(FaceTriangulation::Enhanced));
    m_triangulation->addItem(tr("Standard"), int(FaceTriangulation::Standard));
    form->addRow(tr("Face triangulation"), m_triangulation);
    m_d = numberBox(QStringLiteral("d"), 0.0, CutLimits::kMaxD, 0.01, 3);
    m_d->setToolTip(tr("Cut-node threshold d as a fraction of the mean edge length (the paper: 0.2)"));
    form->addRow(tr("Threshold d"), m_d);
    m_snap = new QCheckBox(tr("Snap cut nodes onto the sweep"));
    m_snap->setObjectName(QStringLiteral("snap"));
    form->addRow(QString(), m_snap);
    m_relaxSteps = new QSpinBox;
    m_relaxSteps->setObjectName(QStringLiteral("relaxSteps"));
    m_relaxSteps->setRange(0, CutLimits::kMaxRelaxSteps);
    m_relaxSteps->setKeyboardTracking(false);
    form->addRow(tr("Relaxation steps"), m_relaxSteps);
    m_wSpring = numberBox(QStringLiteral("wSpring"), 0.0, CutLimits::kMaxRelaxWeight, 0.1, 3);
    form->addRow(tr("Spring weight"), m_wSpring);
    m_wParticle = numberBox(QStringLiteral("wParticle"), 0.0, CutLimits::kMaxRelaxWeight, 0.05, 3);
    form->addRow(tr("Particle weight"), m_wParticle);
    m_relaxDamping = numberBox(QStringLiteral("relaxDamping"), 0.001, CutLimits::kMaxRelaxDamping, 1.0, 3);
    form->addRow(tr("Relaxation damping"), m_relaxDamping);
    m_rings = new QSpinBox;
    m_rings->setObjectName(QStringLiteral("rings"));
    m_rings->setRange(1, CutLimits::kMaxRelaxRings);
    form->addRow(tr("Relaxation rings"), m_rings);
    layout->addWidget(settings);

    // Step 7 of a cut (Tissue::cut, core/cut/improve_mesh.h): the ranges are CutLimits'.
    auto* improvement = new QGroupBox(tr("Mesh improvement"), this);
    auto* improveForm = new QFormLayout(improvement);
    m_improve = new QCheckBox(tr("Improve mesh after cut"));
    m_improve->setObjectName(QStringLiteral("improve"));
    m_improve->setToolTip(tr("After every cut, improve the tets around it: collapse short edges and "
                             "move nodes of bad tets, measured against the tissue as created"));
    improveForm->addRow(QString(), m_improve);
    m_improveQuality = numberBox(QStringLiteral("improveQuality"), 0.0, CutLimits::kMaxImproveQuality, 0.05, 2);
    m_improveQuality->setToolTip(
        tr("Tets whose radius ratio is below this factor times the worst of the tissue as created "
           "are improved (0: off; from 0 to %1)")
            .arg(number(CutLimits::kMaxImproveQuality)));
    improveForm->addRow(tr("Quality factor"), m_improveQuality);
    m_improveShortEdge = numberBox(QStringLiteral("improveShortEdge"), 0.0, CutLimits::kMaxImproveShortEdge, 0.05, 2);
    m_improveShortEdge->setToolTip(
        tr("Edges shorter than this factor times the shortest edge of the tissue as created are "
           "collapsed (0: off; from 0 to %1)")
            .arg(number(CutLimits::kMaxImproveShortEdge)));
    improveForm->addRow(tr("Short-edge factor"), m_improveShortEdge);
    m_improveCoarsen = numberBox(QStringLiteral("improveCoarsen"), 0.0, CutLimits::kMaxImproveCoarsen, 0.05, 2);
    m_improveCoarsen->setToolTip(
        tr("Edges shorter than this factor times the mean edge length (the unit of d) are "
           "collapsed where quality allows, so that repeated cuts do not keep adding tets (0: off; "
           "from 0 to %1)")
            .arg(number(CutLimits::kMaxImproveCoarsen)));
    improveForm->addRow(tr("Coarsening factor"), m_improveCoarsen);
    layout->addWidget(improvement);

    auto* previewBox = new QGroupBox(tr("Preview"), this);
    auto* previewForm = new QFormLayout(previewBox);
    m_previewStatus = new QLabel;
    m_previewStatus->setObjectName(QStringLiteral("previewStatus"));
    m_previewStatus->setWordWrap(true);
    previewForm->addRow(m_previewStatus);
    m_warning = new QFrame;
    m_warning->setObjectName(QStringLiteral("previewWarning"));
    m_warning->setStyleSheet(QStringLiteral("QFrame#previewWarning { background: #fff3cd; border: 1px solid #c09000; }"));
    auto* warningLayout = new QVBoxLayout(m_warning);
    m_warningText = new QLabel;
    m_warningText->setObjectName(QStringLiteral("previewWarningText"));
    m_warningText->setWordWrap(true);
    m_warningText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_warningText->setStyleSheet(QStringLiteral("QLabel { color: #7a4a00; }"));
    warningLayout->addWidget(m_warningText);
    m_inspectWorst = new QPushButton(tr("Inspect the worst tet"));
    m_inspectWorst->setObjectName(QStringLiteral("inspectWorstTet"));
    m_inspectWorst->setToolTip(tr("Shows the tet that limits the time step most in the quality dock's tet "
                                  "inspector; click again for the next"));
    warningLayout->addWidget(m_inspectWorst, 0, Qt::AlignLeft);
    m_warning->hide();
    previewForm->addRow(m_warning);
    addValue(previewForm, QStringLiteral("tets"), tr("Tets"));
    addValue(previewForm, QStringLiteral("added_tets"), tr("Added tets"));
    addValue(previewForm, QStringLiteral("cut_edges"), tr("Cut edges"));
    addValue(previewForm, QStringLiteral("cut_nodes"), tr("Cut nodes"));
    addValue(previewForm, QStringLiteral("snapped_nodes"), tr("Snapped nodes"));
    addValue(previewForm, QStringLiteral("decomposed_tets"), tr("Decomposed tets"));
    addValue(previewForm, QStringLiteral("separated_tets"), tr("Separated tets"));
    addValue(previewForm, QStringLiteral("collapsed_edges"), tr("Collapsed edges"));
    addValue(previewForm, QStringLiteral("smoothed_nodes"), tr("Smoothed nodes"));
    addValue(previewForm, QStringLiteral("removed_tets"), tr("Removed tets"));
    addValue(previewForm, QStringLiteral("pieces"), tr("Pieces"));
    addValue(previewForm, QStringLiteral("chips"), tr("Resected chips"));
    addValue(previewForm, QStringLiteral("resected_volume"), tr("Resected volume (mm³)"));
    addValue(previewForm, QStringLiteral("resected_mass"), tr("Resected mass (g)"));
    addValue(previewForm, QStringLiteral("min_radius_ratio"), tr("Min radius ratio"));
    addValue(previewForm, QStringLiteral("stable_dt"), tr("Stable time step (s)"));
    addValue(previewForm, QStringLiteral("stage_ms"), tr("Intersect / select / decompose (ms)"));
    addValue(previewForm, QStringLiteral("relax_ms"), tr("Snap / relax / update (ms)"));
    addValue(previewForm, QStringLiteral("surface_ms"), tr("Surface cut (ms)"));
    addValue(previewForm, QStringLiteral("improve_ms"), tr("Mesh improvement (ms)"));
    addValue(previewForm, QStringLiteral("total_ms"), tr("Total (ms)"));
    auto* buttons = new QHBoxLayout;
    m_apply = new QPushButton(tr("&Apply cut"));
    m_apply->setObjectName(QStringLiteral("applyCut"));
    m_discard = new QPushButton(tr("&Discard"));
    m_discard->setObjectName(QStringLiteral("discardCut"));
    buttons->addWidget(m_apply);
    buttons->addWidget(m_discard);
    previewForm->addRow(buttons);
    layout->addWidget(previewBox);
    layout->addStretch(1);

    // Controls -> document (undoable edits).
    connect(m_method, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_syncing)
            m_document.setMethod(static_cast<CutMethod>(m_method->currentData().toInt()));
    });
    connect(m_triangulation, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_syncing)
            m_document.setTriangulation(static_cast<FaceTriangulation>(m_triangulation->currentData().toInt()));
    });
    connect(m_d, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_syncing)
            m_document.setD(v);
    });
    connect(m_snap, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            m_document.setSnap(on);
    });
    connect(m_relaxSteps, &QSpinBox::valueChanged, this, [this](int v) {
        if (!m_syncing)
            m_document.setRelaxSteps(v);
    });
    connect(m_wSpring, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_syncing)
            m_document.setWSpring(v);
    });
    connect(m_wParticle, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_syncing)
            m_document.setWParticle(v);
    });
    connect(m_relaxDamping, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_syncing)
            m_document.setRelaxDamping(v);
    });
    connect(m_rings, &QSpinBox::valueChanged, this, [this](int v) {
        if (!m_syncing)
            m_document.setRings(v);
    });
    connect(m_improve, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_syncing)
            m_document.setImprove(on);
    });
    connect(m_improveQuality, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_syncing)
            m_document.setImproveQuality(v);
    });
    connect(m_improveShortEdge, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_syncing)
            m_document.setImproveShortEdge(v);
    });
    connect(m_improveCoarsen, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_syncing)
            m_document.setImproveCoarsen(v);
    });
    connect(m_apply, &QPushButton::clicked, this, &CutPanel::apply);
    connect(m_inspectWorst, &QPushButton::clicked, this, &CutPanel::inspectNextWorstTet);
    connect(m_discard, &QPushButton::clicked, &m_preview, &CutPreview::discard);

    // Document and session -> panel.
    connect(&m_document, &ScenarioDocument::cutSettingsChanged, this, &CutPanel::syncFromDocument);
    connect(&m_document, &ScenarioDocument::documentReset, this, &CutPanel::syncFromDocument);
    connect(&m_preview, &CutPreview::changed, this, &CutPanel::updatePreview);
    connect(&m_preview, &CutPreview::busyChanged, this, &CutPanel::updatePreview);
    connect(&m_session, &TissueSession::currentChanged, this, &CutPanel::updatePreview);
    connect(&m_session, &TissueSession::busyChanged, this, &CutPanel::updatePreview);
    // Refusals are reported here, in place; any later edit or a new document clears them
    // (the undo that refuses an edit comes before its report).
    connect(&m_document, &ScenarioDocument::changed, this, [this] { setNotice(QString()); });
    connect(&m_session, &TissueSession::editRefused, this, [this](const QString& reason) {
        setNotice(tr("The last edit was undone: %1").arg(reason));
    });
    connect(&m_session, &TissueSession::failed, this, [this](const QString& message) {
        setNotice(tr("The tissue or its cuts fail: %1").arg(message));
    });
    syncFromDocument();
    updatePreview();
}

QLabel* CutPanel::addValue(QFormLayout* form, const QString& key, const QString& label) {
    auto* value = new QLabel;
    value->setObjectName(QStringLiteral("preview_") + key);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(label, value);
    m_values.emplace_back(key, value);
    return value;
}

QString CutPanel::notice() const {
    return m_notice->text();
}

void CutPanel::setNotice(const QString& text) {
    m_notice->setText(text);
    m_notice->setVisible(!text.isEmpty());
}

QString CutPanel::previewValue(const QString& key) const {
    for (const auto& [k, label] : m_values)
        if (k == key)
            return label->text();
    return {};
}

void CutPanel::syncFromDocument() {
    const CutSettings& s = m_document.scenario().cut;
    m_syncing = true;
    m_method->setCurrentIndex(m_method->findData(int(s.method)));
    m_triangulation->setCurrentIndex(m_triangulation->findData(int(s.triangulation)));
    m_triangulation->setEnabled(s.method == CutMethod::Hybrid);
    m_d->setValue(s.d);
    m_d->setEnabled(s.method == CutMethod::Hybrid);
    m_snap->setChecked(s.snap);
    m_relaxSteps->setValue(s.relaxSteps);
    m_wSpring->setValue(s.wSpring);
    m_wParticle->setValue(s.wParticle);
    m_relaxDamping->setValue(s.damping);
    m_rings->setValue(s.rings);
    m_improve->setChecked(s.improve);
    m_improveQuality->setValue(s.improveQuality);
    m_improveShortEdge->setValue(s.improveShortEdge);
    m_improveCoarsen->setValue(s.improveCoarsen);
    for (QDoubleSpinBox* factor : {m_improveQuality, m_improveShortEdge, m_improveCoarsen})
        factor->setEnabled(s.improve);
    m_syncing = false;
}

void CutPanel::updatePreview() {
    const auto current = m_session.current();
    const auto preview = m_preview.preview();
    const bool pending = m_preview.hasPending();
    m_apply->setEnabled(m_preview.canApply());
    m_discard->setEnabled(pending);
    if (!pending)
        m_previewStatus->setText(tr("No pending cut. Draw a sweep or record a stroke to preview a cut."));
    else if (!m_preview.error().isEmpty())
        m_previewStatus->setText(
            tr("The cut fails, it cannot be applied: %1").arg(m_preview.error()));
    else if (!m_preview.isReady() || m_session.isBusy())
        m_previewStatus->setText(tr("Computing the preview..."));
    else
        m_previewStatus->setText(tr("Preview of the pending cut (not applied yet)."));

    updateWarning();
    if (!preview || !current || !pending) {
        for (auto& [key, label] : m_values)
            label->clear();
        return;
    }
    const CutStats& c = preview->cutStats;
    const auto set = [this](const QString& key, const QString& text) {
        for (auto& [k, label] : m_values)
            if (k == key)
                label->setText(text);
    };
    set(QStringLiteral("tets"), beforeAfter(QString::number(current->mesh().tetCount()),
                                            QString::number(preview->mesh().tetCount())));
    set(QStringLiteral("added_tets"), QString::number(preview->mesh().tetCount() - current->mesh().tetCount()));
    set(QStringLiteral("cut_edges"), QString::number(c.cutEdges));
    set(QStringLiteral("cut_nodes"), QString::number(c.cutNodes));
    set(QStringLiteral("snapped_nodes"),
        tr("%1 (%2 refused)").arg(c.snappedNodes).arg(c.refusedSnaps));
    set(QStringLiteral("decomposed_tets"), QString::number(c.decomposedTets));
    set(QStringLiteral("separated_tets"), QString::number(c.separatedTets));
    set(QStringLiteral("collapsed_edges"), QString::number(preview->collapsedEdges));
    set(QStringLiteral("smoothed_nodes"), QString::number(preview->smoothedNodes));
    set(QStringLiteral("removed_tets"), QString::number(preview->removedTets));
    set(QStringLiteral("pieces"), beforeAfter(QString::number(current->pieces), QString::number(preview->pieces)));
    const Tissue& was = current->tissue;
    const Tissue& will = preview->tissue;
    set(QStringLiteral("chips"), beforeAfter(QString::number(was.chips().size()), QString::number(will.chips().size())));
    set(QStringLiteral("resected_volume"), beforeAfter(number(was.resectedVolume()), number(will.resectedVolume())));
    set(QStringLiteral("resected_mass"), beforeAfter(number(was.resectedMass()), number(will.resectedMass())));
    set(QStringLiteral("min_radius_ratio"),
        beforeAfter(number(current->quality.minRadiusRatio), number(preview->quality.minRadiusRatio)));
    set(QStringLiteral("stable_dt"), beforeAfter(number(current->stableDt), number(preview->stableDt)));
    set(QStringLiteral("stage_ms"), tr("%1 / %2 / %3")
                                        .arg(number(c.timeMs.intersect, 2), number(c.timeMs.select, 2),
                                             number(c.timeMs.decompose, 2)));
    set(QStringLiteral("relax_ms"), tr("%1 / %2 / %3")
                                        .arg(number(c.timeMs.snap, 2), number(c.timeMs.relax, 2),
                                             number(c.timeMs.update, 2)));
    set(QStringLiteral("surface_ms"), number(preview->surfaceCutMs, 2));
    set(QStringLiteral("improve_ms"), number(preview->improveMs, 2));
    set(QStringLiteral("total_ms"), number(preview->totalMs, 3));
}

QString CutPanel::warning() const {
    return m_warning->isHidden() ? QString() : m_warningText->text();
}

void CutPanel::updateWarning() {
    const auto preview = m_preview.preview();
    const PreviewWarnings w = m_preview.hasPending() && m_preview.error().isEmpty() ? m_preview.warnings()
                                                                                    : PreviewWarnings{};
    if (!preview || !w.any()) {
        m_warning->hide();
        m_warnedPreview = nullptr;
        return;
    }
    if (m_warnedPreview != preview.get()) {
        m_warnedPreview = preview.get();
        m_nextWorst = 0;
    }
    QStringList lines;
    if (w.stepDropped) {
        const auto current = m_session.current();
        lines << tr("This cut makes the stable time step %1 times smaller (%2 s → %3 s): an explicit "
                    "simulation needs that many more steps, and the tets that cause it are tiny or flat.")
                     .arg(number(w.stepDrop, 3), number(current ? current->stableDt : 0),
                          number(preview->stableDt));
    }
    if (w.snapsAllRefused)
        lines << tr("Snapping refused every cut node (%1 refused): the cut nodes stay where the sweep "
                    "crossed the edges, as with subdivision, which leaves small and flat tets.")
                     .arg(w.refusedSnaps);
    QStringList tets;
    for (int t : preview->stepLimitingTets)
        tets << QString::number(t);
    if (!tets.isEmpty())
        lines << tr("Tets that limit the time step, worst first: %1.").arg(tets.join(QStringLiteral(", ")));
    m_warningText->setText(tr("Warning: %1").arg(lines.join(QLatin1Char(' '))));
    m_inspectWorst->setEnabled(!preview->stepLimitingTets.empty());
    m_inspectWorst->setText(m_nextWorst == 0 ? tr("Inspect the worst tet")
                                             : tr("Inspect the next (%1 of %2)")
                                                   .arg(m_nextWorst + 1)
                                                   .arg(preview->stepLimitingTets.size()));
    m_warning->show();
}

void CutPanel::inspectNextWorstTet() {
    const auto preview = m_preview.preview();
    if (!preview || preview->stepLimitingTets.empty())
        return;
    const auto& tets = preview->stepLimitingTets;
    const int tet = tets[static_cast<std::size_t>(m_nextWorst) % tets.size()];
    m_nextWorst = (m_nextWorst + 1) % static_cast<int>(tets.size());
    updateWarning();
    emit inspectTetRequested(tet);
}

void CutPanel::apply() {
    QString error;
    if (!m_preview.apply(&error))
        emit applyFailed(error);
}

} // namespace resect
