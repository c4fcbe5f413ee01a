#include "widgets/scenario_commands.h"

#include "widgets/scenario_document.h"

#include <QCoreApplication>

#include <algorithm>
#include <utility>

namespace resect {

namespace {

/// Command ids for merging (QUndoCommand::id); -1 never merges.
constexpr int kCutSettingsIdBase = 1000;
constexpr int kTitleId = 2000;
constexpr int kEffectParametersId = 3000;
constexpr int kFixedRegionsId = 4000;

bool isNumeric(CutField field) {
    switch (field) {
    case CutField::D:
    case CutField::RelaxSteps:
    case CutField::WSpring:
    case CutField::WParticle:
    case CutField::Damping:
    case CutField::Rings:
    case CutField::ImproveQuality:
    case CutField::ImproveShortEdge:
    case CutField::ImproveCoarsen:
        return true;
    case CutField::All:
    case CutField::Method:
    case CutField::Triangulation:
    case CutField::Snap:
    case CutField::Improve:
        return false;
    }
    return false;
}

/// `sweep` with its file path, relative to `from`, made relative to `to` instead.
SweepSpec rebasedSweep(const SweepSpec& sweep, const std::string& from, const std::string& to) {
    if (sweep.file.empty() || from == to)
        return sweep;
    Scenario holder;
    holder.baseDir = from;
    holder.sweeps.push_back(sweep);
    rebaseScenarioPaths(holder, to);
    return holder.sweeps.front();
}

template <typename T> int clampedIndex(const std::vector<T>& items, int index) {
    return index < 0 || index > static_cast<int>(items.size()) ? static_cast<int>(items.size())
                                                                : index;
}

/// Rank of an effect name in knownEffectNames() (unknown names last).
int effectRank(const std::string& name) {
    const auto& names = knownEffectNames();
    return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

} // namespace

// ---- ScenarioCommand -------------------------------------------------------------------

ScenarioCommand::ScenarioCommand(ScenarioDocument& document, const QString& text)
    : QUndoCommand(text), m_document(document) {}

Scenario& ScenarioCommand::scenario() {
    return m_document.m_scenario;
}

void ScenarioCommand::notify(unsigned parts) {
    m_document.notify(parts);
}

// ---- SetCutSettingsCommand -------------------------------------------------------------

SetCutSettingsCommand::SetCutSettingsCommand(ScenarioDocument& document, CutSettings before,
                                             CutSettings after, CutField field)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Change cut settings")), m_before(std::move(before)),
      m_after(std::move(after)), m_field(field) {}

void SetCutSettingsCommand::redo() {
    scenario().cut = m_after;
    notify(ScenarioDocument::CutSettingsPart);
}

void SetCutSettingsCommand::undo() {
    scenario().cut = m_before;
    notify(ScenarioDocument::CutSettingsPart);
}

int SetCutSettingsCommand::id() const {
    return isNumeric(m_field) ? kCutSettingsIdBase + static_cast<int>(m_field) : -1;
}

bool SetCutSettingsCommand::mergeWith(const QUndoCommand* other) {
    // Same id means same numeric field (QUndoStack only offers commands of equal id).
    const auto* next = static_cast<const SetCutSettingsCommand*>(other);
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

// ---- Strokes ---------------------------------------------------------------------------

AddStrokeCommand::AddStrokeCommand(ScenarioDocument& document, Stroke stroke, int index)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Add stroke")), m_stroke(std::move(stroke)),
      m_index(clampedIndex(scenario().strokes, index)) {}

void AddStrokeCommand::redo() {
    auto& strokes = scenario().strokes;
    strokes.insert(strokes.begin() + m_index, m_stroke);
    notify(ScenarioDocument::StrokesPart);
}

void AddStrokeCommand::undo() {
    auto& strokes = scenario().strokes;
    strokes.erase(strokes.begin() + m_index);
    notify(ScenarioDocument::StrokesPart);
}

RemoveStrokeCommand::RemoveStrokeCommand(ScenarioDocument& document, int index)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Remove stroke")),
      m_stroke(scenario().strokes.at(static_cast<std::size_t>(index))), m_index(index) {}

void RemoveStrokeCommand::redo() {
    auto& strokes = scenario().strokes;
    strokes.erase(strokes.begin() + m_index);
    notify(ScenarioDocument::StrokesPart);
}

void RemoveStrokeCommand::undo() {
    auto& strokes = scenario().strokes;
    strokes.insert(strokes.begin() + m_index, m_stroke);
    notify(ScenarioDocument::StrokesPart);
}

// ---- Sweeps ----------------------------------------------------------------------------

AddSweepCommand::AddSweepCommand(ScenarioDocument& document, SweepSpec sweep, int index)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Add sweep")), m_sweep(std::move(sweep)),
      m_baseDir(scenario().baseDir), m_index(clampedIndex(scenario().sweeps, index)) {}

void AddSweepCommand::redo() {
    auto& sweeps = scenario().sweeps;
    sweeps.insert(sweeps.begin() + m_index,
                  rebasedSweep(m_sweep, m_baseDir, scenario().baseDir));
    notify(ScenarioDocument::SweepsPart);
}

void AddSweepCommand::undo() {
    auto& sweeps = scenario().sweeps;
    sweeps.erase(sweeps.begin() + m_index);
    notify(ScenarioDocument::SweepsPart);
}

RemoveSweepCommand::RemoveSweepCommand(ScenarioDocument& document, int index)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Remove sweep")),
      m_sweep(scenario().sweeps.at(static_cast<std::size_t>(index))),
      m_baseDir(scenario().baseDir), m_index(index) {}

void RemoveSweepCommand::redo() {
    auto& sweeps = scenario().sweeps;
    sweeps.erase(sweeps.begin() + m_index);
    notify(ScenarioDocument::SweepsPart);
}

void RemoveSweepCommand::undo() {
    auto& sweeps = scenario().sweeps;
    sweeps.insert(sweeps.begin() + m_index,
                  rebasedSweep(m_sweep, m_baseDir, scenario().baseDir));
    notify(ScenarioDocument::SweepsPart);
}

// ---- DropRedoCommand -------------------------------------------------------------------

DropRedoCommand::DropRedoCommand(ScenarioDocument& document)
    : ScenarioCommand(document, QString()) {
    setObsolete(true);
}

// ---- Effects ---------------------------------------------------------------------------

SetEffectEnabledCommand::SetEffectEnabledCommand(ScenarioDocument& document, EffectSpec effect,
                                                 bool enable)
    : ScenarioCommand(document, enable ? QCoreApplication::translate("resect::ScenarioCommand", "Switch effect on") : QCoreApplication::translate("resect::ScenarioCommand", "Switch effect off")),
      m_effect(std::move(effect)), m_enable(enable) {
    if (!m_enable) {
        // Keep the effect as it is now (parameters and unknown fields) for undo.
        const auto& effects = scenario().effects;
        const auto it = std::find_if(effects.begin(), effects.end(), [&](const EffectSpec& e) {
            return e.name == m_effect.name;
        });
        if (it != effects.end()) {
            m_effect = *it;
            m_index = static_cast<int>(it - effects.begin());
        }
    }
}

void SetEffectEnabledCommand::insert() {
    auto& effects = scenario().effects;
    if (m_index < 0 || m_index > static_cast<int>(effects.size())) {
        const int rank = effectRank(m_effect.name);
        const auto it = std::find_if(effects.begin(), effects.end(), [&](const EffectSpec& e) {
            return effectRank(e.name) > rank;
        });
        m_index = static_cast<int>(it - effects.begin());
    }
    effects.insert(effects.begin() + m_index, m_effect);
    notify(ScenarioDocument::EffectsPart);
}

void SetEffectEnabledCommand::remove() {
    auto& effects = scenario().effects;
    effects.erase(effects.begin() + m_index);
    notify(ScenarioDocument::EffectsPart);
}

void SetEffectEnabledCommand::redo() {
    if (m_enable)
        insert();
    else
        remove();
}

void SetEffectEnabledCommand::undo() {
    if (m_enable)
        remove();
    else
        insert();
}

SetEffectParametersCommand::SetEffectParametersCommand(ScenarioDocument& document, std::string name,
                                                       QJsonObject before, QJsonObject after)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Change effect parameters")),
      m_name(std::move(name)), m_before(std::move(before)), m_after(std::move(after)) {}

void SetEffectParametersCommand::set(const QJsonObject& parameters) {
    for (EffectSpec& e : scenario().effects)
        if (e.name == m_name)
            e.parameters = parameters;
    notify(ScenarioDocument::EffectsPart);
}

void SetEffectParametersCommand::redo() {
    set(m_after);
}

void SetEffectParametersCommand::undo() {
    set(m_before);
}

int SetEffectParametersCommand::id() const {
    return kEffectParametersId;
}

bool SetEffectParametersCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const SetEffectParametersCommand*>(other);
    if (next->m_name != m_name)
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

// ---- Fixed regions ---------------------------------------------------------------------

SetFixedRegionsCommand::SetFixedRegionsCommand(ScenarioDocument& document, std::vector<FixedRegion> before,
                                               std::vector<FixedRegion> after, int mergeKey)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Change fixed regions")),
      m_before(std::move(before)), m_after(std::move(after)), m_mergeKey(mergeKey) {}

void SetFixedRegionsCommand::redo() {
    scenario().tissues.front().fixedRegions = m_after;
    notify(ScenarioDocument::FixedRegionsPart);
}

void SetFixedRegionsCommand::undo() {
    scenario().tissues.front().fixedRegions = m_before;
    notify(ScenarioDocument::FixedRegionsPart);
}

int SetFixedRegionsCommand::id() const {
    return m_mergeKey >= 0 ? kFixedRegionsId : -1;
}

bool SetFixedRegionsCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const SetFixedRegionsCommand*>(other);
    if (next->m_mergeKey != m_mergeKey)
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

// ---- Metadata --------------------------------------------------------------------------

SetTitleCommand::SetTitleCommand(ScenarioDocument& document, std::string before,
                                 std::string after)
    : ScenarioCommand(document, QCoreApplication::translate("resect::ScenarioCommand", "Change title")), m_before(std::move(before)),
      m_after(std::move(after)) {}

void SetTitleCommand::redo() {
    scenario().metadata.title = m_after;
    notify(ScenarioDocument::MetadataPart);
}

void SetTitleCommand::undo() {
    scenario().metadata.title = m_before;
    notify(ScenarioDocument::MetadataPart);
}

int SetTitleCommand::id() const {
    return kTitleId;
}

bool SetTitleCommand::mergeWith(const QUndoCommand* other) {
    m_after = static_cast<const SetTitleCommand*>(other)->m_after;
    setObsolete(m_after == m_before);
    return true;
}

} // namespace resect
