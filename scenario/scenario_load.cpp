#include "scenario/scenario_load.h"

#include "core/mesher/samples.h"
#include "scenario/scenario_migrate.h"
#include "scenario/scenario_sweeps.h"
#include "scenario/sweep_io.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <set>

namespace resect {

namespace {

namespace fs = std::filesystem;

// Limits on absurd input (see scenario_load.h).
constexpr double kMaxCoordinate = 1e6; // mm
constexpr double kMaxTime = 1e6;       // s
constexpr qsizetype kMaxListLength = 100000;
constexpr long long kMaxPoses = 1000000;
constexpr qsizetype kMaxToolPoints = 100000;
constexpr long long kMaxSweepVertices = 1000000;
constexpr qint64 kMaxFileBytes = 256ll << 20;
constexpr double kMaxSimulationSteps = 1e9;

std::string child(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}
std::string element(const std::string& path, qsizetype i) {
    return path + "[" + std::to_string(i) + "]";
}

std::string typeName(const QJsonValue& v) {
    switch (v.type()) {
    case QJsonValue::Null:
        return "null";
    case QJsonValue::Bool:
        return "a boolean";
    case QJsonValue::Double:
        return "a number";
    case QJsonValue::String:
        return "a string";
    case QJsonValue::Array:
        return "an array";
    case QJsonValue::Object:
        return "an object";
    case QJsonValue::Undefined:
        break;
    }
    return "nothing";
}

std::string num(double v) {
    return QString::number(v, 'g', QLocale::FloatingPointShortest).toStdString();
}

/// A closed or half-open interval of accepted numbers.
struct Range {
    double lo;
    double hi;
    bool loOpen = false;
    bool hiOpen = false;
    bool contains(double v) const {
        return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    }
    std::string text() const {
        return (loOpen ? "(" : "[") + num(lo) + ", " + num(hi) + (hiOpen ? ")" : "]");
    }
};
constexpr Range kCoordinate{-kMaxCoordinate, kMaxCoordinate};

/// Shared state of one read.
struct Context {
    ScenarioDiagnostics& diag;
    std::string baseDir;
    long long poses = 0;
    bool posesCapped = false;

    void error(const std::string& path, const std::string& message) { diag.error(path, message); }
    void warning(const std::string& path, const std::string& message) {
        diag.warning(path, message);
    }

    /// Checks that a referenced file exists; returns false (with an error) if not.
    bool checkFile(const std::string& path, const std::string& file) {
        const std::string resolved = resolveScenarioPath(baseDir, file);
        std::error_code ec;
        const fs::file_status st = fs::status(resolved, ec);
        if (fs::is_regular_file(st))
            return true;
        if (fs::is_directory(st))
            error(path, "'" + file + "' is a folder, not a file (" + resolved + ")");
        else
            error(path, "file not found: '" + file + "' (looked for " + resolved + ")");
        return false;
    }
};

// --- single values ---------------------------------------------------------------------

bool readNumber(Context& c, const QJsonValue& v, const std::string& path, const Range& r,
                double& out) {
    if (!v.isDouble()) {
        c.error(path, "expected a number, got " + typeName(v));
        return false;
    }
    const double x = v.toDouble();
    if (!std::isfinite(x) || !r.contains(x)) {
        c.error(path, "out of range: " + num(x) + " (expected a number in " + r.text() + ")");
        return false;
    }
    out = x;
    return true;
}

bool readInteger(Context& c, const QJsonValue& v, const std::string& path, long long lo,
                 long long hi, long long& out) {
    if (!v.isDouble() || v.toDouble() != std::floor(v.toDouble()) || !std::isfinite(v.toDouble())) {
        c.error(path,
                "expected an integer, got " + (v.isDouble() ? num(v.toDouble()) : typeName(v)));
        return false;
    }
    const double x = v.toDouble();
    if (x < static_cast<double>(lo) || x > static_cast<double>(hi)) {
        c.error(path, "out of range: " + num(x) + " (expected an integer from " +
                          std::to_string(lo) + " to " + std::to_string(hi) + ")");
        return false;
    }
    out = static_cast<long long>(x);
    return true;
}

bool readText(Context& c, const QJsonValue& v, const std::string& path, std::string& out) {
    if (!v.isString()) {
        c.error(path, "expected a string, got " + typeName(v));
        return false;
    }
    out = v.toString().toStdString();
    return true;
}

bool readBool(Context& c, const QJsonValue& v, const std::string& path, bool& out) {
    if (!v.isBool()) {
        c.error(path, "expected true or false, got " + typeName(v));
        return false;
    }
    out = v.toBool();
    return true;
}

/// An array of `n` numbers in `range`.
bool readNumbers(Context& c, const QJsonValue& v, const std::string& path, int n,
                 const Range& range, const char* shape, double* out) {
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != n) {
        c.error(path, std::string("expected ") + shape + ", got " +
                          (v.isArray() ? "an array of " + std::to_string(a.size()) : typeName(v)));
        return false;
    }
    bool ok = true;
    for (int i = 0; i < n; ++i)
        ok = readNumber(c, a[i], element(path, i), range, out[i]) && ok;
    return ok;
}

bool readPoint(Context& c, const QJsonValue& v, const std::string& path, Vec3& out) {
    double p[3];
    if (!readNumbers(c, v, path, 3, kCoordinate, "[x, y, z]", p))
        return false;
    out = Vec3(p[0], p[1], p[2]);
    return true;
}

/// An array of points (a polyline); at most `maxPoints`.
bool readPoints(Context& c, const QJsonValue& v, const std::string& path, qsizetype maxPoints,
                std::vector<Vec3>& out) {
    if (!v.isArray()) {
        c.error(path, "expected an array of [x, y, z] points, got " + typeName(v));
        return false;
    }
    const QJsonArray a = v.toArray();
    if (a.size() > maxPoints) {
        c.error(path, std::to_string(a.size()) + " points: more than the limit of " +
                          std::to_string(maxPoints));
        return false;
    }
    out.clear();
    out.reserve(static_cast<std::size_t>(a.size()));
    bool ok = true;
    for (qsizetype i = 0; i < a.size(); ++i) {
        Vec3 p;
        if (readPoint(c, a[i], element(path, i), p))
            out.push_back(p);
        else
            ok = false;
    }
    return ok;
}

/// The value as an array of at most `limit` entries.
bool readList(Context& c, const QJsonValue& v, const std::string& path, QJsonArray& out,
              qsizetype limit = kMaxListLength) {
    if (!v.isArray()) {
        c.error(path, "expected an array, got " + typeName(v));
        return false;
    }
    out = v.toArray();
    if (out.size() > limit) {
        c.error(path, std::to_string(out.size()) + " entries: more than the limit of " +
                          std::to_string(limit));
        return false;
    }
    return true;
}

// --- objects ---------------------------------------------------------------------------

/// One JSON object being read: each getter marks its key as known; unknown() reports the
/// rest as warnings and returns them (to be kept in the struct's `extra`).
class Fields {
public:
    Fields(Context& c, const QJsonObject& o, std::string path)
        : m_c(c), m_o(o), m_path(std::move(path)) {}

    const std::string& path() const { return m_path; }
    std::string at(const char* key) const { return child(m_path, key); }
    bool has(const char* key) const { return m_o.contains(QLatin1String(key)); }

    /// The value (Undefined if absent); an absent required key is an error.
    QJsonValue take(const char* key, bool required = false) {
        m_known.insert(key);
        const QJsonValue v = m_o.value(QLatin1String(key));
        if (v.isUndefined() && required)
            m_c.error(at(key), "missing (required)");
        return v;
    }
    bool number(const char* key, double& out, const Range& r, bool required = false) {
        const QJsonValue v = take(key, required);
        return !v.isUndefined() && readNumber(m_c, v, at(key), r, out);
    }
    template <class Int>
    bool integer(const char* key, Int& out, long long lo, long long hi, bool required = false) {
        const QJsonValue v = take(key, required);
        long long x = 0;
        if (v.isUndefined() || !readInteger(m_c, v, at(key), lo, hi, x))
            return false;
        out = static_cast<Int>(x);
        return true;
    }
    bool text(const char* key, std::string& out, bool required = false) {
        const QJsonValue v = take(key, required);
        return !v.isUndefined() && readText(m_c, v, at(key), out);
    }
    bool boolean(const char* key, bool& out, bool required = false) {
        const QJsonValue v = take(key, required);
        return !v.isUndefined() && readBool(m_c, v, at(key), out);
    }
    bool point(const char* key, Vec3& out, bool required = false) {
        const QJsonValue v = take(key, required);
        return !v.isUndefined() && readPoint(m_c, v, at(key), out);
    }
    /// One of `names` (an error lists them).
    bool choice(const char* key, const std::vector<std::string>& names, std::string& out,
                bool required = false) {
        std::string s;
        if (!text(key, s, required))
            return false;
        if (std::find(names.begin(), names.end(), s) == names.end()) {
            std::string list;
            for (const auto& n : names)
                list += (list.empty() ? "" : ", ") + n;
            m_c.error(at(key), "unknown value '" + s + "' (expected one of: " + list + ")");
            return false;
        }
        out = s;
        return true;
    }

    QJsonObject unknown() {
        QJsonObject rest;
        for (auto it = m_o.begin(); it != m_o.end(); ++it) {
            const std::string key = it.key().toStdString();
            if (m_known.count(key))
                continue;
            m_c.warning(child(m_path, key), "unknown field (kept, not used)");
            rest.insert(it.key(), it.value());
        }
        return rest;
    }

private:
    Context& m_c;
    QJsonObject m_o;
    std::string m_path;
    std::set<std::string> m_known;
};

/// The value as an object (an error if it is anything else).
bool asObject(Context& c, const QJsonValue& v, const std::string& path, QJsonObject& out) {
    if (!v.isObject()) {
        c.error(path, "expected an object, got " + typeName(v));
        return false;
    }
    out = v.toObject();
    return true;
}

// --- sections --------------------------------------------------------------------------

void readMetadata(Context& c, const QJsonValue& v, ScenarioMetadata& out) {
    QJsonObject o;
    if (v.isUndefined() || !asObject(c, v, "metadata", o))
        return;
    Fields f(c, o, "metadata");
    f.text("title", out.title);
    f.text("author", out.author);
    f.text("description", out.description);
    QJsonArray objectives;
    const QJsonValue ov = f.take("learning_objectives");
    if (!ov.isUndefined() && readList(c, ov, f.at("learning_objectives"), objectives)) {
        for (qsizetype i = 0; i < objectives.size(); ++i) {
            std::string s;
            if (readText(c, objectives[i], element(f.at("learning_objectives"), i), s))
                out.learningObjectives.push_back(s);
        }
    }
    f.integer("difficulty", out.difficulty, 1, 5);
    out.extra = f.unknown();
}

void readMaterial(Context& c, const QJsonValue& v, const std::string& path, MaterialSpec& out) {
    QJsonObject o;
    if (v.isUndefined() || !asObject(c, v, path, o))
        return;
    Fields f(c, o, path);
    f.number("density", out.density, {0, 1, true});
    f.number("stiffness", out.stiffness, {0, 1e15, true});
    f.number("damping", out.damping, {0, 1e6});
    out.extra = f.unknown();
}

void readFixedRegions(Context& c, const QJsonValue& v, const std::string& path,
                      std::vector<FixedRegion>& out) {
    QJsonArray a;
    if (v.isUndefined() || !readList(c, v, path, a))
        return;
    for (qsizetype i = 0; i < a.size(); ++i) {
        const std::string at = element(path, i);
        QJsonObject o;
        if (!asObject(c, a[i], at, o))
            continue;
        Fields f(c, o, at);
        FixedRegion r;
        const bool minOk = f.point("min", r.min, true);
        const bool maxOk = f.point("max", r.max, true);
        if (minOk && maxOk) {
            for (int k = 0; k < 3; ++k)
                if (r.min[k] > r.max[k])
                    c.error(at, std::string("min exceeds max in ") + "xyz"[k] + " (" +
                                    num(r.min[k]) + " > " + num(r.max[k]) + ")");
        }
        r.extra = f.unknown();
        out.push_back(std::move(r));
    }
}

void readTissue(Context& c, const QJsonObject& o, const std::string& path, TissueSpec& out) {
    Fields f(c, o, path);
    if (f.text("name", out.name, true) && out.name.empty())
        c.error(f.at("name"), "must not be empty");
    // A tissue given by its tet mesh alone has no embedded surface.
    if (f.text("surface", out.surface, !f.has("mesh"))) {
        if (out.surface.empty()) {
            c.error(f.at("surface"), "must not be empty (a file or \"sample:NAME\")");
        } else if (isSampleSource(out.surface)) {
            const std::string name = out.surface.substr(7);
            if (!sampleFromName(name)) {
                std::string known;
                for (const auto& n : sampleNames())
                    known += (known.empty() ? "sample:" : ", sample:") + n;
                c.error(f.at("surface"), "unknown sample '" + name + "' (known: " + known + ")");
            }
        } else {
            c.checkFile(f.at("surface"), out.surface);
        }
    }
    if (f.text("mesh", out.mesh)) {
        if (out.mesh.empty())
            c.error(f.at("mesh"), "must not be empty (leave it out to mesh the surface)");
        else
            c.checkFile(f.at("mesh"), out.mesh);
    }
    const QJsonValue meshing = f.take("meshing");
    if (!meshing.isUndefined()) {
        QJsonObject mo;
        if (f.has("mesh"))
            c.error(path, "give either \"mesh\" or \"meshing\", not both");
        else if (asObject(c, meshing, f.at("meshing"), mo)) {
            Fields m(c, mo, f.at("meshing"));
            m.number("edge_length", out.meshing.edgeLength, {0, 1e4});
            m.integer("seed", out.meshing.seed, 0, std::numeric_limits<unsigned>::max());
            out.meshing.extra = m.unknown();
        }
    }
    readMaterial(c, f.take("material"), f.at("material"), out.material);
    readFixedRegions(c, f.take("fixed_regions"), f.at("fixed_regions"), out.fixedRegions);
    out.extra = f.unknown();
}

void readTissues(Context& c, const QJsonValue& v, std::vector<TissueSpec>& out) {
    if (v.isUndefined()) {
        c.error("tissues", "missing (required: at least one tissue)");
        return;
    }
    QJsonArray a;
    if (!readList(c, v, "tissues", a))
        return;
    if (a.isEmpty())
        c.error("tissues", "empty (at least one tissue is required)");
    std::set<std::string> names;
    for (qsizetype i = 0; i < a.size(); ++i) {
        const std::string at = element("tissues", i);
        QJsonObject o;
        if (!asObject(c, a[i], at, o))
            continue;
        TissueSpec t;
        readTissue(c, o, at, t);
        if (!t.name.empty() && !names.insert(t.name).second)
            c.error(child(at, "name"), "duplicate tissue name '" + t.name + "'");
        out.push_back(std::move(t));
    }
}

/// Returns true if the tool is usable for sweeping.
bool readTool(Context& c, const QJsonValue& v, ToolSpec& out) {
    QJsonObject o;
    if (v.isUndefined() || !asObject(c, v, "tool", o))
        return false;
    Fields f(c, o, "tool");
    f.text("name", out.name);
    bool ok = true;
    if (f.has("size"))
        ok = f.number("size", out.size, {0, 1e3, true});
    const QJsonValue curve = f.take("curve", true);
    if (curve.isUndefined()) {
        ok = false;
    } else if (!readPoints(c, curve, f.at("curve"), kMaxToolPoints, out.curve)) {
        ok = false;
    } else if (out.curve.size() < 2) {
        c.error(f.at("curve"),
                "needs at least two points (one segment), got " + std::to_string(out.curve.size()));
        ok = false;
    }
    out.extra = f.unknown();
    return ok;
}

/// Reads one pose; returns false if it is unusable.
bool readPose(Context& c, const QJsonValue& v, const std::string& path, ToolPose& out) {
    QJsonObject o;
    if (!asObject(c, v, path, o))
        return false;
    Fields f(c, o, path);
    bool ok = f.number("t", out.t, {-kMaxTime, kMaxTime}, true);
    ok = f.point("position", out.position, true) && ok;
    const QJsonValue q = f.take("orientation");
    if (!q.isUndefined()) {
        double w[4];
        if (readNumbers(c, q, f.at("orientation"), 4, {-kMaxCoordinate, kMaxCoordinate},
                        "a quaternion [w, x, y, z]", w)) {
            out.orientation = Eigen::Vector4d(w[0], w[1], w[2], w[3]);
            if (!(out.orientation.norm() > 1e-12)) {
                c.error(f.at("orientation"),
                        "quaternion of zero length (no rotation is [1, 0, 0, 0])");
                ok = false;
            }
        } else {
            ok = false;
        }
    }
    out.extra = f.unknown();
    return ok;
}

/// Reads one stroke; returns false if it cannot be swept.
bool readStroke(Context& c, const QJsonObject& o, const std::string& path, Stroke& out) {
    Fields f(c, o, path);
    f.text("name", out.name);
    const QJsonValue pv = f.take("poses", true);
    QJsonArray poses;
    bool ok = !pv.isUndefined() && readList(c, pv, f.at("poses"), poses, kMaxPoses);
    if (ok && (c.posesCapped || c.poses + poses.size() > kMaxPoses)) {
        if (!c.posesCapped)
            c.error(f.at("poses"),
                    "more than " + std::to_string(kMaxPoses) +
                        " poses in all strokes; this stroke and the rest are not read");
        c.posesCapped = true;
        ok = false;
        poses = {};
    }
    c.poses += poses.size();
    if (ok && poses.size() < 2) {
        c.error(f.at("poses"), poses.isEmpty() ? "empty stroke (at least two poses are needed)"
                                               : "a single pose (at least two are needed)");
        ok = false;
    }
    bool warnedLength = false;
    for (qsizetype i = 0; i < poses.size(); ++i) {
        const std::string at = element(f.at("poses"), i);
        ToolPose p;
        if (!readPose(c, poses[i], at, p)) {
            ok = false;
            continue;
        }
        const double length = p.orientation.norm();
        if (!warnedLength && std::abs(length - 1) > 1e-3) {
            c.warning(child(at, "orientation"),
                      "quaternion of length " + num(length) +
                          ", not 1; it is normalised (not reported again for this stroke)");
            warnedLength = true;
        }
        if (!out.poses.empty() && !(p.t > out.poses.back().t)) {
            c.error(child(at, "t"), "time stamps must increase: " + num(p.t) + " comes after " +
                                        num(out.poses.back().t));
            ok = false;
        }
        out.poses.push_back(std::move(p));
    }
    out.extra = f.unknown();
    return ok;
}

void readStrokes(Context& c, const QJsonValue& v, Scenario& s, bool toolOk) {
    QJsonArray a;
    if (v.isUndefined() || !readList(c, v, "strokes", a))
        return;
    for (qsizetype i = 0; i < a.size(); ++i) {
        const std::string at = element("strokes", i);
        QJsonObject o;
        if (!asObject(c, a[i], at, o))
            continue;
        Stroke stroke;
        const bool ok = readStroke(c, o, at, stroke);
        s.strokes.push_back(std::move(stroke));
        const Stroke& st = s.strokes.back();
        if (i > 0 && !s.strokes[i - 1].poses.empty() && !st.poses.empty() &&
            st.poses.front().t < s.strokes[i - 1].poses.back().t)
            c.warning(child(at, "poses[0].t"), "starts before the previous stroke ends (" +
                                                   num(s.strokes[i - 1].poses.back().t) + " s)");
        if (!ok || !toolOk)
            continue;
        // The stroke's sweep must be a valid surface for replay.
        const long long vertices =
            static_cast<long long>(st.poses.size()) * static_cast<long long>(s.tool.curve.size());
        if (vertices > kMaxSweepVertices) {
            c.error(at, "its sweep would have " + std::to_string(vertices) +
                            " vertices (poses x tool points), more than the limit of " +
                            std::to_string(kMaxSweepVertices));
            continue;
        }
        SweepSurface sweep;
        if (Status st2 = strokeSweep(s, static_cast<int>(i), sweep); !st2.ok()) {
            std::string message = st2.message();
            const std::string label = strokeLabel(s, static_cast<int>(i)) + ": ";
            if (message.rfind(label, 0) == 0)
                message = message.substr(label.size());
            c.error(at, "the swept surface is not usable: " + message);
        }
    }
}

void readSweepSpec(Context& c, const QJsonObject& o, const std::string& path, SweepSpec& out) {
    Fields f(c, o, path);
    f.text("name", out.name);
    const bool hasFile = f.has("file"), hasCurves = f.has("curves");
    if (hasFile == hasCurves)
        c.error(path, hasFile ? "give either \"file\" or \"curves\", not both"
                              : "missing \"curves\" (inline sweep) or \"file\" (a sweep file)");
    if (f.text("file", out.file) && !hasCurves) {
        if (out.file.empty()) {
            c.error(f.at("file"), "must not be empty");
        } else if (c.checkFile(f.at("file"), out.file)) {
            SweepSurface sweep;
            if (Status s = readSweep(resolveScenarioPath(c.baseDir, out.file), sweep); !s.ok())
                c.error(f.at("file"), s.message());
        }
    }
    const QJsonValue cv = f.take("curves");
    QJsonArray curves;
    if (!cv.isUndefined() && readList(c, cv, f.at("curves"), curves)) {
        bool ok = true;
        long long points = 0;
        if (curves.size() < 2) {
            c.error(f.at("curves"),
                    "at least two curves are needed, got " + std::to_string(curves.size()));
            ok = false;
        }
        for (qsizetype i = 0; i < curves.size(); ++i) {
            const std::string at = element(f.at("curves"), i);
            std::vector<Vec3> curve;
            const qsizetype n = curves[i].toArray().size();
            if (points + n > kMaxSweepVertices) {
                c.error(at, "more than " + std::to_string(kMaxSweepVertices) +
                                " points in all curves; the rest are not read");
                ok = false;
                break;
            }
            points += n;
            if (!readPoints(c, curves[i], at, kMaxSweepVertices, curve)) {
                ok = false;
                continue;
            }
            if (curve.size() < 2) {
                c.error(at, "needs at least two points, got " + std::to_string(curve.size()));
                ok = false;
            } else if (!out.curves.empty() && curve.size() != out.curves.front().size()) {
                c.error(at, "has " + std::to_string(curve.size()) + " points but curves[0] has " +
                                std::to_string(out.curves.front().size()) +
                                " (all curves need the same count)");
                ok = false;
            }
            out.curves.push_back(std::move(curve));
        }
        if (ok) {
            SweepSurface sweep;
            if (Status s = SweepSurface::fromCurves(out.curves, sweep); !s.ok())
                c.error(f.at("curves"), "not a usable sweep surface: " + s.message());
        }
    }
    out.extra = f.unknown();
}

void readSweeps(Context& c, const QJsonValue& v, std::vector<SweepSpec>& out) {
    QJsonArray a;
    if (v.isUndefined() || !readList(c, v, "sweeps", a))
        return;
    for (qsizetype i = 0; i < a.size(); ++i) {
        const std::string at = element("sweeps", i);
        QJsonObject o;
        if (!asObject(c, a[i], at, o))
            continue;
        SweepSpec s;
        readSweepSpec(c, o, at, s);
        out.push_back(std::move(s));
    }
}

void readCutSettings(Context& c, const QJsonValue& v, CutSettings& out) {
    QJsonObject o;
    if (v.isUndefined() || !asObject(c, v, "cut_settings", o))
        return;
    Fields f(c, o, "cut_settings");
    std::string method = "hybrid";
    f.choice("method", {"hybrid", "subdivision"}, method);
    out.method = method == "hybrid" ? CutMethod::Hybrid : CutMethod::Subdivision;
    const bool hybrid = out.method == CutMethod::Hybrid;
    // Defaults follow `resect cut`: the full pipeline for hybrid, the plain baseline otherwise.
    std::string triangulation = hybrid ? "enhanced" : "standard";
    if (f.choice("triangulation", {"enhanced", "standard"}, triangulation) && !hybrid &&
        triangulation == "enhanced")
        c.error(f.at("triangulation"),
                "the enhanced triangulation applies to the hybrid method only");
    out.triangulation =
        triangulation == "enhanced" ? FaceTriangulation::Enhanced : FaceTriangulation::Standard;
    out.snap = hybrid;
    out.relaxSteps = hybrid ? 10 : 0;
    f.number("d", out.d, {0, CutLimits::kMaxD});
    f.boolean("snap", out.snap);
    f.integer("relax_steps", out.relaxSteps, 0, CutLimits::kMaxRelaxSteps);
    f.number("w_spring", out.wSpring, {0, CutLimits::kMaxRelaxWeight});
    f.number("w_particle", out.wParticle, {0, CutLimits::kMaxRelaxWeight});
    f.number("damping", out.damping, {0, CutLimits::kMaxRelaxDamping, true});
    f.integer("rings", out.rings, 1, CutLimits::kMaxRelaxRings);
    f.boolean("improve", out.improve);
    f.number("improve_quality", out.improveQuality, {0, CutLimits::kMaxImproveQuality});
    f.number("improve_short_edge", out.improveShortEdge, {0, CutLimits::kMaxImproveShortEdge});
    f.number("improve_coarsen", out.improveCoarsen, {0, CutLimits::kMaxImproveCoarsen});
    out.extra = f.unknown();
}

/// Checks the parameters of a known effect; unknown parameters are warnings (kept).
void checkEffectParameters(Context& c, const std::string& name, const QJsonObject& p,
                           const std::string& path) {
    Fields f(c, p, path);
    if (name == "deformation") {
        bool b;
        f.boolean("distance", b);
        f.boolean("volume", b);
        f.boolean("area", b);
    } else if (name == "gravity") {
        double a[3];
        if (f.has("acceleration"))
            readNumbers(c, f.take("acceleration"), f.at("acceleration"), 3,
                        {-EffectLimits::kMaxAcceleration, EffectLimits::kMaxAcceleration},
                        "[x, y, z] in mm/s^2", a);
    } else if (name == "tool-contact") {
        double r;
        f.number("radius", r, {0, EffectLimits::kMaxToolRadius, true}, true);
    } else if (name == "damping") {
        double d;
        f.number("coefficient", d, {0, EffectLimits::kMaxDampingCoefficient, true});
    }
    f.unknown();
}

void readEffects(Context& c, const QJsonValue& v, std::vector<EffectSpec>& out) {
    QJsonArray a;
    if (v.isUndefined() || !readList(c, v, "effects", a))
        return;
    std::set<std::string> names;
    for (qsizetype i = 0; i < a.size(); ++i) {
        const std::string at = element("effects", i);
        QJsonObject o;
        if (!asObject(c, a[i], at, o))
            continue;
        Fields f(c, o, at);
        EffectSpec e;
        const bool known = f.choice("name", knownEffectNames(), e.name, true);
        if (known && !names.insert(e.name).second)
            c.error(f.at("name"), "effect '" + e.name + "' declared twice");
        const QJsonValue pv = f.take("parameters");
        // Absent parameters are an empty object (as saving writes them): required ones are
        // still missing (found by fuzz_scenario: a tool-contact without "parameters" was
        // accepted, written with "parameters": {} and then refused).
        const bool object = pv.isUndefined() || asObject(c, pv, f.at("parameters"), e.parameters);
        if (object && known)
            checkEffectParameters(c, e.name, e.parameters, f.at("parameters"));
        e.extra = f.unknown();
        out.push_back(std::move(e));
    }
}

void readSimulation(Context& c, const QJsonValue& v, SimulationSettings& out) {
    QJsonObject o;
    if (v.isUndefined() || !asObject(c, v, "simulation", o))
        return;
    Fields f(c, o, "simulation");
    f.choice("integrator", {"implicit", "projective-dynamics", "symplectic-euler", "velocity-verlet", "backward-euler"},
             out.integrator);
    f.integer("iterations", out.iterations, 1, 1000);
    const QJsonValue dt = f.take("time_step");
    if (dt.isString()) {
        if (dt.toString() != QLatin1String("stable"))
            c.error(f.at("time_step"), "expected a number of seconds or \"stable\", got '" +
                                           dt.toString().toStdString() + "'");
    } else if (!dt.isUndefined() && !dt.isDouble()) {
        c.error(f.at("time_step"),
                "expected a number of seconds or \"stable\", got " + typeName(dt));
    } else if (dt.isDouble()) {
        readNumber(c, dt, f.at("time_step"), {0, 1, true}, out.timeStep);
    }
    f.choice("resected_pieces", {"rigid", "remove", "deformable"}, out.resectedPieces);
    const bool durationOk = f.number("duration", out.duration, {0, 1e5});
    if (durationOk && out.timeStep > 0 && out.duration / out.timeStep > kMaxSimulationSteps)
        c.error("simulation", "duration / time_step is " + num(out.duration / out.timeStep) +
                                  " steps, more than the limit of " + num(kMaxSimulationSteps));
    out.extra = f.unknown();
}

void readExpectations(Context& c, const QJsonValue& v, std::vector<Expectation>& out) {
    QJsonArray a;
    if (v.isUndefined() || !readList(c, v, "expectations", a))
        return;
    std::vector<std::string> kinds;
    for (ExpectationKind k : allExpectationKinds())
        kinds.push_back(expectationKindName(k));
    for (qsizetype i = 0; i < a.size(); ++i) {
        const std::string at = element("expectations", i);
        QJsonObject o;
        if (!asObject(c, a[i], at, o))
            continue;
        Fields f(c, o, at);
        Expectation e;
        std::string kind;
        if (f.choice("kind", kinds, kind, true)) {
            e.kind =
                allExpectationKinds()[std::find(kinds.begin(), kinds.end(), kind) - kinds.begin()];
            switch (e.kind) {
            case ExpectationKind::PiecesAtLeast:
                f.integer("value", e.value, 1, 1000000000, true);
                break;
            case ExpectationKind::MaxInvertedTets:
                f.integer("value", e.value, 0, 1000000000, true);
                break;
            case ExpectationKind::ResectedVolumeFractionAtLeast:
            case ExpectationKind::MinRadiusRatioAtLeast:
                f.number("value", e.value, {0, 1}, true);
                break;
            case ExpectationKind::StaysFinite: {
                bool b = true;
                if (f.boolean("value", b, true))
                    e.value = b ? 1 : 0;
                break;
            }
            }
        } else {
            f.take("value");
        }
        f.text("tissue", e.tissue);
        e.extra = f.unknown();
        out.push_back(std::move(e));
    }
}

/// Consistency between sections.
void crossCheck(Context& c, const Scenario& s, bool toolPresent) {
    if (!s.strokes.empty() && !toolPresent)
        c.error("tool", "missing: the strokes need a tool");
    for (std::size_t i = 0; i < s.effects.size(); ++i) {
        const EffectSpec& e = s.effects[i];
        const std::string at = element("effects", static_cast<qsizetype>(i));
        if (e.name == "tool-contact" && !toolPresent)
            c.error(at, "tool-contact needs a tool (\"tool\" is missing)");
        if (e.name == "fixed") {
            const bool any =
                std::any_of(s.tissues.begin(), s.tissues.end(),
                            [](const TissueSpec& t) { return !t.fixedRegions.empty(); });
            if (!any)
                c.error(at, "the fixed effect needs fixed_regions in a tissue, and none has any");
        }
        if (e.name == "damping" && !e.parameters.contains("coefficient"))
            for (std::size_t t = 0; t < s.tissues.size(); ++t)
                if (s.tissues[t].material.damping <= 0)
                    c.error(at, "damping has no coefficient and tissues[" + std::to_string(t) +
                                    "].material.damping is 0");
    }
    for (std::size_t i = 0; i < s.expectations.size(); ++i) {
        const Expectation& e = s.expectations[i];
        if (!e.tissue.empty() && !s.findTissue(e.tissue))
            c.error(child(element("expectations", static_cast<qsizetype>(i)), "tissue"),
                    "no tissue named '" + e.tissue + "'");
    }
    if (s.strokes.empty() && s.sweeps.empty())
        c.warning("strokes", "no strokes and no sweeps: the scenario cuts nothing");
}

void readDocument(Context& c, const QJsonObject& root, Scenario& s) {
    Fields f(c, root, "");
    f.take("format");
    f.take("version");
    readMetadata(c, f.take("metadata"), s.metadata);
    readTissues(c, f.take("tissues"), s.tissues);
    const QJsonValue tool = f.take("tool");
    const bool toolOk = readTool(c, tool, s.tool);
    readStrokes(c, f.take("strokes"), s, toolOk);
    readSweeps(c, f.take("sweeps"), s.sweeps);
    readCutSettings(c, f.take("cut_settings"), s.cut);
    readEffects(c, f.take("effects"), s.effects);
    readSimulation(c, f.take("simulation"), s.simulation);
    readExpectations(c, f.take("expectations"), s.expectations);
    crossCheck(c, s, !tool.isUndefined());
    s.extra = f.unknown();
}

/// Checks "format" and "version"; returns the version, or -1 after an error (reading stops).
int checkHeader(Context& c, const QJsonObject& root) {
    const QJsonValue format = root.value("format");
    if (format.isUndefined()) {
        c.error("format", std::string("missing (expected \"") + kScenarioFormat + "\")");
        return -1;
    }
    if (format != QJsonValue(QLatin1String(kScenarioFormat))) {
        c.error("format", std::string("expected \"") + kScenarioFormat + "\", got " +
                              (format.isString() ? "\"" + format.toString().toStdString() + "\""
                                                 : typeName(format)) +
                              ": not a scenario document");
        return -1;
    }
    const QJsonValue version = root.value("version");
    if (version.isUndefined()) {
        c.error("version", "missing (expected " + std::to_string(kScenarioVersion) + ")");
        return -1;
    }
    long long v = 0;
    if (!readInteger(c, version, "version", 0, std::numeric_limits<int>::max(), v))
        return -1;
    if (v > kScenarioVersion) {
        c.error("version", "version " + std::to_string(v) +
                               " is newer than this program reads (up to " +
                               std::to_string(kScenarioVersion) + ")");
        return -1;
    }
    return static_cast<int>(v);
}

std::string absoluteDir(const std::string& dir) {
    std::error_code ec;
    const fs::path p = fs::absolute(dir.empty() ? fs::path(".") : fs::path(dir), ec);
    return ec ? dir : p.lexically_normal().string();
}

} // namespace

Status parseScenario(const QByteArray& json, const std::string& baseDir, const std::string& name,
                     Scenario& out, ScenarioDiagnostics& diag) {
    diag.clear();
    try {
        Context c{diag, absoluteDir(baseDir)};
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(json, &error);
        if (error.error != QJsonParseError::NoError) {
            c.error("", "not valid JSON: " + error.errorString().toStdString() + " at offset " +
                            std::to_string(error.offset));
        } else if (!doc.isObject()) {
            c.error("", "expected a JSON object (a scenario document), got " +
                            std::string(doc.isArray() ? "an array" : "nothing"));
        } else {
            QJsonObject root = doc.object();
            const int version = checkHeader(c, root);
            if (version == 0)
                root = migrateScenarioV0(root, diag);
            if (version >= 0) {
                Scenario s;
                s.baseDir = c.baseDir;
                readDocument(c, root, s);
                if (!diag.hasErrors()) {
                    out = std::move(s);
                    return Status::success();
                }
            }
        }
    } catch (const std::exception& e) {
        diag.error("", std::string("internal error while reading: ") + e.what());
    } catch (...) {
        diag.error("", "internal error while reading");
    }
    return Status::error(diag.firstError(name));
}

Status loadScenario(const std::string& path, Scenario& out, ScenarioDiagnostics& diag) {
    diag.clear();
    QFile file(QString::fromStdString(path));
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        diag.error("", "no such file");
        return Status::error(path + ": no such file");
    }
    if (fs::is_directory(path, ec)) {
        diag.error("", "is a folder");
        return Status::error(path + ": is a folder, not a scenario file");
    }
    if (!file.open(QIODevice::ReadOnly)) {
        diag.error("", "cannot open (" + file.errorString().toStdString() + ")");
        return Status::error(path + ": cannot open (" + file.errorString().toStdString() + ")");
    }
    if (file.size() > kMaxFileBytes) {
        diag.error("", "larger than 256 MiB; not a scenario file");
        return Status::error(path + ": larger than 256 MiB; not a scenario file");
    }
    const std::string folder = fs::path(path).parent_path().string();
    return parseScenario(file.readAll(), folder, path, out, diag);
}

Status validateScenario(const Scenario& scenario, ScenarioDiagnostics& diag) {
    const QByteArray json = QJsonDocument(scenarioToJson(scenario)).toJson(QJsonDocument::Compact);
    Scenario parsed;
    return parseScenario(json, scenario.baseDir, "scenario", parsed, diag);
}

} // namespace resect
