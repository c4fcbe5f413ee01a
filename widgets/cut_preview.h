#pragma once
// CutPreview: the pending cut (a sweep being drawn or a stroke just recorded) that is not in
// the document yet, and its live, non-destructive preview.
//
// The preview is a TissueState: a copy of the session's current state (TissueSession::
// current()) cut by the pending sweep through Tissue::cut, with current's cut settings. It is
// computed on this object's own worker thread and never on the GUI thread: the latest request
// wins (a running computation is cancelled through the cut's stage callback and its result
// dropped), and the preview follows both the pending cut (setPendingSweep/Stroke) and the
// current state (the session's currentChanged, which also follows the cut settings). While a
// new preview is computed the previous one stays on show.
//
// apply() adds the pending cut to the document as one undoable edit; the session then derives
// the new current state from the document. A new document drops the pending cut.
//
// Warnings (issue 19, "cuts that wreck the simulation go unnoticed"): a preview whose stable
// time step is more than kStepDropWarning times smaller than current's, or whose snapping
// refused every cut node, warns (warnings()); its stepLimitingTets then name the tets that
// limit the step, worst first (computed on the worker with the preview).

#include "scenario/scenario_document.h"
#include "widgets/tissue_state.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <thread>

namespace resect {

class ScenarioDocument;
class TissueSession;

/// What in a preview may wreck the simulation.
struct PreviewWarnings {
    double stepDrop = 1;          ///< current's stable step over the preview's (> 1: smaller)
    bool stepDropped = false;     ///< stepDrop > CutPreview::kStepDropWarning
    bool snapsAllRefused = false; ///< snapping was on and refused every cut node (>= 1)
    int refusedSnaps = 0;
    bool any() const { return stepDropped || snapsAllRefused; }
};

class CutPreview : public QObject {
    Q_OBJECT

public:
    /// A preview warns when it divides the stable time step by more than this.
    static constexpr double kStepDropWarning = 10.0;
    /// How many step-limiting tets a warning preview names (TissueState::stepLimitingTets).
    static constexpr int kStepLimitingTets = 5;

    /// The warnings of `preview`, cut from `current` with `options` (none when either is null).
    static PreviewWarnings warningsOf(const TissueState* current, const TissueState* preview,
                                      const CutOptions& options);
    /// The warnings of the preview on show (against the session's current state).
    PreviewWarnings warnings() const;

    CutPreview(ScenarioDocument& document, TissueSession& session, QObject* parent = nullptr);
    /// Cancels the worker and waits for it (at most the current stage of one cut).
    ~CutPreview() override;

    /// Sets the pending cut (replacing any other) and schedules its preview.
    void setPendingSweep(const SweepSpec& sweep);
    void setPendingStroke(const Stroke& stroke);
    bool hasPending() const { return m_sweep.has_value() || m_stroke.has_value(); }
    /// Drops the pending cut and its preview.
    void discard();

    /// The preview of the pending cut on the current state, or null (none pending, not
    /// computed yet, or failed).
    std::shared_ptr<const TissueState> preview() const { return m_preview; }
    /// Why the preview of the pending cut could not be made (empty otherwise).
    const QString& error() const { return m_error; }
    /// True when the preview on show is that of the pending cut on the session's current
    /// state (no newer computation is due).
    bool isReady() const { return m_preview && m_shownRequest == m_request; }

    /// True when apply() would add the pending cut: its preview on the session's current state
    /// is shown and succeeded, and the session is not deriving a newer state (Apply is
    /// enabled exactly then: it follows changed() and the session's busyChanged()).
    bool canApply() const { return applyBlocker().isEmpty(); }
    /// Why apply() would refuse now, as the cut panel shows it; empty when canApply().
    QString applyBlocker() const;

    /// Adds the pending cut to the document (one undoable edit: addStroke or addSweep) and
    /// clears it. False, with the reason (applyBlocker) in `error` and the document untouched,
    /// if there is no pending cut, its preview failed, or it is not ready yet.
    bool apply(QString* error = nullptr);

    /// True while the worker runs or a request waits for it.
    bool isBusy() const { return m_worker.joinable() || m_startPosted || m_queued.has_value(); }
    /// Runs the event loop until the session and this object are idle, or `ms` passed (tests,
    /// the command line's --screenshot). True if idle.
    bool waitForIdle(int ms);

signals:
    /// The pending cut, its preview or its error changed.
    void changed();
    void busyChanged(bool busy);

private:
    struct Request {
        std::uint64_t id = 0;
        Scenario scenario; ///< for the pending cut's sweep (the tool, the folder of sweep files)
        std::shared_ptr<const TissueState> current;
        std::optional<SweepSpec> sweep;
        std::optional<Stroke> stroke;
    };
    struct Result {
        std::uint64_t id = 0;
        std::shared_ptr<const TissueState> preview;
        QString error;
        bool cancelled = false;
    };

    /// Schedules a new preview of the pending cut on the session's current state.
    void request();
    void startNext();
    void finish(Result result);
    static Result compute(const Request& request, const std::atomic<bool>& cancel);

    ScenarioDocument& m_document;
    TissueSession& m_session;
    std::optional<SweepSpec> m_sweep;
    std::optional<Stroke> m_stroke;
    std::shared_ptr<const TissueState> m_preview;
    QString m_error;

    std::uint64_t m_request = 0;      ///< id of the latest request (results of others are dropped)
    std::uint64_t m_shownRequest = 0; ///< id of the request whose result is on show
    std::optional<Request> m_queued;
    bool m_startPosted = false;
    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
};

} // namespace resect
