// resect export SCENARIO --out DIR [--force]: a self-contained package for the trainer.
//
// DIR/
//   scenario.json          the scenario, paths rewritten to the files below
//   NAME.vtu               each tissue's tet mesh before any cut (replaces its meshing step)
//   NAME-surface.EXT       each tissue's surface file, copied as it was (samples stay built in)
//   NAME-visual.glb        each tissue's visual surface (binary glTF with texture coordinates)
//   sweep-I.json           sweep files the scenario refers to
//   result/NAME.vtu        the expert's recorded result: the tet mesh after the replay,
//   result/NAME.glb        the cut surface, deformed with it,
//   result/report.json     and the run report (as `resect run --report`)
//   manifest.json          every other file with its size and SHA-256
//
// The package is written into a temporary folder next to DIR and renamed into place; an
// existing non-empty DIR is refused unless --force (it is then replaced as a whole, after
// the new package is complete). DIR may not hold the scenario or a file it refers to.
#include "app/cli/cli_common.h"

#include "core/mesh/masses.h"
#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/scenario_load.h"
#include "scenario/scenario_run.h"
#include "scenario/scenario_save.h"
#include "scenario/surface_io.h"

#include <QCryptographicHash>
#include <QFile>
#include <QJsonArray>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace resect::cli {

Scenario loadScenarioOrFail(const std::string& path);

namespace {

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

QJsonObject manifestEntry(const fs::path& root, const fs::path& file) {
    QFile f(QString::fromStdString(file.string()));
    if (!f.open(QIODevice::ReadOnly))
        throw CliError{kInternal, "cannot read back " + file.string()};
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!hash.addData(&f))
        throw CliError{kInternal, "cannot hash " + file.string()};
    return QJsonObject{{"path", QString::fromStdString(fs::relative(file, root).generic_string())},
                       {"size", static_cast<double>(fs::file_size(file))},
                       {"sha256", QString::fromLatin1(hash.result().toHex())}};
}

/// Removes a folder on scope exit unless released.
struct TempDir {
    fs::path path;
    ~TempDir() {
        if (!path.empty()) {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    }
};

} // namespace

int runExport(Args args) {
    const std::string out = args.requiredOption("--out");
    const bool force = args.flag("--force");
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one SCENARIO file");
    Scenario scenario = loadScenarioOrFail(files[0]);

    const fs::path target = fs::absolute(out).lexically_normal();
    std::error_code ec;
    if (fs::exists(target, ec)) {
        if (!fs::is_directory(target, ec))
            badInput(out + ": exists and is not a folder");
        if (!fs::is_empty(target, ec) && !force)
            badInput(out + ": the folder is not empty (use --force to replace it)");
    }
    // Never replace a folder that holds an input.
    std::vector<std::string> inputs{files[0]};
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
            badInput(out + ": holds " + input + ", an input of the scenario; export elsewhere");

    // The package, in a temporary folder next to the target.
    const fs::path parent = target.parent_path();
    fs::create_directories(parent, ec);
    std::string pattern = (parent / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
        throw CliError{kInternal, "cannot create a temporary folder in " + parent.string()};
    TempDir temp{fs::path(pattern)};
    const fs::path root = temp.path;
    fs::create_directories(root / "result");

    Scenario package = scenario;
    ScenarioRun run;
    for (std::size_t i = 0; i < scenario.tissues.size(); ++i) {
        const TissueSpec& tissue = scenario.tissues[i];
        const std::string name = safeName(tissue.name, static_cast<int>(i));
        ReplayPlan plan;
        if (Status s = planTissue(scenario, tissue, plan); !s.ok())
            throw CliError{kBadInput, s.message()};
        requireOk(writeVtu((root / (name + ".vtu")).string(), plan.mesh));
        TissueSpec& packed = package.tissues[i];
        packed.mesh = name + ".vtu";
        packed.meshing = {};
        if (!tissue.surface.empty() && !isSampleSource(tissue.surface)) {
            const fs::path source = resolveScenarioPath(scenario.baseDir, tissue.surface);
            const std::string copy = name + "-surface" + source.extension().string();
            fs::copy_file(source, root / copy, ec);
            if (ec)
                throw CliError{kInternal, "cannot copy " + source.string() + ": " + ec.message()};
            packed.surface = copy;
        }
        if (!plan.surface.triangles.empty())
            requireOk(writeSurface((root / (name + "-visual.glb")).string(), plan.surface));
        TissueRun t;
        t.name = tissue.name;
        if (Status s = replay(std::move(plan), t.outcome); !s.ok())
            throw CliError{kInternal, "tissue '" + tissue.name + "': " + s.message()};
        requireOk(writeVtu((root / "result" / (name + ".vtu")).string(), t.outcome.mesh));
        if (!t.outcome.surface.triangles.empty())
            requireOk(writeSurface((root / "result" / (name + ".glb")).string(), t.outcome.surface));
        run.tissues.push_back(std::move(t));
    }
    run.expectations = evaluateExpectations(scenario, run.tissues);
    for (std::size_t i = 0; i < scenario.sweeps.size(); ++i)
        if (!scenario.sweeps[i].file.empty()) {
            const std::string copy = "sweep-" + std::to_string(i) + ".json";
            fs::copy_file(resolveScenarioPath(scenario.baseDir, scenario.sweeps[i].file), root / copy, ec);
            if (ec)
                throw CliError{kInternal, "cannot copy " + scenario.sweeps[i].file + ": " + ec.message()};
            package.sweeps[i].file = copy;
        }
    package.baseDir = root.string();
    requireOk(saveScenario((root / "scenario.json").string(), package));
    QJsonObject report = scenarioRunJson(run);
    report["scenario"] = "scenario.json";
    requireOk(writeJson((root / "result" / "report.json").string(), report));

    QJsonArray entries;
    std::vector<fs::path> written;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file())
            written.push_back(e.path());
    std::sort(written.begin(), written.end());
    for (const fs::path& f : written)
        entries.append(manifestEntry(root, f));
    requireOk(writeJson((root / "manifest.json").string(),
                        QJsonObject{{"format", "resect-package"}, {"version", 1}, {"files", entries}}));

    // Into place: the old folder (if any) goes only once the new one is complete.
    if (fs::exists(target, ec)) {
        std::string old = (parent / ("." + target.filename().string() + ".old-XXXXXX")).string();
        if (!mkdtemp(old.data()))
            throw CliError{kInternal, "cannot create a temporary folder in " + parent.string()};
        fs::remove(old, ec);
        fs::rename(target, old, ec);
        if (ec)
            throw CliError{kInternal, "cannot move the old " + out + " aside: " + ec.message()};
        fs::rename(root, target, ec);
        if (ec) {
            std::error_code back;
            fs::rename(old, target, back);
            throw CliError{kInternal, "cannot move the package into " + out + ": " + ec.message()};
        }
        fs::remove_all(old, ec);
    } else {
        fs::rename(root, target, ec);
        if (ec)
            throw CliError{kInternal, "cannot move the package into " + out + ": " + ec.message()};
    }
    temp.path.clear();
    std::printf("%s: %zu files, expectations %s\n", out.c_str(), written.size() + 1,
                run.allPassed() ? "passed" : "FAILED");
    return kOk;
}

} // namespace resect::cli
