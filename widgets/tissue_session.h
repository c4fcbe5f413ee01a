#pragma once
// TissueSession: the tissue the studio shows, derived from the ScenarioDocument (the single
// source of truth) on a worker thread, never on the GUI thread. It holds no edit of its own:
// a cut not yet in the document is CutPreview's (cut_preview.h).
//
// Two states, each an immutable snapshot (TissueState, tissue_state.h) shared with the views:
//  - base():    the scenario's first tissue, loaded or meshed (scenario_run.h loadTissue) and
//               made into a Tissue as replay makes it (planLoadedTissue, makeTissue: the
//               embedded high-resolution surface bound, the fixed regions' nodes anchored);
//               no cuts;
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

#include "scenario/scenario_document.h"
#include "widgets/tissue_state.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <optional>
#include <thread>

namespace resect {

class ScenarioDocument;

class TissueSession : public QObject {
    Q_OBJECT

public:
    explicit TissueSession(ScenarioDocument& document, QObject* parent = nullptr);
    /// Cancels the worker and waits for it.
    ~TissueSession() override;

    /// True while the worker runs or a request waits for it.
    bool isBusy() const { return m_worker.joinable() || m_startPosted || m_queued.has_value(); }
    /// The last load or cut failure (empty after a success).
    const QString& error() const { return m_error; }

    std::shared_ptr<const TissueState> base() const { return m_base; }
    std::shared_ptr<const TissueState> current() const { return m_current; }

    /// Cancels a running load (meshing stops; the previous tissue stays).
    void cancel();

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
    /// Loading or applying the document's cuts failed; `message` names what and why.
    void failed(const QString& message);

private:
    struct Request {
        Scenario scenario;
        bool reload = false;
        bool reapply = false;
    };
    struct Result {
        std::shared_ptr<const TissueState> base, current;
        bool baseChanged = false, currentChanged = false;
        bool loadFailed = false, cancelled = false;
        QString key; ///< tissueKey of a newly loaded base
        QString error;
    };

    void onDocumentReset();
    void schedule(bool reload, bool reapply);
    void startNext();
    void finish(Result result);
    static Result compute(const Request& request, std::shared_ptr<const TissueState> base,
                          std::shared_ptr<const TissueState> current, const std::atomic<bool>& cancel);

    ScenarioDocument& m_document;
    std::shared_ptr<const TissueState> m_base, m_current;
    QString m_baseKey;     ///< what the base was loaded from (tissue spec and folder)
    QString m_loadingKey;  ///< what the running or queued load loads
    QString m_error;

    std::optional<Request> m_queued;
    bool m_startPosted = false; ///< a start of the queued request is posted
    bool m_dropRunning = false; ///< the running job's result belongs to a closed document
    bool m_reframe = false;     ///< a new document reuses the base: say baseChanged once cut
    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
};

} // namespace resect
