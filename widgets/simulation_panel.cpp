#include "widgets/simulation_panel.h"

#include "core/tissue/tissue.h"
#include "scenario/scenario_document.h"
#include "widgets/effect_parameter_editor.h"
#include "widgets/fixed_region_editor.h"
#include "widgets/scenario_document.h"
#include "widgets/simulation_controller.h"
#include "widgets/tissue_session.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace resect {

namespace {

/// The effect names as the author reads them.
QString effectTitle(const std::string& name) {
    if (name == "deformation")
        return SimulationPanel::tr("Deformation (mass-spring)");
    if (name == "gravity")
        return SimulationPanel::tr("Gravity");
    if (name == "fixed")
        return SimulationPanel::tr("Fixed regions");
    if (name == "tool-contact")
        return SimulationPanel::tr("Tool contact");
    if (name == "damping")
        return SimulationPanel::tr("Damping");
    return QString::fromStdString(name);
}

QString number(double v, int precision = 3) { return QLocale().toString(v, 'g', precision); }

} // namespace

SimulationPanel::SimulationPanel(ScenarioDocument& document, TissueSession& session, SimulationController& controller,
                                 QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session), m_controller(controller) {
    setObjectName(QStringLiteral("simulationPanel"));
    auto* layout = new QVBoxLayout(this);

    auto* buttons = new QHBoxLayout;
    m_play = new QPushButton(tr("Play"));
    m_play->setObjectName(QStringLiteral("simPlay"));
    m_step = new QPushButton(tr("Step"));
    m_step->setObjectName(QStringLiteral("simStep"));
    m_reset = new QPushButton(tr("Reset"));
    m_reset->setObjectName(QStringLiteral("simReset"));
    buttons->addWidget(m_play);
    buttons->addWidget(m_step);
    buttons->addWidget(m_reset);
    layout->addLayout(buttons);
    m_notice = new QLabel(this);
    m_notice->setObjectName(QStringLiteral("simNotice"));
    m_notice->setWordWrap(true);
    m_notice->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notice->setStyleSheet(QStringLiteral("QLabel { color: #a40000; font-weight: bold; }"));
    m_notice->hide();
    layout->addWidget(m_notice);

    // Each effect's check box, its parameters indented under it.
    auto* effects = new QGroupBox(tr("Effects in the scenario"), this);
    auto* effectsLayout = new QVBoxLayout(effects);
    const auto indented = [effectsLayout](QWidget* widget) {
        auto* row = new QHBoxLayout;
        row->setContentsMargins(24, 0, 0, 6);
        row->addWidget(widget, 1);
        effectsLayout->addLayout(row);
    };
    for (const std::string& name : knownEffectNames()) {
        auto* box = new QCheckBox(effectTitle(name));
        box->setObjectName(QStringLiteral("effect_") + QString::fromStdString(name));
        effectsLayout->addWidget(box);
        m_effects[name] = box;
        connect(box, &QCheckBox::toggled, this, [this, name](bool on) {
            if (!m_syncing)
                onEffectToggled(name, on);
        });
        if (name == "fixed") {
            // The regions are the tissue's: editable whether the effect is on or not (they
            // also tell the tissue from the chips a cut resects).
            m_fixedRegions = new FixedRegionEditor(m_document, m_session);
            connect(m_fixedRegions, &FixedRegionEditor::notice, this, &SimulationPanel::setNotice);
            indented(m_fixedRegions);
            continue;
        }
        auto* editor = new EffectParameterEditor(name);
        m_parameters[name] = editor;
        if (editor->hasControls())
            indented(editor);
        connect(editor, &EffectParameterEditor::edited, this, [this, name](const QJsonObject& parameters) {
            if (!m_syncing)
                m_document.setEffectParameters(QString::fromStdString(name), parameters);
        });
    }
    layout->addWidget(effects);

    auto* figures = new QGroupBox(tr("Cost"), this);
    auto* form = new QFormLayout(figures);
    m_time = new QLabel;
    m_time->setObjectName(QStringLiteral("simTime"));
    form->addRow(tr("Simulated time"), m_time);
    m_dt = new QLabel;
    m_dt->setObjectName(QStringLiteral("simDt"));
    form->addRow(tr("Time step"), m_dt);
    m_cost = new QLabel;
    m_cost->setObjectName(QStringLiteral("simCost"));
    m_cost->setWordWrap(true);
    form->addRow(tr("Per step"), m_cost);
    m_realTime = new QLabel;
    m_realTime->setObjectName(QStringLiteral("simRealtime"));
    m_realTime->setWordWrap(true);
    form->addRow(tr("Real time"), m_realTime);
    layout->addWidget(figures);
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("simStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    layout->addStretch(1);

    connect(m_play, &QPushButton::clicked, this, [this] {
        if (m_controller.isPlaying())
            m_controller.pause();
        else
            m_controller.play();
    });
    connect(m_step, &QPushButton::clicked, &m_controller, &SimulationController::step);
    connect(m_reset, &QPushButton::clicked, &m_controller, &SimulationController::reset);
    connect(&m_controller, &SimulationController::playingChanged, this, &SimulationPanel::updateState);
    connect(&m_controller, &SimulationController::resetDone, this, &SimulationPanel::updateState);
    connect(&m_controller, &SimulationController::cutsFollowed, this, &SimulationPanel::updateFigures);
    connect(&m_controller, &SimulationController::stepped, this, &SimulationPanel::updateFigures);
    connect(&m_controller, &SimulationController::failed, this, &SimulationPanel::updateState);
    connect(&m_document, &ScenarioDocument::effectsChanged, this, &SimulationPanel::syncEffects);
    connect(&m_document, &ScenarioDocument::documentReset, this, &SimulationPanel::syncEffects);
    // Refusals are reported here, in place; the next edit or a new document clears them (the
    // undo that refuses an edit comes before its report).
    connect(&m_document, &ScenarioDocument::changed, this, [this] { setNotice(QString()); });
    connect(&m_session, &TissueSession::editRefused, this, [this](const QString& reason) {
        setNotice(tr("The last edit was undone: %1").arg(reason));
    });
    syncEffects();
    updateState();
}

QCheckBox* SimulationPanel::effectBox(const std::string& name) const {
    const auto it = m_effects.find(name);
    return it == m_effects.end() ? nullptr : it->second;
}

EffectParameterEditor* SimulationPanel::parameterEditor(const std::string& name) const {
    const auto it = m_parameters.find(name);
    return it == m_parameters.end() ? nullptr : it->second;
}

QString SimulationPanel::notice() const {
    return m_notice->text();
}

void SimulationPanel::setNotice(const QString& text) {
    m_notice->setText(text);
    m_notice->setVisible(!text.isEmpty());
}

void SimulationPanel::onEffectToggled(const std::string& name, bool on) {
    const QString effect = QString::fromStdString(name);
    if (name == "fixed" && on && m_document.fixedRegions().empty()) {
        // The effect needs a region: the tissue's base, once the tissue is known.
        const std::optional<FixedRegion> base = m_fixedRegions->baseRegionOfTissue();
        if (!base) {
            setNotice(tr("Fixed regions: the tissue is not loaded yet, so its base cannot be anchored. "
                         "Try again once it is shown."));
            syncEffects();
            return;
        }
        m_document.fixRegion(*base);
        return;
    }
    m_document.setEffectEnabled(effect, on);
}

void SimulationPanel::syncEffects() {
    m_syncing = true;
    for (auto& [name, box] : m_effects)
        box->setChecked(m_document.isEffectEnabled(QString::fromStdString(name)));
    for (auto& [name, editor] : m_parameters) {
        const EffectSpec* spec = m_document.scenario().findEffect(name);
        editor->setEnabled(spec != nullptr);
        if (spec)
            editor->setParameters(spec->parameters);
    }
    m_syncing = false;
}

void SimulationPanel::updateState() {
    const bool ready = m_controller.isReady();
    m_play->setEnabled(ready);
    m_step->setEnabled(ready && !m_controller.isPlaying());
    m_reset->setEnabled(ready || !m_controller.error().isEmpty());
    m_play->setText(m_controller.isPlaying() ? tr("Pause") : tr("Play"));
    if (!m_controller.error().isEmpty())
        m_status->setText(m_controller.error());
    else if (!ready)
        m_status->setText(tr("No tissue to simulate."));
    else
        m_status->setText(m_controller.isPlaying() ? tr("Running.") : tr("Paused."));
    updateFigures();
}

void SimulationPanel::updateFigures() {
    m_time->setText(tr("%1 s (%2 steps)").arg(number(m_controller.time(), 4)).arg(m_controller.steps()));
    m_dt->setText(tr("%1 s (stable: %2 s)").arg(number(m_controller.timeStep()), number(m_controller.stableTimeStep())));
    QStringList parts;
    for (const auto& [name, ms] : m_controller.effectMsPerStep())
        parts << tr("%1: %2 ms").arg(QString::fromStdString(name), number(ms, 2));
    // The integrator's own work (node passes; for the implicit one, its iterations and solves,
    // which evaluate the deformation forces themselves).
    if (const Simulator* sim = m_controller.tissue().simulator(); sim && sim->stepsTaken() > 0)
        parts << tr("integrator: %1 ms").arg(number(sim->integrateMsTotal() / sim->stepsTaken(), 2));
    if (m_controller.msPerSimulatedSecond() > 0)
        parts << tr("%1 ms per simulated second").arg(number(m_controller.msPerSimulatedSecond()));
    m_cost->setText(parts.join(QLatin1Char('\n')));
    const SimulationSettings& settings = m_document.scenario().simulation;
    QString integrator = QString::fromStdString(settings.integrator);
    if (Integrator kind{}; parseIntegrator(settings.integrator, kind) && kind == Integrator::ProjectiveDynamics)
        integrator = settings.iterations == 1 ? tr("implicit, 1 iteration a step")
                                              : tr("implicit, %1 iterations a step").arg(settings.iterations);
    const double ms = m_controller.msPerSimulatedSecond();
    m_realTime->setText(ms > 0 ? tr("%1x real time (%2)").arg(number(1000 / ms, 3), integrator)
                               : tr("not measured yet (%1)").arg(integrator));
}

} // namespace resect
