#include "scenario/scenario_diagnostics.h"

namespace resect {

void ScenarioDiagnostics::error(const std::string& path, const std::string& message) {
    add(ScenarioIssue::Severity::Error, path, message);
}

void ScenarioDiagnostics::warning(const std::string& path, const std::string& message) {
    add(ScenarioIssue::Severity::Warning, path, message);
}

void ScenarioDiagnostics::add(ScenarioIssue::Severity severity, const std::string& path,
                              const std::string& message) {
    (severity == ScenarioIssue::Severity::Error ? m_errors : m_warnings) += 1;
    if (static_cast<int>(m_issues.size()) >= kMaxIssues) {
        ++m_dropped;
        return;
    }
    m_issues.push_back({severity, path, message});
}

const ScenarioIssue* ScenarioDiagnostics::find(const std::string& path,
                                               ScenarioIssue::Severity severity) const {
    for (const ScenarioIssue& i : m_issues)
        if (i.severity == severity && i.path == path)
            return &i;
    return nullptr;
}

namespace {

std::string located(const std::string& name, const std::string& path) {
    std::string s = name;
    if (!path.empty())
        s += (s.empty() ? "" : ": ") + path;
    return s;
}

} // namespace

std::string ScenarioDiagnostics::format(const std::string& name) const {
    std::string out;
    for (const ScenarioIssue& i : m_issues) {
        const std::string where = located(name, i.path);
        out += where + (where.empty() ? "" : ": ") + (i.isError() ? "error: " : "warning: ") +
               i.message + "\n";
    }
    if (m_dropped > 0)
        out += located(name, "") + (name.empty() ? "" : ": ") + "... and " +
               std::to_string(m_dropped) + " more problems not listed\n";
    return out;
}

std::string ScenarioDiagnostics::firstError(const std::string& name) const {
    for (const ScenarioIssue& i : m_issues) {
        if (!i.isError())
            continue;
        const std::string where = located(name, i.path);
        std::string s = where + (where.empty() ? "" : ": ") + i.message;
        if (m_errors > 1)
            s += " (and " + std::to_string(m_errors - 1) + " more error" +
                 (m_errors > 2 ? "s" : "") + ")";
        return s;
    }
    return m_errors > 0 ? located(name, "") + ": " + std::to_string(m_errors) + " errors" : "";
}

} // namespace resect
