#include "widgets/tissue_session.h"

#include "core/mesh/stable_time_step.h"
#include "core/mesh/topology.h"
#include "scenario/scenario_run.h"
#include "scenario/scenario_save.h"
#include "scenario/scenario_sweeps.h"
#include "widgets/scenario_document.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QMetaObject>

#include <exception>
#include <utility>

namespace resect {

namespace {

/// What the base is loaded from: the first tissue's source fields and the folder relative
/// paths are resolved against. Two documents with equal keys mesh to the same tissue.
QString tissueKey(const Scenario& scenario) {
    if (scenario.tissues.empty())
        return {};
    const TissueSpec& t = scenario.tissues.front();
    QJsonObject key;
    key["surface"] = QString::fromStdString(t.surface);
    key["mesh"] = QString::fromStdString(t.mesh);
    key["edge_length"] = t.meshing.edgeLength;
    key["seed"] = static_cast<double>(t.meshing.seed);
    key["density"] = t.material.density;
    key["stiffness"] = t.material.stiffness;
    key["damping"] = t.material.damping;
    key["base"] = QString::fromStdString(scenario.baseDir);
    return QString::fromUtf8(QJsonDocument(key).toJson(QJsonDocument::Compact));
}

/// Fills the measures of a state from its mesh.
void measure(TissueState& state, const Material& material) {
    state.quality = summarizeQuality(state.mesh);
    state.stableDt = state.mesh.empty() ? 0 : stableTimeStep(state.mesh, material).dt;
    state.pieces = state.mesh.empty() ? 0 : connectedComponents(state.mesh).count;
}

/// Cuts `state` (a copy being built) along `sweep`, keeping schemes, stats and the surface in
/// step. On failure `state` may be partly changed: the caller drops it.
Status cutState(TissueState& state, HybridCutter& cutter, const SweepSurface& sweep, const CutOptions& options) {
    CutResult result;
    if (Status s = cutter.cut(sweep, options, result); !s.ok())
        return s;
    const CutChanges& changes = result.changes;
    state.schemes.resize(state.mesh.tetCount(), Scheme::None);
    for (int t : changes.modifiedTets)
        if (const Scheme s = changes.schemeOf(t); s != Scheme::None)
            state.schemes[t] = s;
    for (std::size_t i = 0; i < changes.parentOfNewTet.size(); ++i) {
        const int parent = changes.parentOfNewTet[i];
        const Scheme s = changes.schemeOf(parent);
        state.schemes[changes.firstNewTet + static_cast<int>(i)] = s != Scheme::None ? s : state.schemes[parent];
    }
    state.cutStats += result.stats;
    if (!state.surface.empty()) {
        EmbeddedCut ec;
        if (Status s = state.surface.cut(state.mesh, changes, sweep, &ec); !s.ok())
            return Status::error("cutting the surface: " + s.message());
        state.surfaceCutMs += ec.rebindMs + ec.cutMs + ec.bindNewMs;
        state.surfaceCapTriangles += ec.surface.capTriangles;
    }
    ++state.cuts;
    return Status::success();
}

/// The sweep of a pending cut, resolved against the scenario (its tool and folder).
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

TissueSession::TissueSession(ScenarioDocument& document, QObject* parent)
    : QObject(parent), m_document(document) {
    connect(&m_document, &ScenarioDocument::documentReset, this, &TissueSession::onDocumentReset);
    connect(&m_document, &ScenarioDocument::cutSettingsChanged, this, [this] { schedule(false, true, true); });
    connect(&m_document, &ScenarioDocument::strokesChanged, this, [this] { schedule(false, true, true); });
    connect(&m_document, &ScenarioDocument::sweepsChanged, this, [this] { schedule(false, true, true); });
    if (!m_document.scenario().tissues.empty())
        onDocumentReset();
}

TissueSession::~TissueSession() {
    m_cancel = true;
    if (m_worker.joinable())
        m_worker.join();
}

void TissueSession::onDocumentReset() {
    m_pendingSweep.reset();
    m_pendingStroke.reset();
    m_previewError.clear();
    if (m_preview) {
        m_preview.reset();
        emit previewChanged();
    }
    const QString key = tissueKey(m_document.scenario());
    if (key.isEmpty()) {
        // A closed document: nothing to show; whatever is running is dropped.
        m_cancel = true;
        m_dropRunning = m_worker.joinable();
        m_queued.reset();
        m_base.reset();
        m_current.reset();
        m_baseKey.clear();
        m_loadingKey.clear();
        emit baseChanged();
        emit currentChanged();
        return;
    }
    const bool reload = key != m_baseKey || !m_base;
    if (reload && m_worker.joinable() && key != m_loadingKey)
        m_cancel = true; // the running load is for another tissue
    // The same tissue as loaded: it is reused, but the views still reframe for the new
    // document once its cuts are applied.
    m_reframe = !reload;
    schedule(reload, true, false);
}

void TissueSession::setPendingSweep(const SweepSpec& sweep) {
    m_pendingStroke.reset();
    m_pendingSweep = sweep;
    schedule(false, false, true);
}

void TissueSession::setPendingStroke(const Stroke& stroke) {
    m_pendingSweep.reset();
    m_pendingStroke = stroke;
    schedule(false, false, true);
}

void TissueSession::discardPending() {
    const bool had = hasPending() || m_preview || !m_previewError.isEmpty();
    m_pendingSweep.reset();
    m_pendingStroke.reset();
    m_preview.reset();
    m_previewError.clear();
    if (m_queued)
        m_queued->repreview = false;
    if (had)
        emit previewChanged();
}

bool TissueSession::applyPending(QString* error) {
    if (!hasPending()) {
        if (error)
            *error = tr("There is no cut to apply: draw a sweep or record a stroke first.");
        return false;
    }
    SweepSurface check;
    if (Status s = pendingSweep(m_document.scenario(), m_pendingSweep, m_pendingStroke, check); !s.ok()) {
        if (error)
            *error = tr("The cut cannot be applied: %1").arg(QString::fromStdString(s.message()));
        return false;
    }
    const std::optional<SweepSpec> sweep = std::move(m_pendingSweep);
    const std::optional<Stroke> stroke = std::move(m_pendingStroke);
    m_pendingSweep.reset();
    m_pendingStroke.reset();
    // The preview is dropped; the document change below re-applies every cut, this one
    // included, and publishes it as the current state.
    m_preview.reset();
    m_previewError.clear();
    emit previewChanged();
    if (stroke)
        m_document.addStroke(*stroke);
    else
        m_document.addSweep(*sweep);
    return true;
}

void TissueSession::cancel() {
    m_cancel = true;
    m_queued.reset();
}

bool TissueSession::waitForIdle(int ms) {
    QDeadlineTimer deadline(ms);
    while (isBusy()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
    return true;
}

void TissueSession::schedule(bool reload, bool reapply, bool repreview) {
    if (m_document.scenario().tissues.empty())
        return;
    if (!m_queued)
        m_queued = Request{};
    Request& r = *m_queued;
    r.scenario = m_document.scenario();
    r.reload = r.reload || reload;
    r.reapply = r.reapply || reapply || reload;
    r.repreview = (r.repreview || repreview || r.reapply) && hasPending();
    r.pendingSweep = m_pendingSweep;
    r.pendingStroke = m_pendingStroke;
    if (r.reload)
        m_loadingKey = tissueKey(r.scenario);
    // Started from the event loop, so that the several signals of one document change (a
    // new document announces every part) make one request.
    if (!m_startPosted && !m_worker.joinable()) {
        m_startPosted = true;
        QMetaObject::invokeMethod(this, [this] {
            m_startPosted = false;
            startNext();
        }, Qt::QueuedConnection);
    }
}

void TissueSession::startNext() {
    if (!m_queued || m_worker.joinable())
        return;
    Request request = std::move(*m_queued);
    m_queued.reset();
    if (!request.reload && !request.reapply && !request.repreview)
        return;
    m_cancel = false;
    m_worker = std::thread([this, request = std::move(request), base = m_base, current = m_current]() mutable {
        Result result;
        try {
            result = compute(request, std::move(base), std::move(current), m_cancel);
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

TissueSession::Result TissueSession::compute(const Request& request, std::shared_ptr<const TissueState> base,
                                             std::shared_ptr<const TissueState> current,
                                             const std::atomic<bool>& cancel) {
    Result result;
    const Scenario& scenario = request.scenario;
    const TissueSpec& tissue = scenario.tissues.front();
    const Material material = tissue.material.toMaterial();
    const QString name = QString::fromStdString(tissue.name);

    if (request.reload || !base) {
        auto state = std::make_shared<TissueState>();
        state->tissueName = name;
        TriangleSurface surface;
        if (Status s = loadTissue(scenario, tissue, state->mesh, surface, &cancel); !s.ok()) {
            result.error = QString::fromStdString(s.message());
            result.loadFailed = true;
            result.cancelled = cancel.load();
            return result;
        }
        if (!surface.triangles.empty())
            if (Status s = state->surface.bind(state->mesh, std::move(surface)); !s.ok()) {
                result.error = tr("tissue '%1': binding the surface: %2").arg(name, QString::fromStdString(s.message()));
                result.loadFailed = true;
                return result;
            }
        state->schemes.assign(state->mesh.tetCount(), Scheme::None);
        measure(*state, material);
        base = state;
        result.base = base;
        result.baseChanged = true;
        result.key = tissueKey(scenario);
    }

    const CutOptions options = toCutOptions(scenario.cut, tissue.material);
    if (request.reapply || !current || result.baseChanged) {
        std::vector<ScenarioCut> cuts;
        if (Status s = scenarioCuts(scenario, cuts); !s.ok()) {
            result.error = QString::fromStdString(s.message());
            return result;
        }
        auto state = std::make_shared<TissueState>(*base);
        state->cutStats = {};
        state->cuts = 0;
        if (!cuts.empty()) {
            HybridCutter cutter(state->mesh);
            for (const ScenarioCut& cut : cuts) {
                if (cancel) {
                    result.cancelled = true;
                    return result;
                }
                if (Status s = cutState(*state, cutter, cut.sweep, options); !s.ok()) {
                    result.error = tr("%1: %2").arg(QString::fromStdString(cut.label), QString::fromStdString(s.message()));
                    return result;
                }
            }
            measure(*state, material);
        }
        current = state;
        result.current = current;
        result.currentChanged = true;
    }

    if (request.repreview && (request.pendingSweep || request.pendingStroke)) {
        result.previewChanged = true;
        SweepSurface sweep;
        if (Status s = pendingSweep(scenario, request.pendingSweep, request.pendingStroke, sweep); !s.ok()) {
            result.previewError = QString::fromStdString(s.message());
            return result;
        }
        auto state = std::make_shared<TissueState>(*current);
        state->cutStats = {};
        state->surfaceCutMs = 0;
        state->surfaceCapTriangles = 0;
        HybridCutter cutter(state->mesh);
        if (Status s = cutState(*state, cutter, sweep, options); !s.ok()) {
            result.previewError = QString::fromStdString(s.message());
            return result;
        }
        measure(*state, material);
        result.preview = state;
    }
    return result;
}

void TissueSession::finish(Result result) {
    if (m_worker.joinable())
        m_worker.join();
    // A newer load replaces whatever this run produced; a newer re-application replaces its
    // current state and preview; a newer preview replaces its preview.
    const bool superseded = m_dropRunning || (m_queued && m_queued->reload);
    m_dropRunning = false;
    bool emitBase = false, emitCurrent = false, emitPreview = false, emitFailed = false;
    if (!superseded) {
        if (result.baseChanged && result.base) {
            m_base = result.base;
            m_baseKey = result.key;
            emitBase = true;
        }
        if (!result.error.isEmpty()) {
            m_error = result.error;
            emitFailed = !result.cancelled;
            if (result.loadFailed) {
                // The document's tissue could not be loaded: nothing of the old one stays.
                m_base.reset();
                m_current.reset();
                m_preview.reset();
                m_baseKey.clear();
                m_queued.reset();
                emitBase = emitCurrent = emitPreview = true;
            }
        } else {
            m_error.clear();
        }
        if (result.currentChanged && result.current && !(m_queued && m_queued->reapply)) {
            m_current = result.current;
            emitCurrent = true;
            if (m_reframe) {
                emitBase = true;
                m_reframe = false;
            }
        }
        if (result.previewChanged && hasPending() && !(m_queued && m_queued->repreview)) {
            m_preview = result.preview;
            m_previewError = result.previewError;
            emitPreview = true;
        }
    }
    if (emitBase)
        emit baseChanged();
    if (emitCurrent)
        emit currentChanged();
    if (emitPreview)
        emit previewChanged();
    if (emitFailed)
        emit failed(m_error);
    if (m_queued)
        startNext();
    if (!isBusy())
        emit busyChanged(false);
}

} // namespace resect
