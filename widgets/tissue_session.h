#pragma once
// TissueSession: the tissue the studio shows, derived from the ScenarioDocument (the single
// source of truth) on a worker thread, never on the GUI thread. It holds no edit of its own:
// a cut not yet in the document is CutPreview's (cut_preview.h).
//
// Two states, each an immutable snapshot (TissueState, tissue_state.h) shared with the views:
//  - base():    the scenario's first tissue, loaded or meshed (scenario_run.h loadTissue) and
//               made into a Tissue as replay makes it (planLoadedTissue, makeTissue: the
//               embedded high-resolution surface bound, the fixed regions' nodes anchored);
//               no cuts. An edit of the fixed regions re-anchors the loaded tissue
//               (Tissue::setAnchors) instead of loading it again, and does not announce a new
//               base (the views keep their framing); every cut is applied again;
//  - current(): a copy of base with every cut of the document applied in replay order
//               (strokes, then sweeps; scenario_sweeps.h scenarioCuts) by Tissue::cut with
//               the document's cut settings, in the rest configuration (the simulation runs
//               separately, simulation_controller.h). The copy keeps base's spatial index and
//               unit of d, so the studio cuts bit-identically to `resect cut` and replay.
//
// What is recomputed follows what changed: a new document re-meshes only if its tissue
// differs from the loaded one; when the document only adds cuts to those of current (same
// base, same settings), only the new ones are cut, on a copy of current; otherwise (undo,
// settings) every cut is re-applied on a copy of base (a few milliseconds for the samples).
// Requests made while the worker is busy are merged and run next; a newer load cancels an
// older one. Results of superseded requests are dropped.
//
// Every state of the document is derived as replay would derive it, so the document never
// keeps one that does not: a state is first validated as loading it would be
// (validateScenario: also what saving checks, so a derived state can be saved and read back),
// then its cuts are applied; effect edits are validated too, and every state is checked as
// starting replay's simulation would check it (checkSimulation, scenario_run.h: the fixed
// effect must hold a node, every effect must take its parameters). When a state of the document
// fails, the edits that led to it are undone back to the nearest earlier state that derived
// (ScenarioDocument::revertTo; they are dropped from the undo stack) and editRefused() says
// why; only a state with no such earlier state (a document opened directly, not through a
// trial) stays failed and is reported by failed(). A state that derived is "verified"; the
// comparison ignores the metadata and where relative paths are resolved from.
//
// Progress: while a load meshes a surface, loadProgress() reports each stage of the mesher
// (MeshingProgress, core/mesher/tetrahedralize.h) on this thread; progress of a request that
// was cancelled or superseded is dropped, as its result is.
//
// Trials: trial() derives a scenario that is not the document yet (a file being opened) on
// the same worker, without touching the document or the published states; the studio
// replaces the document only once its trial succeeded (DocumentOpener), and the trial's
// states are then published at once instead of being derived again.

#include "core/mesher/tetrahedralize.h"
#include "scenario/scenario_document.h"
#include "widgets/tissue_state.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

namespace resect {

class ScenarioDocument;

class TissueSession : public QObject {
    Q_OBJECT

public:
    explicit TissueSession(ScenarioDocument& document, QObject* parent = nullptr);
    /// Cancels the worker and waits for it.
    ~TissueSession() override;

    /// True while the worker runs or a request (or trial) waits for it.
    bool isBusy() const {
        return m_worker.joinable() || m_startPosted || m_queued.has_value() ||
               m_queuedTrial.has_value();
    }
    /// The last load, validation or cut failure of the document's state (empty after a
    /// success).
    const QString& error() const { return m_error; }
    /// Why the document's state cannot be saved now (ScenarioDocument::setSaveCheck): still
    /// being derived, failed, or never derived (a derivation was cancelled); empty when this
    /// very state derived.
    QString saveBlocker() const;

    std::shared_ptr<const TissueState> base() const { return m_base; }
    std::shared_ptr<const TissueState> current() const { return m_current; }

    /// Cancels a running load or trial (meshing stops; the previous tissue stays).
    void cancel();

    /// Derives `scenario` (a document about to be opened) as the document's state would be,
    /// without touching the document or the published states; trialFinished(id, ...) reports
    /// on this thread. A newer trial replaces an older one (whose result is dropped unreported);
    /// cancel() ends it with a failure. Returns the trial's id (never 0).
    std::uint64_t trial(const Scenario& scenario);
    /// True while a trial runs or waits.
    bool isTrialRunning() const { return m_trialRunning || m_queuedTrial.has_value(); }

    /// Runs the event loop until the worker is idle and no request is queued, or `ms` passed
    /// (for tests and the command line's --screenshot). True if idle.
    bool waitForIdle(int ms);

signals:
    void busyChanged(bool busy);
    /// A different tissue was loaded, or a new document reuses the loaded one (views
    /// reframe). base() may be null after a failed load.
    void baseChanged();
    /// A new current state was published (after any change of the document's cuts or cut
    /// settings, and after base changes).
    void currentChanged();
    /// Loading or applying the document's cuts failed and no earlier state could be
    /// restored; `message` names what and why.
    void failed(const QString& message);
    /// The document's last edits made a state that does not derive: they were undone (and
    /// dropped) back to the last state that did; `reason` names the edit's problem.
    void editRefused(const QString& reason);
    /// A trial ended: ok (its states are published when the document is replaced by its
    /// scenario), or why not (also "cancelled").
    void trialFinished(std::uint64_t id, bool ok, const QString& message);
    /// The load of the document's tissue or of a trial meshes a surface and started a stage:
    /// `stage` names it for the author (with the attempt when the mesher re-meshes with another
    /// seed), `fraction` (0..1) estimates the work done (MeshingProgress; a new attempt starts
    /// again at 0). Only for the request that runs and is still wanted.
    void loadProgress(const QString& stage, double fraction);

private:
    struct Request {
        Scenario scenario;
        bool reload = false;
        bool reapply = false;
        std::uint64_t generation = 0; ///< the document's (see m_generation)
        std::uint64_t trial = 0;      ///< a trial's id; 0: the document's state
    };
    struct Result {
        Scenario scenario; ///< what was derived
        std::shared_ptr<const TissueState> base, current;
        bool baseChanged = false, currentChanged = false;
        bool baseReanchored = false; ///< base is the loaded one with the anchors of other regions
        bool loadFailed = false, cancelled = false;
        QString key; ///< tissueKey of a newly loaded base
        QString error;
        std::uint64_t generation = 0;
        std::uint64_t trial = 0;
    };

    void onDocumentReset();
    /// Publishes a successful trial's states for the document that now holds its scenario.
    void adoptTrial(Result trial);
    void schedule(bool reload, bool reapply);
    void postStart();
    void startNext();
    void finish(Result result);
    void finishTrial(Result result);
    /// On this thread: emits loadProgress for the request of `generation` and `trial` (its
    /// Request fields) unless that request was cancelled or superseded.
    void reportProgress(std::uint64_t generation, std::uint64_t trial,
                        const MeshingProgress& progress);
    /// What loadProgress says of `progress`.
    static QString stageText(const MeshingProgress& progress);
    /// After a failure of the document's state: reverts the document to its last verified
    /// state if it still holds the failed one; true if it did.
    bool refuse(const Scenario& failed);
    void addVerified(const Scenario& scenario);
    bool isVerified(const Scenario& scenario) const;
    /// Derives `request` on the worker; `progress` receives the meshing stages of a load.
    static Result compute(const Request& request, std::shared_ptr<const TissueState> base,
                          std::shared_ptr<const TissueState> current,
                          const std::atomic<bool>& cancel,
                          const std::function<void(const MeshingProgress&)>& progress);

    ScenarioDocument& m_document;
    std::shared_ptr<const TissueState> m_base, m_current;
    QString m_baseKey;     ///< what the base was loaded from (tissue spec and folder)
    QString m_loadingKey;  ///< what the running or queued load loads
    QString m_error;

    std::optional<Request> m_queued;      ///< the document's next state to derive
    std::optional<Request> m_queuedTrial; ///< the next trial
    std::optional<Result> m_trialResult;  ///< a successful trial, until the document takes it
    std::uint64_t m_lastTrial = 0;        ///< id of the latest trial
    bool m_trialRunning = false;
    /// Counts document replacements; a result of an older document is dropped.
    std::uint64_t m_generation = 1;
    /// States of this document that derived (derivationKey), the latest last.
    std::vector<Scenario> m_verified;
    /// The derivationKey of the state m_current shows (empty when there is none).
    std::optional<Scenario> m_currentKey;
    bool m_startPosted = false; ///< a start of the queued request is posted
    bool m_reframe = false;     ///< a new document reuses the base: say baseChanged once cut
    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
};

} // namespace resect
