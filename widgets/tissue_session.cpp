#include "widgets/tissue_session.h"

#include "scenario/replay.h"
#include "scenario/scenario_run.h"
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

/// What the base is made from: the first tissue's source fields, material and fixed regions
/// (its anchors), and the folder relative paths are resolved against. Two documents with
/// equal keys give the same base.
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
    QJsonArray fixed;
    for (const FixedRegion& r : t.fixedRegions)
        fixed.append(QJsonArray{r.min.x(), r.min.y(), r.min.z(), r.max.x(), r.max.y(), r.max.z()});
    key["fixed_regions"] = fixed;
    key["base"] = QString::fromStdString(scenario.baseDir);
    return QString::fromUtf8(QJsonDocument(key).toJson(QJsonDocument::Compact));
}

/// The base tissue: the loaded mesh and surface made into a Tissue as replay makes it
/// (planLoadedTissue, makeTissue), so that the anchors are the nodes in the tissue's fixed
/// regions. The plan is made on the scenario without its cuts and effects: the base depends on
/// neither, and a bad cut or effect is reported where it is applied, not as a failed load.
Status makeBaseTissue(const Scenario& scenario, TetMesh mesh, TriangleSurface surface, Tissue& out) {
    Scenario tissueOnly = scenario;
    tissueOnly.strokes.clear();
    tissueOnly.sweeps.clear();
    tissueOnly.effects.clear();
    ReplayPlan plan;
    if (Status s = planLoadedTissue(tissueOnly, tissueOnly.tissues.front(), std::move(mesh), std::move(surface), plan);
        !s.ok())
        return s;
    return makeTissue(plan, out);
}

/// Asks `cancel` before every stage of a cut.
CutStageCallback cancellable(const std::atomic<bool>& cancel) {
    return [&cancel](CutStage) { return !cancel.load(); };
}

} // namespace

TissueSession::TissueSession(ScenarioDocument& document, QObject* parent)
    : QObject(parent), m_document(document) {
    connect(&m_document, &ScenarioDocument::documentReset, this, &TissueSession::onDocumentReset);
    connect(&m_document, &ScenarioDocument::cutSettingsChanged, this, [this] { schedule(false, true); });
    connect(&m_document, &ScenarioDocument::strokesChanged, this, [this] { schedule(false, true); });
    connect(&m_document, &ScenarioDocument::sweepsChanged, this, [this] { schedule(false, true); });
    if (!m_document.scenario().tissues.empty())
        onDocumentReset();
}

TissueSession::~TissueSession() {
    m_cancel = true;
    if (m_worker.joinable())
        m_worker.join();
}

void TissueSession::onDocumentReset() {
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
    schedule(reload, true);
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

void TissueSession::schedule(bool reload, bool reapply) {
    if (m_document.scenario().tissues.empty())
        return;
    if (!m_queued)
        m_queued = Request{};
    Request& r = *m_queued;
    r.scenario = m_document.scenario();
    r.reload = r.reload || reload;
    r.reapply = r.reapply || reapply || reload;
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
    if (!request.reload && !request.reapply)
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
    const QString name = QString::fromStdString(tissue.name);

    if (request.reload || !base) {
        TetMesh mesh;
        TriangleSurface surface;
        if (Status s = loadTissue(scenario, tissue, mesh, surface, &cancel); !s.ok()) {
            result.error = QString::fromStdString(s.message());
            result.loadFailed = true;
            result.cancelled = cancel.load();
            return result;
        }
        auto state = std::make_shared<TissueState>();
        state->tissueName = name;
        if (Status s = makeBaseTissue(scenario, std::move(mesh), std::move(surface), state->tissue); !s.ok()) {
            result.error = QString::fromStdString("tissue '" + tissue.name + "': " + s.message());
            result.loadFailed = true;
            return result;
        }
        state->applied.baseId = newBaseId();
        state->applied.options = toCutOptions(scenario.cut, tissue.material);
        state->settle();
        base = state;
        current.reset();
        result.base = base;
        result.baseChanged = true;
        result.key = tissueKey(scenario);
    }

    if (request.reapply || !current || result.baseChanged) {
        std::vector<ScenarioCut> cuts;
        if (Status s = scenarioCuts(scenario, cuts); !s.ok()) {
            result.error = QString::fromStdString(s.message());
            return result;
        }
        AppliedCuts wanted{base->applied.baseId, {}, toCutOptions(scenario.cut, tissue.material)};
        for (const ScenarioCut& cut : cuts)
            wanted.sweeps.push_back(cut.sweep);
        // Only the cuts the document added to current's, or all of them on the base.
        const bool extendsCurrent = current && appendedCuts(current->applied, wanted) >= 0;
        auto state = std::make_shared<TissueState>(extendsCurrent ? *current : *base);
        state->applied.options = wanted.options;
        for (std::size_t i = state->applied.sweeps.size(); i < cuts.size(); ++i) {
            if (Status s = state->cut(cuts[i].sweep, wanted.options, cancellable(cancel)); !s.ok()) {
                if (cancel) {
                    result.cancelled = true;
                    return result;
                }
                result.error = tr("%1: %2").arg(QString::fromStdString(cuts[i].label), QString::fromStdString(s.message()));
                return result;
            }
        }
        state->settle();
        result.current = state;
        result.currentChanged = true;
    }
    return result;
}

void TissueSession::finish(Result result) {
    if (m_worker.joinable())
        m_worker.join();
    // A newer load replaces whatever this run produced; a newer re-application replaces its
    // current state.
    const bool superseded = m_dropRunning || (m_queued && m_queued->reload);
    m_dropRunning = false;
    bool emitBase = false, emitCurrent = false, emitFailed = false;
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
                m_baseKey.clear();
                m_queued.reset();
                emitBase = emitCurrent = true;
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
    }
    if (emitBase)
        emit baseChanged();
    if (emitCurrent)
        emit currentChanged();
    if (emitFailed)
        emit failed(m_error);
    if (m_queued)
        startNext();
    if (!isBusy())
        emit busyChanged(false);
}

} // namespace resect
