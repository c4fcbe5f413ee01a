#include "scenario/trainer_export.h"

#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/scenario_load.h"
#include "scenario/scenario_save.h"
#include "scenario/surface_io.h"

#include <QCryptographicHash>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <new>

namespace fs = std::filesystem;

namespace resect {

namespace {

/// Thrown inside the export, caught once in exportTrainerPackage (never leaves this file).
struct ExportError {
    ExportFailure kind;
    std::string message;
};

[[noreturn]] void fail(ExportFailure kind, std::string message) {
    throw ExportError{kind, std::move(message)};
}

/// A writer's failure: bad input, as `resect export` has always reported it.
void require(const Status& status) {
    if (!status.ok())
        fail(ExportFailure::BadInput, status.message());
}

/// Reports progress and turns a refusal into the "cancelled" error.
class ProgressReporter {
public:
    explicit ProgressReporter(const ExportProgress& callback) : m_callback(callback) {}

    void step(double progress, const std::string& stage) {
        if (m_callback && !m_callback(progress, stage)) {
            m_cancelled = true;
            fail(ExportFailure::Cancelled, "cancelled");
        }
    }

    /// The replay's progress mapped onto [from, to] of the export's.
    ReplayProgress replayProgress(double from, double to, const std::string& stage) {
        if (!m_callback)
            return {};
        return [this, from, to, stage](double f) {
            if (!m_callback(from + std::clamp(f, 0.0, 1.0) * (to - from), stage))
                m_cancelled = true;
            return !m_cancelled;
        };
    }

    bool cancelled() const { return m_cancelled; }

    /// The final report; its return is ignored (the package is in place) and so is a throw.
    void done() noexcept {
        try {
            if (m_callback)
                m_callback(1.0, "done");
        } catch (...) {
        }
    }

private:
    const ExportProgress& m_callback;
    bool m_cancelled = false;
};

/// A file name made of the tissue's name: letters, digits, '-' and '_' kept, others '_'.
std::string safeName(const std::string& name, int index) {
    std::string s;
    for (char c : name)
        s += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    return s.empty() ? "tissue-" + std::to_string(index) : s;
}

bool isInside(const fs::path& file, const fs::path& dir) {
    std::error_code ec;
    const fs::path f = fs::weakly_canonical(file, ec), d = fs::weakly_canonical(dir, ec);
    const auto [a, b] = std::mismatch(d.begin(), d.end(), f.begin(), f.end());
    return a == d.end();
}

Status writeJson(const std::string& path, const QJsonObject& object) {
    const QByteArray text = QJsonDocument(object).toJson(QJsonDocument::Indented);
    return writeFileAtomically(path, std::string_view(text.constData(), static_cast<std::size_t>(text.size())));
}

QJsonObject manifestEntry(const fs::path& root, const fs::path& file) {
    QFile f(QString::fromStdString(file.string()));
    if (!f.open(QIODevice::ReadOnly))
        fail(ExportFailure::Internal, "cannot read back " + file.string());
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!hash.addData(&f))
        fail(ExportFailure::Internal, "cannot hash " + file.string());
    return QJsonObject{{"path", QString::fromStdString(fs::relative(file, root).generic_string())},
                       {"size", static_cast<double>(fs::file_size(file))},
                       {"sha256", QString::fromLatin1(hash.result().toHex())}};
}

/// Removes a folder on scope exit unless released (path cleared).
struct TempDir {
    fs::path path;
    ~TempDir() {
        if (!path.empty()) {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    }
};

/// Folders created to hold the package (missing parents of OUT): removed again, innermost
/// first and only while empty, on scope exit unless released.
struct CreatedFolders {
    std::vector<fs::path> paths; // outermost first
    bool keep = false;
    ~CreatedFolders() {
        if (keep)
            return;
        std::error_code ec;
        for (auto it = paths.rbegin(); it != paths.rend(); ++it)
            fs::remove(*it, ec); // only removes empty folders
    }
};

void exportPackage(const Scenario& scenario, const std::string& out, const ExportOptions& options,
                   ExportSummary& summary, ProgressReporter& progress) {
    progress.step(0, "checking");
    const fs::path target = fs::absolute(out).lexically_normal();
    std::error_code ec;
    if (fs::exists(target, ec)) {
        if (!fs::is_directory(target, ec))
            fail(ExportFailure::BadInput, out + ": exists and is not a folder");
        if (!fs::is_empty(target, ec) && !options.force)
            fail(ExportFailure::BadInput,
                 out + ": the folder is not empty (use --force to replace it)");
    }
    // Never replace a folder that holds an input.
    std::vector<std::string> inputs;
    if (!options.scenarioFile.empty())
        inputs.push_back(options.scenarioFile);
    for (const TissueSpec& t : scenario.tissues) {
        if (!t.surface.empty() && !isSampleSource(t.surface))
            inputs.push_back(resolveScenarioPath(scenario.baseDir, t.surface));
        if (!t.mesh.empty())
            inputs.push_back(resolveScenarioPath(scenario.baseDir, t.mesh));
    }
    for (const SweepSpec& s : scenario.sweeps)
        if (!s.file.empty())
            inputs.push_back(resolveScenarioPath(scenario.baseDir, s.file));
    for (const std::string& input : inputs)
        if (isInside(input, target))
            fail(ExportFailure::BadInput,
                 out + ": holds " + input + ", an input of the scenario; export elsewhere");

    // The package, in a temporary folder next to the target.
    const fs::path parent = target.parent_path();
    CreatedFolders created;
    for (fs::path p = parent; !p.empty() && !fs::exists(p, ec) && p != p.parent_path();
         p = p.parent_path())
        created.paths.insert(created.paths.begin(), p);
    fs::create_directories(parent, ec);
    std::string pattern = (parent / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
        fail(ExportFailure::Internal, "cannot create a temporary folder in " + parent.string());
    TempDir temp{fs::path(pattern)};
    const fs::path root = temp.path;
    fs::create_directories(root / "result");

    Scenario package = scenario;
    ScenarioRun run;
    const std::size_t tissueCount = scenario.tissues.size();
    constexpr double kTissuesStart = 0.02, kTissuesEnd = 0.92;
    for (std::size_t i = 0; i < tissueCount; ++i) {
        const TissueSpec& tissue = scenario.tissues[i];
        const std::string name = safeName(tissue.name, static_cast<int>(i));
        const double from =
            kTissuesStart + (kTissuesEnd - kTissuesStart) * double(i) / double(tissueCount);
        const double span = (kTissuesEnd - kTissuesStart) / double(tissueCount);
        progress.step(from, "meshing:" + tissue.name);
        ReplayPlan plan;
        if (Status s = planTissue(scenario, tissue, plan); !s.ok())
            fail(ExportFailure::BadInput, s.message());
        progress.step(from + 0.25 * span, "writing:" + tissue.name);
        require(writeVtu((root / (name + ".vtu")).string(), plan.mesh));
        TissueSpec& packed = package.tissues[i];
        packed.mesh = name + ".vtu";
        packed.meshing = {};
        if (!tissue.surface.empty() && !isSampleSource(tissue.surface)) {
            const fs::path source = resolveScenarioPath(scenario.baseDir, tissue.surface);
            const std::string copy = name + "-surface" + source.extension().string();
            fs::copy_file(source, root / copy, ec);
            if (ec)
                fail(ExportFailure::Internal,
                     "cannot copy " + source.string() + ": " + ec.message());
            packed.surface = copy;
        }
        if (!plan.surface.triangles.empty())
            require(writeSurface((root / (name + "-visual.glb")).string(), plan.surface));
        const std::string replaying = "replaying:" + tissue.name;
        progress.step(from + 0.3 * span, replaying);
        TissueRun t;
        t.name = tissue.name;
        const Status replayed =
            replay(std::move(plan), t.outcome,
                   progress.replayProgress(from + 0.3 * span, from + 0.95 * span, replaying));
        if (progress.cancelled())
            fail(ExportFailure::Cancelled, "cancelled");
        if (!replayed.ok())
            fail(ExportFailure::Internal, "tissue '" + tissue.name + "': " + replayed.message());
        if (!t.outcome.cutFailure.empty())  // (the expert's result would lack that cut and the rest)
            fail(ExportFailure::Internal, "tissue '" + tissue.name + "': " + t.outcome.cutFailure);
        progress.step(from + 0.95 * span, "writing-result:" + tissue.name);
        require(writeVtu((root / "result" / (name + ".vtu")).string(), t.outcome.mesh));
        if (!t.outcome.surface.triangles.empty())
            require(writeSurface((root / "result" / (name + ".glb")).string(), t.outcome.surface));
        run.tissues.push_back(std::move(t));
    }
    progress.step(kTissuesEnd, "packaging");
    run.expectations = evaluateExpectations(scenario, run.tissues);
    for (std::size_t i = 0; i < scenario.sweeps.size(); ++i)
        if (!scenario.sweeps[i].file.empty()) {
            const std::string copy = "sweep-" + std::to_string(i) + ".json";
            fs::copy_file(resolveScenarioPath(scenario.baseDir, scenario.sweeps[i].file),
                          root / copy, ec);
            if (ec)
                fail(ExportFailure::Internal,
                     "cannot copy " + scenario.sweeps[i].file + ": " + ec.message());
            package.sweeps[i].file = copy;
        }
    package.baseDir = root.string();
    require(saveScenario((root / "scenario.json").string(), package));
    QJsonObject report = scenarioRunJson(run);
    report["scenario"] = "scenario.json";
    require(writeJson((root / "result" / "report.json").string(), report));

    progress.step(0.95, "manifest");
    QJsonArray entries;
    std::vector<fs::path> written;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file())
            written.push_back(e.path());
    std::sort(written.begin(), written.end());
    for (const fs::path& f : written)
        entries.append(manifestEntry(root, f));
    require(
        writeJson((root / "manifest.json").string(),
                  QJsonObject{{"format", "resect-package"}, {"version", 1}, {"files", entries}}));

    // Into place: the old folder (if any) goes only once the new one is complete.
    progress.step(0.99, "finishing");
    if (fs::exists(target, ec)) {
        std::string old = (parent / ("." + target.filename().string() + ".old-XXXXXX")).string();
        if (!mkdtemp(old.data()))
            fail(ExportFailure::Internal, "cannot create a temporary folder in " + parent.string());
        fs::remove(old, ec);
        fs::rename(target, old, ec);
        if (ec)
            fail(ExportFailure::Internal, "cannot move the old " + out + " aside: " + ec.message());
        fs::rename(root, target, ec);
        if (ec) {
            std::error_code back;
            fs::rename(old, target, back);
            fail(ExportFailure::Internal,
                 "cannot move the package into " + out + ": " + ec.message());
        }
        fs::remove_all(old, ec);
    } else {
        fs::rename(root, target, ec);
        if (ec)
            fail(ExportFailure::Internal,
                 "cannot move the package into " + out + ": " + ec.message());
    }
    temp.path.clear();
    created.keep = true;

    summary.outDir = target.string();
    for (const fs::path& f : written)
        summary.files.push_back(fs::relative(f, root).generic_string());
    summary.files.push_back("manifest.json");
    summary.expectationsPassed = run.allPassed();
    summary.run = std::move(run);
}

} // namespace

Status exportTrainerPackage(const Scenario& scenario, const std::string& outDir,
                            const ExportOptions& options, ExportSummary& out,
                            const ExportProgress& progress) {
    out = ExportSummary{};
    ExportFailure kind = ExportFailure::Internal;
    std::string message;
    try {
        ProgressReporter reporter(progress);
        exportPackage(scenario, outDir, options, out, reporter);
        reporter.done();
        return Status::success();
    } catch (const ExportError& e) {
        kind = e.kind;
        message = e.message;
    } catch (const std::bad_alloc&) {
        message = "out of memory";
    } catch (const std::exception& e) {
        message = std::string("internal error: ") + e.what();
    } catch (...) {
        message = "internal error";
    }
    out = ExportSummary{};
    out.failure = kind;
    return Status::error(message);
}

Status exportTrainerPackage(const std::string& scenarioPath, const std::string& outDir,
                            const ExportOptions& options, ExportSummary& out,
                            const ExportProgress& progress) {
    Scenario scenario;
    ScenarioDiagnostics diag;
    if (Status s = loadScenario(scenarioPath, scenario, diag); !s.ok()) {
        out = ExportSummary{};
        out.failure = ExportFailure::BadInput;
        return s;
    }
    ExportOptions withFile = options;
    withFile.scenarioFile = scenarioPath;
    return exportTrainerPackage(scenario, outDir, withFile, out, progress);
}

} // namespace resect
