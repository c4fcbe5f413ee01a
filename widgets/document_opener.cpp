#include "widgets/document_opener.h"

#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include <QFileInfo>

#include <utility>

namespace resect {

DocumentOpener::DocumentOpener(ScenarioDocument& document, TissueSession& session, QObject* parent)
    : QObject(parent), m_document(document), m_session(session) {
    connect(&m_session, &TissueSession::trialFinished, this, &DocumentOpener::onTrialFinished);
}

bool DocumentOpener::openScenario(const QString& path, QString* error) {
    Scenario scenario;
    if (!ScenarioDocument::readScenario(path, scenario, error))
        return false;
    start(std::move(scenario), path, path);
    return true;
}

bool DocumentOpener::openAnatomy(const QString& path, QString* error) {
    Scenario scenario;
    if (!ScenarioDocument::anatomyScenario(path, scenario, error))
        return false;
    start(std::move(scenario), QString(), path);
    return true;
}

bool DocumentOpener::openSample(const QString& name, QString* error) {
    Scenario scenario;
    if (!ScenarioDocument::sampleScenario(name, scenario, error))
        return false;
    start(std::move(scenario), QString(), name);
    return true;
}

void DocumentOpener::start(Scenario scenario, const QString& filePath, const QString& name) {
    m_scenario = std::move(scenario);
    m_filePath = filePath;
    m_name = name;
    m_trial = m_session.trial(m_scenario);
}

void DocumentOpener::onTrialFinished(std::uint64_t id, bool ok, const QString& message) {
    if (id != m_trial)
        return;
    m_trial = 0;
    Scenario scenario = std::move(m_scenario);
    m_scenario = Scenario{};
    if (!ok) {
        // Name the input unless the message already does (a tissue file's own errors do).
        const QString file = QFileInfo(m_name).fileName();
        emit failed(message.contains(file) ? message : tr("%1: %2").arg(m_name, message));
        return;
    }
    m_document.replace(std::move(scenario), m_filePath);
    emit opened();
}

} // namespace resect
