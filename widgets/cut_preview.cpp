#include "widgets/cut_preview.h"

#include "core/mesh/stable_time_step.h"
#include "scenario/scenario_sweeps.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QMetaObject>

#include <algorithm>
#include <exception>
#include <numeric>
#include <utility>

namespace resect {

namespace {

/// The sweep of a pending cut, resolved against the scenario (its tool and folder) as the
/// document will resolve it once the cut is added (scenario_sweeps.h).
Status pendingSweep(const Scenario& scenario, const std::optional<SweepSpec>& sweep,
                    const std::optional<Stroke>& stroke, SweepSurface& out) {
    Scenario copy = scenario;
    if (stroke) {
        copy.strokes.push_back(*stroke);
        return strokeSweep(copy, static_cast<int>(copy.strokes.size()) - 1, out);
    }
    copy.sweeps = {*sweep};
    std::vector<SweepSurface> sweeps;
    if (Status s = explicitSweeps(copy, sweeps); !s.ok())
        return s;
    out = std::move(sweeps.front());
    return Status::success();
}

} // namespace

CutPreview::CutPreview(ScenarioDocument& document, TissueSession& session, QObject* parent)
    : QObject(parent), m_document(document), m_session(session) {
    connect(&m_document, &ScenarioDocument::documentReset, this, &CutPreview::discard);
    connect(&m_session, &TissueSession::currentChanged, this, &CutPreview::request);
}

CutPreview::~CutPreview() {
    m_cancel = true;
    if (m_worker.joinable())
        m_worker.join();
}

void CutPreview::setPendingSweep(const SweepSpec& sweep) {
    m_stroke.reset();
    m_sweep = sweep;
    request();
    emit changed();
}

void CutPreview::setPendingStroke(const Stroke& stroke) {
    m_sweep.reset();
    m_stroke = stroke;
    request();
    emit changed();
}

void CutPreview::discard() {
    const bool had = hasPending() || m_preview || !m_error.isEmpty();
    m_sweep.reset();
    m_stroke.reset();
    m_preview.reset();
    m_error.clear();
    // Whatever runs or waits is for the dropped cut.
    ++m_request;
    m_cancel = true;
    m_queued.reset();
    if (had)
        emit changed();
}

QString CutPreview::applyBlocker() const {
    if (!hasPending())
        return tr("There is no cut to apply: draw a sweep or record a stroke first.");
    if (!m_error.isEmpty())
        return tr("The cut cannot be applied: %1").arg(m_error);
    if (!isReady() || m_session.isBusy())
        return tr("The preview of the cut is not ready yet: apply it once it is shown.");
    return {};
}

bool CutPreview::apply(QString* error) {
    if (const QString reason = applyBlocker(); !reason.isEmpty()) {
        if (error)
            *error = reason;
        return false;
    }
    const std::optional<SweepSpec> sweep = std::move(m_sweep);
    const std::optional<Stroke> stroke = std::move(m_stroke);
    // The pending cut becomes document state: the session derives the new current state from
    // it (only the new cut is cut, on a copy of current).
    discard();
    if (stroke)
        m_document.addStroke(*stroke);
    else
        m_document.addSweep(*sweep);
    return true;
}

bool CutPreview::waitForIdle(int ms) {
    QDeadlineTimer deadline(ms);
    while (isBusy() || m_session.isBusy()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
    return true;
}

void CutPreview::request() {
    if (!hasPending())
        return;
    ++m_request;
    m_cancel = true; // a running computation is for an older request
    const auto current = m_session.current();
    if (!current) {
        // No tissue (yet): the preview follows when the session publishes one.
        m_queued.reset();
        if (m_preview || !m_error.isEmpty()) {
            m_preview.reset();
            m_error.clear();
            emit changed();
        }
        return;
    }
    m_queued = Request{m_request, m_document.scenario(), current, m_sweep, m_stroke};
    // Started from the event loop: several edits in a row (a handle dragged) make one request.
    if (!m_startPosted && !m_worker.joinable()) {
        m_startPosted = true;
        QMetaObject::invokeMethod(
            this,
            [this] {
                m_startPosted = false;
                startNext();
            },
            Qt::QueuedConnection);
    }
}

void CutPreview::startNext() {
    if (!m_queued || m_worker.joinable())
        return;
    Request request = std::move(*m_queued);
    m_queued.reset();
    m_cancel = false;
    m_worker = std::thread([this, request = std::move(request)] {
        Result result;
        result.id = request.id;
        try {
            result = compute(request, m_cancel);
        } catch (const std::exception& e) {
            result.error = tr("Internal error: %1").arg(QString::fromUtf8(e.what()));
        } catch (...) {
            result.error = tr("Internal error");
        }
        QMetaObject::invokeMethod(
            this, [this, result = std::move(result)]() mutable { finish(std::move(result)); },
            Qt::QueuedConnection);
    });
    emit busyChanged(true);
}

CutPreview::Result CutPreview::compute(const Request& request, const std::atomic<bool>& cancel) {
    Result result;
    result.id = request.id;
    SweepSurface sweep;
    if (Status s = pendingSweep(request.scenario, request.sweep, request.stroke, sweep); !s.ok()) {
        result.error = QString::fromStdString(s.message());
        return result;
    }
    auto state = std::make_shared<TissueState>(*request.current);
    state->clearCutFigures();
    const CutStageCallback proceed = [&cancel](CutStage) { return !cancel.load(); };
    if (Status s = state->cut(sweep, request.current->applied.options, proceed); !s.ok()) {
        result.cancelled = cancel.load();
        result.error = QString::fromStdString(s.message());
        return result;
    }
    state->settle();
    if (warningsOf(request.current.get(), state.get(), request.current->applied.options).any()) {
        // The tets to inspect: those whose own step is smallest.
        const std::vector<double> steps =
            tetStableTimeSteps(state->mesh(), state->tissue.material());
        std::vector<int> order(steps.size());
        std::iota(order.begin(), order.end(), 0);
        const auto count = std::min<std::size_t>(kStepLimitingTets, order.size());
        std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count),
                          order.end(), [&](int a, int b) { return steps[a] < steps[b]; });
        order.resize(count);
        state->stepLimitingTets = std::move(order);
    }
    result.preview = std::move(state);
    return result;
}

PreviewWarnings CutPreview::warningsOf(const TissueState* current, const TissueState* preview,
                                       const CutOptions& options) {
    PreviewWarnings w;
    if (!current || !preview)
        return w;
    if (preview->stableDt > 0 && current->stableDt > 0)
        w.stepDrop = current->stableDt / preview->stableDt;
    w.stepDropped = w.stepDrop > kStepDropWarning;
    const CutStats& c = preview->cutStats;
    w.refusedSnaps = c.refusedSnaps;
    w.snapsAllRefused = options.snap && c.refusedSnaps > 0 && c.snappedNodes == 0;
    return w;
}

PreviewWarnings CutPreview::warnings() const {
    const auto current = m_session.current();
    if (!m_preview || !current)
        return {};
    return warningsOf(current.get(), m_preview.get(), m_preview->applied.options);
}

void CutPreview::finish(Result result) {
    if (m_worker.joinable())
        m_worker.join();
    // Only the latest request's result is shown; a superseded or cancelled one is dropped.
    if (result.id == m_request && !result.cancelled && hasPending()) {
        m_preview = std::move(result.preview);
        m_error = std::move(result.error);
        m_shownRequest = result.id;
        emit changed();
    }
    if (m_queued)
        startNext();
    if (!isBusy())
        emit busyChanged(false);
}

} // namespace resect
