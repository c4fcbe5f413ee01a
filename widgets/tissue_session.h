#pragma once
// TissueSession: the tissue the studio shows, derived from the ScenarioDocument (the single
// source of truth) on a worker thread, never on the GUI thread.
//
// Three states, each an immutable snapshot (TissueState) shared with the views:
//  - base():    the scenario's first tissue, loaded or meshed (scenario_run.h loadTissue),
//               with its embedded high-resolution surface bound; no cuts;
//  - current(): base with every cut of the document applied in replay order (strokes, then
//               sweeps; scenario_sweeps.h scenarioCuts) with the document's cut settings,
//               in the rest configuration (the simulation runs separately,
//               simulation_controller.h);
//  - preview(): current with one pending cut (a sweep being drawn or a stroke just
//               recorded) that is not in the document yet: the live, non-destructive preview.
//               applyPending() adds the pending cut to the document as one undoable edit;
//               discardPending() drops it.
//
// What is recomputed follows what changed: a new document re-meshes only if its tissue
// differs from the loaded one; cut settings, strokes and sweeps re-apply the cuts on the
// base (a few milliseconds for the samples) and re-run the preview; undo and redo are just
// such changes. Requests made while the worker is busy are merged and run next; a newer
// load cancels an older one. Results of superseded requests are dropped.

#include "core/cut/hybrid_cutter.h"
#include "core/embed/embedded_surface.h"
#include "core/mesh/quality.h"
#include "scenario/scenario_document.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

namespace resect {

class ScenarioDocument;

/// One state of the tissue (see above). Never modified once published.
struct TissueState {
    TetMesh mesh;
    EmbeddedSurface surface;     ///< bound to `mesh`; may be empty
    std::vector<Scheme> schemes; ///< per tet: the scheme (Figure 4) that produced it (None: original)
    QualitySummary quality;
    double stableDt = 0;         ///< s, stableTimeStep of the mass-spring model
    int pieces = 0;              ///< connected components
    int cuts = 0;                ///< cuts applied since base
    CutStats cutStats;           ///< summed over those cuts (for a preview: the pending cut)
    double surfaceCutMs = 0;     ///< embedded-surface re-binding and cutting, summed
    int surfaceCapTriangles = 0; ///< cap triangles the cuts added to the surface
    QString tissueName;
};

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
    /// Why the preview could not be made (empty if there is one or no pending cut).
    const QString& previewError() const { return m_previewError; }

    std::shared_ptr<const TissueState> base() const { return m_base; }
    std::shared_ptr<const TissueState> current() const { return m_current; }
    std::shared_ptr<const TissueState> preview() const { return m_preview; }

    /// Sets the pending cut (replacing any other) and schedules its preview.
    void setPendingSweep(const SweepSpec& sweep);
    void setPendingStroke(const Stroke& stroke);
    bool hasPending() const { return m_pendingSweep.has_value() || m_pendingStroke.has_value(); }
    /// Drops the pending cut and its preview.
    void discardPending();
    /// Adds the pending cut to the document (one undoable edit) and clears it; the current
    /// state follows. False (with a reason) if there is no pending cut or it is invalid.
    bool applyPending(QString* error = nullptr);

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
    /// The document's cuts were re-applied (also after base changes).
    void currentChanged();
    /// The preview appeared, changed or was cleared.
    void previewChanged();
    /// Loading or applying the document's cuts failed; `message` names what and why.
    void failed(const QString& message);

private:
    struct Request {
        Scenario scenario;
        bool reload = false;
        bool reapply = false;
        bool repreview = false;
        std::optional<SweepSpec> pendingSweep;
        std::optional<Stroke> pendingStroke;
    };
    struct Result {
        std::shared_ptr<const TissueState> base, current, preview;
        bool baseChanged = false, currentChanged = false, previewChanged = false;
        bool loadFailed = false, cancelled = false;
        QString key; ///< tissueKey of a newly loaded base
        QString error, previewError;
    };

    void onDocumentReset();
    void schedule(bool reload, bool reapply, bool repreview);
    void startNext();
    void finish(Result result);
    static Result compute(const Request& request, std::shared_ptr<const TissueState> base,
                          std::shared_ptr<const TissueState> current, const std::atomic<bool>& cancel);

    ScenarioDocument& m_document;
    std::shared_ptr<const TissueState> m_base, m_current, m_preview;
    QString m_baseKey;     ///< what the base was loaded from (tissue spec and folder)
    QString m_loadingKey;  ///< what the running or queued load loads
    std::optional<SweepSpec> m_pendingSweep;
    std::optional<Stroke> m_pendingStroke;
    QString m_error, m_previewError;

    std::optional<Request> m_queued;
    bool m_startPosted = false; ///< a start of the queued request is posted
    bool m_dropRunning = false; ///< the running job's result belongs to a closed document
    bool m_reframe = false;     ///< a new document reuses the base: say baseChanged once cut
    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
};

} // namespace resect
