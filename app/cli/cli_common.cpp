#include "app/cli/cli_common.h"

#include "scenario/atomic_file.h"

#include <QJsonDocument>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace resect::cli {

void badInput(const std::string& message) { throw CliError{kBadInput, message}; }

void requireOk(const Status& status) {
    if (!status.ok())
        badInput(status.message());
}

std::optional<std::string> Args::option(const std::string& name) {
    std::optional<std::string> value;
    for (std::size_t i = 0; i < m_args.size();) {
        if (m_args[i] == name) {
            if (i + 1 >= m_args.size())
                badInput(name + ": missing value");
            if (value)
                badInput(name + ": given more than once");
            value = m_args[i + 1];
            m_args.erase(m_args.begin() + i, m_args.begin() + i + 2);
        } else if (m_args[i].rfind(name + "=", 0) == 0) {
            if (value)
                badInput(name + ": given more than once");
            value = m_args[i].substr(name.size() + 1);
            m_args.erase(m_args.begin() + i);
        } else {
            ++i;
        }
    }
    return value;
}

std::vector<std::string> Args::options(const std::string& name) {
    std::vector<std::string> values;
    for (std::size_t i = 0; i < m_args.size();) {
        if (m_args[i] == name) {
            if (i + 1 >= m_args.size())
                badInput(name + ": missing value");
            values.push_back(m_args[i + 1]);
            m_args.erase(m_args.begin() + i, m_args.begin() + i + 2);
        } else if (m_args[i].rfind(name + "=", 0) == 0) {
            values.push_back(m_args[i].substr(name.size() + 1));
            m_args.erase(m_args.begin() + i);
        } else {
            ++i;
        }
    }
    return values;
}

std::optional<std::vector<std::string>> Args::optionValues(const std::string& name, int count) {
    std::optional<std::vector<std::string>> values;
    for (std::size_t i = 0; i < m_args.size();) {
        if (m_args[i] != name) {
            ++i;
            continue;
        }
        if (values)
            badInput(name + ": given more than once");
        std::vector<std::string> taken;
        for (int k = 1; k <= count; ++k) {
            if (i + k >= m_args.size() || m_args[i + k].rfind("--", 0) == 0)
                badInput(name + ": expected " + std::to_string(count) + " values");
            taken.push_back(m_args[i + k]);
        }
        values = taken;
        m_args.erase(m_args.begin() + i, m_args.begin() + i + 1 + count);
    }
    return values;
}

std::optional<std::vector<double>> Args::numbers(const std::string& name, int count,
                                                 const std::string& what) {
    const auto texts = optionValues(name, count);
    if (!texts)
        return std::nullopt;
    std::vector<double> values;
    for (const std::string& text : *texts) {
        std::size_t used = 0;
        double value = 0;
        try {
            value = std::stod(text, &used);
        } catch (...) {
            used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(value))
            badInput(name + ": expected " + what + " (finite numbers), got '" + text + "'");
        values.push_back(value);
    }
    return values;
}

std::string Args::requiredOption(const std::string& name) {
    auto v = option(name);
    if (!v || v->empty())
        badInput(name + " is required");
    return *v;
}

bool Args::flag(const std::string& name) {
    bool found = false;
    for (std::size_t i = 0; i < m_args.size();) {
        if (m_args[i] == name) {
            found = true;
            m_args.erase(m_args.begin() + i);
        } else {
            ++i;
        }
    }
    return found;
}

std::optional<double> Args::number(const std::string& name, double min, double max) {
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(*text, &used);
    } catch (...) {
        used = 0;
    }
    if (used == 0 || used != text->size() || !std::isfinite(value))
        badInput(name + ": expected a finite number, got '" + *text + "'");
    if (value < min || value > max)
        badInput(name + ": " + *text + " is out of range [" + std::to_string(min) + ", " +
                 std::to_string(max) + "]");
    return value;
}

std::optional<int> Args::integer(const std::string& name, int min, int max) {
    const auto text = option(name);
    if (!text)
        return std::nullopt;
    std::size_t used = 0;
    long long value = 0;
    try {
        value = std::stoll(*text, &used);
    } catch (...) {
        used = 0;
    }
    if (used == 0 || used != text->size())
        badInput(name + ": expected a whole number, got '" + *text + "'");
    if (value < min || value > max)
        badInput(name + ": " + *text + " is out of range [" + std::to_string(min) + ", " +
                 std::to_string(max) + "]");
    return static_cast<int>(value);
}

std::vector<std::string> Args::positionals() {
    std::vector<std::string> result;
    for (std::size_t i = 0; i < m_args.size();) {
        if (m_args[i].rfind("--", 0) != 0) {
            result.push_back(m_args[i]);
            m_args.erase(m_args.begin() + i);
        } else {
            ++i;
        }
    }
    return result;
}

void Args::finish() const {
    if (!m_args.empty())
        badInput("unknown option " + m_args.front());
}

void printJson(const QJsonObject& object) {
    const QByteArray text = QJsonDocument(object).toJson(QJsonDocument::Indented);
    std::fwrite(text.constData(), 1, static_cast<std::size_t>(text.size()), stdout);
    std::fflush(stdout);
}

Status writeJson(const std::string& path, const QJsonObject& object) {
    const QByteArray text = QJsonDocument(object).toJson(QJsonDocument::Indented);
    return writeFileAtomically(path, std::string_view(text.constData(), static_cast<std::size_t>(text.size())));
}

void requireDistinct(const std::string& input, const std::string& out) {
    std::error_code ec;
    if (std::filesystem::exists(out, ec) && std::filesystem::equivalent(input, out, ec))
        badInput("--out " + out + " is the input file; refusing to overwrite an input");
}

MeshOutput meshOutput(const std::string& path, const std::optional<std::string>& formatKey,
                      const std::string& option) {
    MeshOutput out{path, MeshFormat::Vtu};
    if (Status s = chooseMeshWriteFormat(path, formatKey ? *formatKey : std::string(), out.format); !s)
        badInput(option + ": " + s.message());
    return out;
}

std::vector<std::string> meshFiles(const std::string& path) {
    const std::filesystem::path p(path);
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".node" && ext != ".ele")
        return {path};
    std::filesystem::path other = p;
    other.replace_extension(ext == ".node" ? ".ele" : ".node");
    return {path, other.string()};
}

void requireDistinctMesh(const std::string& input, const std::string& out) {
    for (const std::string& in : meshFiles(input))
        for (const std::string& o : meshFiles(out)) {
            std::error_code ec;
            if (std::filesystem::exists(o, ec) && std::filesystem::equivalent(in, o, ec))
                badInput("--out " + out + " would overwrite the input file " + in +
                         "; refusing to overwrite an input");
        }
}

void writeMeshOutput(const MeshOutput& out, const TetMesh& mesh) {
    requireOk(writeTetMesh(out.path, mesh, out.format));
}

void printReadNotes(const std::string& path, const MeshReadReport& report) {
    if (report.dropped.empty() && report.notes.empty())
        return;
    std::fprintf(stderr, "note: %s: %s\n", path.c_str(), report.summary().c_str());
}

} // namespace resect::cli
