#include "scenario/scenario_save.h"

#include "scenario/atomic_file.h"
#include "scenario/scenario_load.h"

#include <QJsonDocument>

#include <filesystem>
#include <fstream>

namespace resect {

QByteArray scenarioJsonText(const Scenario& scenario) {
    return QJsonDocument(scenarioToJson(scenario)).toJson(QJsonDocument::Indented);
}

Status saveScenario(const std::string& path, const Scenario& scenario) {
    if (path.empty())
        return Status::error("cannot save a scenario: empty file name");
    Scenario rebased = scenario;
    rebaseScenarioPaths(rebased, std::filesystem::path(path).parent_path().string());
    ScenarioDiagnostics diag;
    if (Status s = validateScenario(rebased, diag); !s.ok())
        return Status::error(path + ": not saved, the document has errors: " + diag.firstError(""));
    const QByteArray text = scenarioJsonText(rebased);
    return writeAtomically(path, [&](const std::string& tmp) {
        std::ofstream f(tmp, std::ios::binary);
        f.write(text.constData(), text.size());
        f.close();
        return f ? Status::success() : Status::error("cannot write " + tmp);
    });
}

} // namespace resect
