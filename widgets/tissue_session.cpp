#include "widgets/tissue_session.h"

#include "scenario/replay.h"
#include "scenario/scenario_load.h"
#include "scenario/scenario_run.h"
#include "scenario/scenario_sweeps.h"
#include "widgets/scenario_document.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QMetaObject>

#include <algorithm>
#include <exception>
#include <utility>

namespace resect {

namespace {

/// What the base is loaded from: the first tissue's source fields and material, and the
/// folder relative paths are resolved against. Two documents with equal keys load the same
/// mesh; their anchors (the nodes in the fixed regions) are set on it apart (anchoredBase),
/// so editing a fixed region never re-meshes.
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

/// `base` with the anchors of `scenario`'s fixed regions (regionAnchors): `base` itself when
/// it has them already, else a copy re-anchored (Tissue::setAnchors: the tissue makeBaseTissue
/// would make) under a new base id, so that every state derived from it is told apart.
Status anchoredBase(const Scenario& scenario, std::shared_ptr<const TissueState>& base) {
    const FixedSelection anchors = regionAnchors(scenario.tissues.front(), base->mesh());
    if (anchors.nodes == base->tissue.anchors().nodes() && anchors.box == base->tissue.anchors().box())
        return Status::success();
    auto state = std::make_shared<TissueState>(*base);
    if (Status s = state->tissue.setAnchors(anchors); !s.ok())
        return s;
    state->applied.baseId = newBaseId();
    base = std::move(state);
    return Status::success();
}

/// What a state is derived from, comparable with ==: the scenario without its metadata (an
/// edit of the title changes nothing derived) and with its relative paths resolved from the
/// root, so that saving to another folder (which rebases them) keeps states comparable.
Scenario derivationKey(const Scenario& scenario) {
    Scenario key = scenario;
    key.metadata = {};
    rebaseScenarioPaths(key, "/");
    return key;
}

/// How many verified states are remembered (enough for any undo history an author keeps).
constexpr std::size_t kMaxVerifiedStates = 500;

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
    // Effects do not change the tissue, but a state with bad effects would not load again.
    connect(&m_document, &ScenarioDocument::effectsChanged, this,
            [this] { schedule(false, false); });
    // Fixed regions change the anchors (what a cut resects) and what the fixed effect holds.
    connect(&m_document, &ScenarioDocument::fixedRegionsChanged, this,
            [this] { schedule(false, true); });
    if (!m_document.scenario().tissues.empty())
        onDocumentReset();
}

TissueSession::~TissueSession() {
    m_cancel = true;
    if (m_worker.joinable())
        m_worker.join();
}

QString TissueSession::saveBlocker() const {
    if (m_document.scenario().tissues.empty())
        return tr("There is no tissue to save.");
    if (m_worker.joinable() || m_startPosted || m_queued)
        return tr("The tissue is still being derived from the last edit: save once it is shown.");
    if (!m_error.isEmpty())
        return tr("The document's tissue or cuts fail: %1").arg(m_error);
    if (!m_current || !isVerified(m_document.scenario()))
        return tr("The tissue has not been derived yet.");
    return {};
}

void TissueSession::onDocumentReset() {
    ++m_generation;
    m_verified.clear();
    if (m_trialResult &&
        derivationKey(m_trialResult->scenario) == derivationKey(m_document.scenario())) {
        Result trial = std::move(*m_trialResult);
        m_trialResult.reset();
        adoptTrial(std::move(trial));
        return;
    }
    m_trialResult.reset();
    const QString key = tissueKey(m_document.scenario());
    if (key.isEmpty()) {
        // A closed document: nothing to show; whatever is running for it is dropped.
        if (m_worker.joinable() && !m_trialRunning)
            m_cancel = true;
        m_queued.reset();
        m_base.reset();
        m_current.reset();
        m_currentKey.reset();
        m_baseKey.clear();
        m_loadingKey.clear();
        m_error.clear();
        emit baseChanged();
        emit currentChanged();
        return;
    }
    const bool reload = key != m_baseKey || !m_base;
    if (reload && m_worker.joinable() && !m_trialRunning && key != m_loadingKey)
        m_cancel = true; // the running load is for another tissue
    // The same tissue as loaded: it is reused, but the views still reframe for the new
    // document once its cuts are applied.
    m_reframe = !reload;
    schedule(reload, true);
}

void TissueSession::adoptTrial(Result trial) {
    // Whatever runs or waits for the previous document is superseded (the generation moved
    // on, so a running job's result is dropped); the trial's states are this document's.
    if (m_worker.joinable() && !m_trialRunning)
        m_cancel = true;
    m_queued.reset();
    m_base = std::move(trial.base);
    m_baseKey = trial.key;
    m_loadingKey.clear();
    m_current = std::move(trial.current);
    m_currentKey = derivationKey(m_document.scenario());
    m_error.clear();
    m_reframe = false;
    addVerified(m_document.scenario());
    emit baseChanged();
    emit currentChanged();
}

void TissueSession::cancel() {
    m_cancel = true;
    m_queued.reset();
    if (m_queuedTrial) {
        // Never started: it ends here.
        const std::uint64_t id = m_queuedTrial->trial;
        m_queuedTrial.reset();
        QMetaObject::invokeMethod(
            this, [this, id] { emit trialFinished(id, false, tr("Opening was cancelled.")); },
            Qt::QueuedConnection);
    }
}

std::uint64_t TissueSession::trial(const Scenario& scenario) {
    Request r;
    r.scenario = scenario;
    r.trial = ++m_lastTrial;
    const QString key = tissueKey(scenario);
    r.reload = key.isEmpty() || key != m_baseKey || !m_base;
    r.reapply = true;
    if (m_trialRunning)
        m_cancel = true; // the running trial is for an older open
    m_queuedTrial = std::move(r);
    m_trialResult.reset();
    postStart();
    return m_lastTrial;
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
    // The document came back to the state on show (an edit refused, an adopted trial): it
    // derived, nothing to do.
    if (!reload && !m_reframe && !m_worker.joinable() && !m_queued && m_current && m_currentKey &&
        *m_currentKey == derivationKey(m_document.scenario())) {
        m_error.clear();
        return;
    }
    if (!m_queued)
        m_queued = Request{};
    Request& r = *m_queued;
    r.scenario = m_document.scenario();
    r.reload = r.reload || reload;
    r.reapply = r.reapply || reapply || reload;
    r.generation = m_generation;
    if (r.reload)
        m_loadingKey = tissueKey(r.scenario);
    postStart();
}

void TissueSession::postStart() {
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
    if (m_worker.joinable())
        return;
    // A trial first: the author waits for the file to open.
    std::optional<Request>& next = m_queuedTrial ? m_queuedTrial : m_queued;
    if (!next)
        return;
    Request request = std::move(*next);
    next.reset();
    std::shared_ptr<const TissueState> base = m_base, current = m_current;
    if (request.trial != 0) {
        m_trialRunning = true;
        if (request.reload)
            base.reset(), current.reset();
    }
    m_cancel = false;
    m_worker = std::thread([this, request = std::move(request), base = std::move(base),
                            current = std::move(current)]() mutable {
        // Progress goes to this thread, as the result does (finish()), and is judged there.
        const auto progress = [this, generation = request.generation,
                               trial = request.trial](const MeshingProgress& p) {
            QMetaObject::invokeMethod(
                this, [this, generation, trial, p] { reportProgress(generation, trial, p); },
                Qt::QueuedConnection);
        };
        Result result;
        try {
            result = compute(request, std::move(base), std::move(current), m_cancel, progress);
        } catch (const std::exception& e) {
            result.error = tr("Internal error: %1").arg(QString::fromUtf8(e.what()));
        } catch (...) {
            result.error = tr("Internal error");
        }
        result.scenario = std::move(request.scenario);
        result.generation = request.generation;
        result.trial = request.trial;
        QMetaObject::invokeMethod(
            this, [this, result = std::move(result)]() mutable { finish(std::move(result)); },
            Qt::QueuedConnection);
    });
    emit busyChanged(true);
}

TissueSession::Result
TissueSession::compute(const Request& request, std::shared_ptr<const TissueState> base,
                       std::shared_ptr<const TissueState> current, const std::atomic<bool>& cancel,
                       const std::function<void(const MeshingProgress&)>& progress) {
    Result result;
    const Scenario& scenario = request.scenario;
    if (scenario.tissues.empty()) {
        result.error = tr("the scenario has no tissue");
        result.loadFailed = true;
        return result;
    }
    const TissueSpec& tissue = scenario.tissues.front();
    const QString name = QString::fromStdString(tissue.name);

    // As loading the saved file would check it (and saving does).
    {
        ScenarioDiagnostics diag;
        if (!validateScenario(scenario, diag).ok()) {
            result.error = QString::fromStdString(diag.firstError(""));
            if (result.error.startsWith(QLatin1String(": ")))
                result.error.remove(0, 2);
            // Without its tissue loaded, nothing of this document can be shown.
            result.loadFailed = request.reload || !base;
            return result;
        }
    }

    if (request.reload || !base) {
        TetMesh mesh;
        TriangleSurface surface;
        MeshReadReport read;
        if (Status s = loadTissue(scenario, tissue, mesh, surface, &cancel, progress, &read); !s.ok()) {
            result.error = QString::fromStdString(s.message());
            result.loadFailed = true;
            result.cancelled = cancel.load();
            return result;
        }
        auto state = std::make_shared<TissueState>();
        state->tissueName = name;
        if (!read.dropped.empty() || !read.notes.empty())
            state->readNote = QString::fromStdString(read.summary());
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

    // The anchors of the document's fixed regions: an edit of a region re-anchors the loaded
    // mesh instead of loading it again, and every cut is applied again (anchors decide what
    // a cut resects).
    {
        const std::shared_ptr<const TissueState> loaded = base;
        if (Status s = anchoredBase(scenario, base); !s.ok()) {
            result.error = QString::fromStdString("tissue '" + tissue.name + "': " + s.message());
            result.loadFailed = result.baseChanged;
            return result;
        }
        if (base != loaded) {
            current.reset();
            result.base = base;
            result.baseReanchored = !result.baseChanged;
        }
    }

    // What starting the simulation would refuse, as replay would (the fixed effect holding no
    // node, parameters an effect does not take): such a state does not derive either.
    if (Status s = checkSimulation(scenario, tissue, base->tissue); !s.ok()) {
        result.error = QString::fromStdString(s.message());
        result.loadFailed = result.baseChanged;
        return result;
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
                // A tissue loaded for this state is of no use without its cuts.
                result.loadFailed = result.baseChanged;
                return result;
            }
        }
        state->settle();
        result.current = state;
        result.currentChanged = true;
    }
    // The base the states derive from, also when it was not loaded for them: a trial's is
    // adopted with them (a new document on the tissue already loaded keeps its base).
    if (!result.base) {
        result.base = base;
        result.key = tissueKey(scenario);
    }
    return result;
}

void TissueSession::finish(Result result) {
    if (m_worker.joinable())
        m_worker.join();
    if (result.trial != 0) {
        finishTrial(std::move(result));
    } else {
        // A result for an older document, or a newer load, replaces whatever this run produced; a
        // newer re-application replaces its current state.
        const bool superseded = result.generation != m_generation || (m_queued && m_queued->reload);
        bool emitBase = false, emitCurrent = false, emitFailed = false, emitRefused = false;
        if (superseded) {
            if (!result.cancelled && result.error.isEmpty() && result.generation == m_generation)
                addVerified(result.scenario); // a fact about that state, even if not shown
        } else if (result.cancelled) {
            // Not a failure of the state (it is derived again when the document asks); but a
            // load cancelled for this document leaves nothing of the previous one on show.
            if (result.loadFailed) {
                m_base.reset();
                m_current.reset();
                m_currentKey.reset();
                m_baseKey.clear();
                m_error = result.error;
                emitBase = emitCurrent = true;
            }
        } else {
            if (result.baseChanged && result.base) {
                m_base = result.base;
                m_baseKey = result.key;
                emitBase = true;
            }
            // The same mesh with other anchors: the views keep their framing (only current,
            // derived from it, is announced).
            if (result.baseReanchored && result.base && result.error.isEmpty())
                m_base = result.base;
            if (!result.error.isEmpty()) {
                m_error = result.error;
                if (result.loadFailed) {
                    // The document's tissue could not be loaded: nothing of the old one stays.
                    m_base.reset();
                    m_current.reset();
                    m_currentKey.reset();
                    m_baseKey.clear();
                    m_queued.reset();
                    emitBase = emitCurrent = emitFailed = true;
                } else {
                    // Reverting re-schedules the restored state, which clears the error.
                    emitRefused = refuse(result.scenario);
                    emitFailed = !emitRefused;
                }
            } else {
                m_error.clear();
                addVerified(result.scenario);
                // Validated only (an effect edit): the tissue on show is this state's.
                if (!result.currentChanged && m_current)
                    m_currentKey = derivationKey(result.scenario);
            }
            if (result.currentChanged && result.current && !(m_queued && m_queued->reapply)) {
                m_current = result.current;
                m_currentKey = derivationKey(result.scenario);
                emitCurrent = true;
                if (m_reframe) {
                    emitBase = true;
                    m_reframe = false;
                }
            }
        }
        const QString message = result.error;
        if (emitBase)
            emit baseChanged();
        if (emitCurrent)
            emit currentChanged();
        if (emitRefused)
            emit editRefused(message);
        if (emitFailed)
            emit failed(m_error);
    }
    if (m_queued || m_queuedTrial)
        startNext();
    if (!isBusy())
        emit busyChanged(false);
}

void TissueSession::reportProgress(std::uint64_t generation, std::uint64_t trial,
                                   const MeshingProgress& progress) {
    // Posted before the request's result, so the request still runs (or has just ended): it is
    // dropped, as finish() drops its result, when cancelled, replaced by a newer trial, made
    // for an older document or about to be replaced by a newer load.
    if (m_cancel.load())
        return;
    const bool superseded = trial != 0
                                ? trial != m_lastTrial
                                : generation != m_generation || (m_queued && m_queued->reload);
    if (superseded)
        return;
    emit loadProgress(stageText(progress), progress.fraction);
}

QString TissueSession::stageText(const MeshingProgress& progress) {
    QString stage;
    switch (progress.stage) {
    case MeshingStage::CheckingSurface:
        stage = tr("Checking the surface");
        break;
    case MeshingStage::Refining:
        stage = tr("Meshing (Delaunay refinement)");
        break;
    case MeshingStage::Perturbing:
        stage = tr("Removing slivers (perturbation)");
        break;
    case MeshingStage::Exuding:
        stage = tr("Removing slivers (exudation)");
        break;
    case MeshingStage::MatchingVolume:
        stage = tr("Matching the volume");
        break;
    case MeshingStage::CheckingQuality:
        stage = tr("Checking element quality");
        break;
    }
    if (progress.attempt > 1)
        stage =
            tr("%1 — attempt %2 of %3")
                .arg(stage, QString::number(progress.attempt), QString::number(progress.attempts));
    return stage;
}

void TissueSession::finishTrial(Result result) {
    m_trialRunning = false;
    if (result.trial != m_lastTrial)
        return; // a newer trial replaced it
    if (result.cancelled || !result.error.isEmpty()) {
        emit trialFinished(result.trial, false,
                           result.cancelled ? tr("Opening was cancelled.") : result.error);
        return;
    }
    const std::uint64_t id = result.trial;
    m_trialResult = std::move(result);
    emit trialFinished(id, true, QString());
}

bool TissueSession::refuse(const Scenario& failed) {
    if (!(derivationKey(failed) == derivationKey(m_document.scenario())))
        return false; // the document moved on: its newer state is derived next
    return m_document.revertTo([this](const Scenario& s) { return isVerified(s); });
}

void TissueSession::addVerified(const Scenario& scenario) {
    Scenario key = derivationKey(scenario);
    if (!m_verified.empty() && m_verified.back() == key)
        return;
    m_verified.push_back(std::move(key));
    if (m_verified.size() > kMaxVerifiedStates)
        m_verified.erase(m_verified.begin());
}

bool TissueSession::isVerified(const Scenario& scenario) const {
    const Scenario key = derivationKey(scenario);
    return std::find(m_verified.rbegin(), m_verified.rend(), key) != m_verified.rend();
}

} // namespace resect
