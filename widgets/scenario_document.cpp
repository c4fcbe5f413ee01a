#include "widgets/scenario_document.h"

#include "widgets/scenario_commands.h"

#include "core/mesher/samples.h"
#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/scenario_load.h"
#include "scenario/scenario_save.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace resect {

namespace {

/// The default tool of a new document: a half loop of radius 1 in the tool's x-z plane,
/// opening upwards (as the bundled examples), 8 segments, scaled to 3.5 mm (7 mm wide).
ToolSpec defaultTool() {
    constexpr int kSegments = 8;
    ToolSpec tool;
    tool.name = "loop electrode";
    tool.size = 3.5;
    for (int i = 0; i <= kSegments; ++i) {
        const double a = std::numbers::pi * i / kSegments;
        tool.curve.emplace_back(std::cos(a), 0.0, -std::sin(a));
    }
    return tool;
}

QString fromStd(const std::string& s) {
    return QString::fromStdString(s);
}

std::string toStd(const QString& s) {
    return s.toStdString();
}

/// Every error of `diag`, one line each, "NAME: PATH: MESSAGE".
QString errorLines(const ScenarioDiagnostics& diag, const QString& name) {
    QStringList lines;
    for (const ScenarioIssue& issue : diag.issues()) {
        if (!issue.isError())
            continue;
        lines << (issue.path.empty() ? name + QStringLiteral(": ") + fromStd(issue.message)
                                     : name + QStringLiteral(": ") + fromStd(issue.path) +
                                           QStringLiteral(": ") + fromStd(issue.message));
    }
    if (diag.dropped() > 0)
        lines << name + QStringLiteral(": ... and %1 more problems").arg(diag.dropped());
    return lines.join(QLatin1Char('\n'));
}

void setError(QString* error, const QString& message) {
    if (error)
        *error = message;
}

} // namespace

ScenarioDocument::ScenarioDocument(QObject* parent) : QObject(parent) {
    connect(&m_undo, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
    connect(&m_autosaveTimer, &QTimer::timeout, this, [this] { autosaveNow(); });
}

// Leaves any autosave in place on purpose: see the header (a crash looks the same).
ScenarioDocument::~ScenarioDocument() = default;

QString ScenarioDocument::displayName() const {
    return m_filePath.isEmpty() ? tr("untitled") : QFileInfo(m_filePath).fileName();
}

// ---- Files -----------------------------------------------------------------------------

bool ScenarioDocument::newFromSample(const QString& name, QString* error) {
    Scenario s;
    if (!sampleScenario(name, s, error))
        return false;
    replace(std::move(s));
    return true;
}

bool ScenarioDocument::newFromAnatomy(const QString& path, QString* error) {
    Scenario s;
    if (!anatomyScenario(path, s, error))
        return false;
    replace(std::move(s));
    return true;
}

bool ScenarioDocument::open(const QString& path, QString* error) {
    Scenario loaded;
    if (!readScenario(path, loaded, error))
        return false;
    replace(std::move(loaded), path);
    return true;
}

bool ScenarioDocument::sampleScenario(const QString& name, Scenario& out, QString* error) {
    if (!sampleFromName(toStd(name))) {
        setError(error, tr("unknown sample \"%1\" (known: %2)")
                            .arg(name, fromStd([] {
                                     std::string all;
                                     for (const std::string& n : sampleNames())
                                         all += (all.empty() ? "" : ", ") + n;
                                     return all;
                                 }())));
        return false;
    }
    TissueSpec tissue;
    tissue.name = toStd(name);
    tissue.surface = "sample:" + toStd(name);
    out = newScenario(std::move(tissue));
    applySceneDefaults(out, sampleBaseRegion(*sampleFromName(toStd(name))));
    return true;
}

bool ScenarioDocument::anatomyScenario(const QString& path, Scenario& out, QString* error) {
    const QFileInfo info(path);
    if (!info.exists() || !info.isFile()) {
        setError(error, tr("%1: no such file").arg(path));
        return false;
    }
    const bool tetMesh = isTetMeshPath(QFile::encodeName(path).toStdString());
    TissueSpec tissue;
    tissue.name = toStd(info.completeBaseName().isEmpty() ? QStringLiteral("tissue") : info.completeBaseName());
    // Absolute until the first save, which rewrites it relative to the scenario's folder.
    (tetMesh ? tissue.mesh : tissue.surface) = toStd(info.absoluteFilePath());
    out = newScenario(std::move(tissue));
    return true;
}

bool ScenarioDocument::readScenario(const QString& path, Scenario& out, QString* error) {
    Scenario loaded;
    ScenarioDiagnostics diag;
    const Status status = loadScenario(toStd(path), loaded, diag);
    if (!status) {
        const QString lines = errorLines(diag, path);
        setError(error, lines.isEmpty() ? fromStd(status.message()) : lines);
        return false;
    }
    out = std::move(loaded);
    return true;
}

Scenario ScenarioDocument::newScenario(TissueSpec tissue) {
    Scenario s;
    s.metadata.title = toStd(tr("New %1 scenario").arg(fromStd(tissue.name)));
    s.tissues.push_back(std::move(tissue));
    s.tool = defaultTool();
    // The effects a new scene starts with; a sample's also anchors its base (sampleScenario).
    for (const char* name : {"deformation", "damping"}) {
        EffectSpec effect;
        effect.name = name;
        effect.parameters = defaultEffectParameters(name);
        s.effects.push_back(std::move(effect));
    }
    return s;
}

void ScenarioDocument::replace(Scenario scenario, const QString& filePath) {
    removeOwnAutosave();
    if (filePath.isEmpty()) {
        reset(std::move(scenario), QString(), false);
        return;
    }
    const QString absolute = QFileInfo(filePath).absoluteFilePath();
    reset(std::move(scenario), absolute, false);
    addRecentFile(absolute);
}

bool ScenarioDocument::save(QString* error) {
    if (m_filePath.isEmpty()) {
        setError(error, tr("the document has no file name yet (use Save As)"));
        return false;
    }
    return saveAs(m_filePath, error);
}

bool ScenarioDocument::saveAs(const QString& path, QString* error) {
    if (path.isEmpty()) {
        setError(error, tr("no file name given"));
        return false;
    }
    if (m_saveCheck) {
        if (const QString reason = m_saveCheck(); !reason.isEmpty()) {
            setError(error, reason);
            return false;
        }
    }
    const QFileInfo info(path);
    const QString absolute = info.absoluteFilePath();
    const Status status = saveScenario(toStd(absolute), m_scenario);
    if (!status) {
        setError(error, fromStd(status.message()));
        return false;
    }
    // The file now holds the paths relative to its folder; so does the document.
    rebaseScenarioPaths(m_scenario, toStd(info.absolutePath()));
    m_undo.setClean();
    setFilePath(absolute);
    removeOwnAutosave();
    addRecentFile(absolute);
    return true;
}

void ScenarioDocument::close() {
    removeOwnAutosave();
    reset(Scenario{}, QString(), false);
}

void ScenarioDocument::reset(Scenario scenario, const QString& filePath, bool modified) {
    m_scenario = std::move(scenario);
    m_offEffectParameters = {};
    m_undo.clear(); // clean again: emits modifiedChanged(false) if it was modified
    if (modified)
        m_undo.resetClean(); // no state is clean: emits modifiedChanged(true)
    setFilePath(filePath);
    emit documentReset();
    notify(AllParts);
}

void ScenarioDocument::setFilePath(const QString& path) {
    if (path == m_filePath)
        return;
    m_filePath = path;
    emit fileChanged(m_filePath);
}

// ---- Recent files ----------------------------------------------------------------------

QSettings& ScenarioDocument::settings() const {
    if (m_settings)
        return *m_settings;
    if (!m_appSettings)
        m_appSettings = std::make_unique<QSettings>();
    return *m_appSettings;
}

QStringList ScenarioDocument::recentFiles() const {
    return settings().value(QLatin1String(kRecentFilesKey)).toStringList();
}

void ScenarioDocument::addRecentFile(const QString& path) {
    const QString absolute = QDir::cleanPath(QFileInfo(path).absoluteFilePath());
    QStringList files = recentFiles();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings().setValue(QLatin1String(kRecentFilesKey), files);
    emit recentFilesChanged();
}

void ScenarioDocument::clearRecentFiles() {
    settings().remove(QLatin1String(kRecentFilesKey));
    emit recentFilesChanged();
}

// ---- Autosave --------------------------------------------------------------------------

QString ScenarioDocument::autosaveDirectory() const {
    return m_autosaveDir.isEmpty()
               ? QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)
               : m_autosaveDir;
}

QString ScenarioDocument::autosavePath() const {
    return QDir(autosaveDirectory()).filePath(QLatin1String(kAutosaveFileName));
}

void ScenarioDocument::setAutosaveInterval(int ms) {
    if (ms <= 0) {
        m_autosaveTimer.stop();
        return;
    }
    m_autosaveTimer.start(ms);
}

bool ScenarioDocument::autosaveNow(QString* error) {
    if (!isModified())
        return true;
    const QString dir = autosaveDirectory();
    if (dir.isEmpty() || !QDir().mkpath(dir)) {
        setError(error, tr("cannot create the autosave folder \"%1\"").arg(dir));
        return false;
    }
    // Relative paths are rewritten to stay valid next to the autosave file.
    Scenario copy = m_scenario;
    rebaseScenarioPaths(copy, toStd(dir));
    const auto writeBytes = [](const QByteArray& bytes) {
        return [bytes](const std::string& tmpPath) {
            QFile file(QString::fromStdString(tmpPath));
            if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() ||
                !file.flush())
                return Status::error(tmpPath + ": " + file.errorString().toStdString());
            return Status::success();
        };
    };
    Status status = writeAtomically(toStd(autosavePath()), writeBytes(scenarioJsonText(copy)));
    if (status) {
        const QJsonObject info{{"file", m_filePath},
                               {"written", QDateTime::currentDateTimeUtc().toString(Qt::ISODate)}};
        status = writeAtomically(
            toStd(QDir(dir).filePath(QLatin1String(kAutosaveInfoFileName))),
            writeBytes(QJsonDocument(info).toJson()));
    }
    if (!status) {
        setError(error, fromStd(status.message()));
        return false;
    }
    m_ownsAutosave = true;
    return true;
}

QString ScenarioDocument::autosaveOriginalFile() const {
    QFile file(QDir(autosaveDirectory()).filePath(QLatin1String(kAutosaveInfoFileName)));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.read(1 << 20)).object().value("file").toString();
}

QString ScenarioDocument::recoverableAutosave() const {
    const QFileInfo autosave(autosavePath());
    if (!autosave.isFile())
        return {};
    const QString original = autosaveOriginalFile();
    if (!original.isEmpty()) {
        const QFileInfo file(original);
        // Saved after the autosave was written: nothing to recover.
        if (file.exists() && file.lastModified() > autosave.lastModified())
            return {};
    }
    return autosave.absoluteFilePath();
}

bool ScenarioDocument::recover(QString* error) {
    const QString path = recoverableAutosave();
    if (path.isEmpty()) {
        setError(error, tr("there is no autosave to recover"));
        return false;
    }
    Scenario loaded;
    ScenarioDiagnostics diag;
    const Status status = loadScenario(toStd(path), loaded, diag);
    if (!status) {
        const QString lines = errorLines(diag, path);
        setError(error, lines.isEmpty() ? fromStd(status.message()) : lines);
        return false;
    }
    const QString original = autosaveOriginalFile();
    if (!original.isEmpty())
        rebaseScenarioPaths(loaded, toStd(QFileInfo(original).absolutePath()));
    reset(std::move(loaded), original, true);
    m_ownsAutosave = true; // removed when the recovered document is saved or closed
    return true;
}

void ScenarioDocument::discardAutosave() {
    QFile::remove(autosavePath());
    QFile::remove(QDir(autosaveDirectory()).filePath(QLatin1String(kAutosaveInfoFileName)));
    m_ownsAutosave = false;
}

void ScenarioDocument::removeOwnAutosave() {
    if (m_ownsAutosave)
        discardAutosave();
}

// ---- Edits -----------------------------------------------------------------------------

void ScenarioDocument::notify(unsigned parts) {
    if (m_quiet) {
        m_quietParts |= parts;
        return;
    }
    if (parts & CutSettingsPart)
        emit cutSettingsChanged();
    if (parts & StrokesPart)
        emit strokesChanged();
    if (parts & SweepsPart)
        emit sweepsChanged();
    if (parts & EffectsPart)
        emit effectsChanged();
    if (parts & MetadataPart)
        emit metadataChanged();
    if (parts & FixedRegionsPart)
        emit fixedRegionsChanged();
    emit changed();
}

void ScenarioDocument::pushCutSettings(const CutSettings& after, int field) {
    if (after == m_scenario.cut)
        return;
    m_undo.push(
        new SetCutSettingsCommand(*this, m_scenario.cut, after, static_cast<CutField>(field)));
}

void ScenarioDocument::setCutSettings(const CutSettings& settings) {
    CutSettings s = settings;
    // The enhanced triangulation is the hybrid method's (scenario_document.h): a document
    // with it and subdivision would not load again.
    if (s.method != CutMethod::Hybrid)
        s.triangulation = FaceTriangulation::Standard;
    pushCutSettings(s, static_cast<int>(CutField::All));
}

void ScenarioDocument::setMethod(CutMethod method) {
    CutSettings s = m_scenario.cut;
    if (method == s.method)
        return;
    s.method = method;
    // As when reading a file: subdivision has the standard triangulation, hybrid the
    // enhanced one unless the author picks the other.
    s.triangulation =
        method == CutMethod::Hybrid ? FaceTriangulation::Enhanced : FaceTriangulation::Standard;
    pushCutSettings(s, static_cast<int>(CutField::Method));
}

void ScenarioDocument::setTriangulation(FaceTriangulation triangulation) {
    CutSettings s = m_scenario.cut;
    s.triangulation = triangulation;
    pushCutSettings(s, static_cast<int>(CutField::Triangulation));
}

void ScenarioDocument::setD(double d) {
    CutSettings s = m_scenario.cut;
    s.d = d;
    pushCutSettings(s, static_cast<int>(CutField::D));
}

void ScenarioDocument::setSnap(bool snap) {
    CutSettings s = m_scenario.cut;
    s.snap = snap;
    pushCutSettings(s, static_cast<int>(CutField::Snap));
}

void ScenarioDocument::setRelaxSteps(int steps) {
    CutSettings s = m_scenario.cut;
    s.relaxSteps = steps;
    pushCutSettings(s, static_cast<int>(CutField::RelaxSteps));
}

void ScenarioDocument::setWSpring(double w) {
    CutSettings s = m_scenario.cut;
    s.wSpring = w;
    pushCutSettings(s, static_cast<int>(CutField::WSpring));
}

void ScenarioDocument::setWParticle(double w) {
    CutSettings s = m_scenario.cut;
    s.wParticle = w;
    pushCutSettings(s, static_cast<int>(CutField::WParticle));
}

void ScenarioDocument::setRelaxDamping(double damping) {
    CutSettings s = m_scenario.cut;
    s.damping = damping;
    pushCutSettings(s, static_cast<int>(CutField::Damping));
}

void ScenarioDocument::setRings(int rings) {
    CutSettings s = m_scenario.cut;
    s.rings = rings;
    pushCutSettings(s, static_cast<int>(CutField::Rings));
}

void ScenarioDocument::setImprove(bool improve) {
    CutSettings s = m_scenario.cut;
    s.improve = improve;
    pushCutSettings(s, static_cast<int>(CutField::Improve));
}

void ScenarioDocument::setImproveQuality(double factor) {
    CutSettings s = m_scenario.cut;
    s.improveQuality = factor;
    pushCutSettings(s, static_cast<int>(CutField::ImproveQuality));
}

void ScenarioDocument::setImproveShortEdge(double factor) {
    CutSettings s = m_scenario.cut;
    s.improveShortEdge = factor;
    pushCutSettings(s, static_cast<int>(CutField::ImproveShortEdge));
}

void ScenarioDocument::setImproveCoarsen(double factor) {
    CutSettings s = m_scenario.cut;
    s.improveCoarsen = factor;
    pushCutSettings(s, static_cast<int>(CutField::ImproveCoarsen));
}

void ScenarioDocument::addStroke(const Stroke& stroke, int index) {
    m_undo.push(new AddStrokeCommand(*this, stroke, index));
}

bool ScenarioDocument::removeStroke(int index) {
    if (index < 0 || index >= static_cast<int>(m_scenario.strokes.size()))
        return false;
    m_undo.push(new RemoveStrokeCommand(*this, index));
    return true;
}

void ScenarioDocument::addSweep(const SweepSpec& sweep, int index) {
    m_undo.push(new AddSweepCommand(*this, sweep, index));
}

bool ScenarioDocument::removeSweep(int index) {
    if (index < 0 || index >= static_cast<int>(m_scenario.sweeps.size()))
        return false;
    m_undo.push(new RemoveSweepCommand(*this, index));
    return true;
}

bool ScenarioDocument::isEffectEnabled(const QString& name) const {
    return m_scenario.findEffect(toStd(name)) != nullptr;
}

bool ScenarioDocument::setEffectEnabled(const QString& name, bool enabled) {
    const std::string key = toStd(name);
    const auto& known = knownEffectNames();
    if (std::find(known.begin(), known.end(), key) == known.end())
        return false;
    const EffectSpec* current = m_scenario.findEffect(key);
    if ((current != nullptr) == enabled)
        return true;
    EffectSpec effect;
    effect.name = key;
    if (enabled) {
        effect.parameters = m_offEffectParameters.contains(name)
                                ? m_offEffectParameters.value(name).toObject()
                                : defaultEffectParameters(key);
    } else {
        m_offEffectParameters.insert(name, current->parameters);
    }
    m_undo.push(new SetEffectEnabledCommand(*this, std::move(effect), enabled));
    return true;
}

bool ScenarioDocument::toggleEffect(const QString& name) {
    return setEffectEnabled(name, !isEffectEnabled(name));
}

bool ScenarioDocument::setEffectParameters(const QString& name, const QJsonObject& parameters) {
    const EffectSpec* effect = m_scenario.findEffect(toStd(name));
    if (!effect)
        return false;
    if (effect->parameters != parameters)
        m_undo.push(new SetEffectParametersCommand(*this, effect->name, effect->parameters, parameters));
    return true;
}

const std::vector<FixedRegion>& ScenarioDocument::fixedRegions() const {
    static const std::vector<FixedRegion> none;
    return m_scenario.tissues.empty() ? none : m_scenario.tissues.front().fixedRegions;
}

void ScenarioDocument::pushFixedRegions(std::vector<FixedRegion> after, int mergeKey) {
    if (after == fixedRegions())
        return;
    m_undo.push(new SetFixedRegionsCommand(*this, fixedRegions(), std::move(after), mergeKey));
}

bool ScenarioDocument::addFixedRegion(const FixedRegion& region) {
    if (m_scenario.tissues.empty())
        return false;
    std::vector<FixedRegion> regions = fixedRegions();
    regions.push_back(region);
    pushFixedRegions(std::move(regions), -1);
    return true;
}

bool ScenarioDocument::setFixedRegion(int index, const FixedRegion& region) {
    if (index < 0 || index >= static_cast<int>(fixedRegions().size()))
        return false;
    std::vector<FixedRegion> regions = fixedRegions();
    regions[static_cast<std::size_t>(index)] = region;
    pushFixedRegions(std::move(regions), index);
    return true;
}

bool ScenarioDocument::removeFixedRegion(int index) {
    if (index < 0 || index >= static_cast<int>(fixedRegions().size()))
        return false;
    std::vector<FixedRegion> regions = fixedRegions();
    regions.erase(regions.begin() + index);
    const bool lastOfFixed = regions.empty() && isEffectEnabled(QStringLiteral("fixed"));
    if (lastOfFixed)
        m_undo.beginMacro(tr("Remove the last fixed region"));
    pushFixedRegions(std::move(regions), -1);
    if (lastOfFixed) {
        setEffectEnabled(QStringLiteral("fixed"), false);
        m_undo.endMacro();
    }
    return true;
}

bool ScenarioDocument::fixRegion(const FixedRegion& region) {
    if (m_scenario.tissues.empty())
        return false;
    if (isEffectEnabled(QStringLiteral("fixed")))
        return true;
    const bool add = fixedRegions().empty();
    if (add) {
        m_undo.beginMacro(tr("Fix a region"));
        addFixedRegion(region);
    }
    setEffectEnabled(QStringLiteral("fixed"), true);
    if (add)
        m_undo.endMacro();
    return true;
}

bool ScenarioDocument::revertTo(const std::function<bool(const Scenario&)>& good) {
    const int start = m_undo.index();
    int found = -1;
    m_quiet = true;
    m_quietParts = 0;
    for (int i = start - 1; i >= 0; --i) {
        m_undo.setIndex(i);
        if (good(m_scenario)) {
            found = i;
            break;
        }
    }
    if (found < 0)
        m_undo.setIndex(start); // back to where it was: nothing to announce
    m_quiet = false;
    if (found < 0)
        return false;
    // An obsolete command is not added, but pushing it deletes the commands above the index.
    m_undo.push(new DropRedoCommand(*this));
    notify(m_quietParts);
    return true;
}

void ScenarioDocument::setTitle(const QString& title) {
    const std::string after = toStd(title);
    if (after == m_scenario.metadata.title)
        return;
    m_undo.push(new SetTitleCommand(*this, m_scenario.metadata.title, after));
}

} // namespace resect
