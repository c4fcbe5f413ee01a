#pragma once
// DocumentOpener: replaces the studio's document only with one whose tissue and cuts derive
// (issue 15: a failed open leaves the previous document and view fully intact).
//
// Opening is two steps apart: the file (or sample, or anatomy) is read into a Scenario
// without touching the document (ScenarioDocument::readScenario, sampleScenario,
// anatomyScenario); the TissueSession derives it as a trial on its worker (validated as
// loading would, the tissue loaded or meshed, every cut applied); only when that succeeds is
// the document replaced (ScenarioDocument::replace), and the session publishes the trial's
// states at once. Until then the open document, its undo stack, its title and everything on
// show stay as they are; a failure says why and changes nothing. A newer open replaces one
// still running; TissueSession::cancel() (the progress dialog's Cancel) ends it as failed.

#include "scenario/scenario_document.h"

#include <QObject>
#include <QString>

#include <cstdint>

namespace resect {

class ScenarioDocument;
class TissueSession;

class DocumentOpener : public QObject {
    Q_OBJECT

public:
    DocumentOpener(ScenarioDocument& document, TissueSession& session, QObject* parent = nullptr);

    /// A scenario file (.json). False (nothing started, nothing changed; *error says why) if it
    /// cannot be read or is not valid; otherwise opened() or failed() follows.
    bool openScenario(const QString& path, QString* error = nullptr);
    /// A new document on an anatomy file: a tet mesh, or a surface meshed in the background.
    bool openAnatomy(const QString& path, QString* error = nullptr);
    /// A new document on a built-in sample.
    bool openSample(const QString& name, QString* error = nullptr);

    /// True from a start until opened() or failed().
    bool isOpening() const { return m_trial != 0; }

signals:
    /// The document now holds what was opened, and its tissue and cuts are derived.
    void opened();
    /// Nothing was opened and nothing changed; `message` names the input and the problem.
    void failed(const QString& message);

private:
    void start(Scenario scenario, const QString& filePath, const QString& name);
    void onTrialFinished(std::uint64_t id, bool ok, const QString& message);

    ScenarioDocument& m_document;
    TissueSession& m_session;
    Scenario m_scenario; ///< what is being opened
    QString m_filePath;  ///< its scenario file (empty: a new document)
    QString m_name;      ///< how messages name it
    std::uint64_t m_trial = 0;
};

} // namespace resect
