#pragma once
// Problems found while reading a scenario document, each with the JSON path of the value it
// concerns (e.g. "tissues[0].material.density"; "" is the document itself) and a plain
// message. Errors make the document unusable; warnings (unknown fields, a migrated older
// version, ...) do not.

#include <string>
#include <vector>

namespace resect {

struct ScenarioIssue {
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    std::string path;
    std::string message;
    bool isError() const { return severity == Severity::Error; }
};

class ScenarioDiagnostics {
public:
    /// At most this many issues are kept; later ones are only counted (see dropped()), so
    /// that absurd input cannot produce an absurd report.
    static constexpr int kMaxIssues = 1000;

    void error(const std::string& path, const std::string& message);
    void warning(const std::string& path, const std::string& message);

    const std::vector<ScenarioIssue>& issues() const { return m_issues; }
    int errorCount() const { return m_errors; }
    int warningCount() const { return m_warnings; }
    bool hasErrors() const { return m_errors > 0; }
    /// Issues counted but not kept (beyond kMaxIssues).
    int dropped() const { return m_dropped; }
    void clear() { *this = {}; }

    /// The first issue of this severity at exactly this path, or null.
    const ScenarioIssue*
    find(const std::string& path,
         ScenarioIssue::Severity severity = ScenarioIssue::Severity::Error) const;

    /// One line per issue: "NAME: PATH: error: MESSAGE" (the path left out for the document
    /// itself), and a last line for dropped issues.
    std::string format(const std::string& name) const;
    /// "NAME: PATH: MESSAGE" of the first error, with " (and N more errors)" if there are more.
    std::string firstError(const std::string& name) const;

private:
    void add(ScenarioIssue::Severity severity, const std::string& path, const std::string& message);

    std::vector<ScenarioIssue> m_issues;
    int m_errors = 0;
    int m_warnings = 0;
    int m_dropped = 0;
};

} // namespace resect
