#include "fuzz/fuzz_inputs.h"

#include "core/mesh/predicates.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace resect::fuzz {
namespace {

std::vector<Target>& registry() {
    static std::vector<Target> targets;
    return targets;
}

/// The scratch folder, removed when the process exits normally.
class ScratchDir {
public:
    ScratchDir() {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern =
            (std::filesystem::path(tmp && *tmp ? tmp : "/tmp") / "resect-fuzz-XXXXXX").string();
        if (mkdtemp(pattern.data()))
            m_path = pattern;
    }
    ~ScratchDir() {
        std::error_code ec;
        if (!m_path.empty())
            std::filesystem::remove_all(m_path, ec);
    }
    const std::string& path() const { return m_path; }

private:
    std::string m_path;
};

} // namespace

bool registerTarget(const char* name, InputFunction run) {
    registry().push_back({name, run});
    return true;
}

std::vector<Target> targets() {
    std::vector<Target> all = registry();
    std::sort(all.begin(), all.end(),
              [](const Target& a, const Target& b) { return std::string_view(a.name) < b.name; });
    return all;
}

const Target* findTarget(std::string_view name) {
    for (const Target& t : registry())
        if (name == t.name)
            return &t;
    return nullptr;
}

const std::string& scratchDir() {
    static const ScratchDir dir;
    return dir.path();
}

std::string writeScratchFile(const std::string& name, std::span<const std::uint8_t> bytes) {
    const std::string path = (std::filesystem::path(scratchDir()) / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (scratchDir().empty() || !out) {
        std::fprintf(stderr, "fuzz harness: cannot write %s\n", path.c_str());
        std::abort();
    }
    return path;
}

Outcome rejected(const Status& status, std::initializer_list<std::string_view> paths) {
    if (status.ok())
        return Outcome::broken("rejected() called with a success");
    for (std::string_view p : paths)
        if (status.message().find(p) != std::string::npos)
            return {Outcome::Kind::Rejected, status.message()};
    return Outcome::broken("the error does not name the file: " + status.message());
}

std::string checkTetMesh(const TetMesh& mesh, bool importedMesh) {
    const auto n = static_cast<std::size_t>(mesh.nodeCount());
    if (n == 0 || mesh.tetCount() == 0)
        return "accepted a mesh without nodes or tets";
    if (mesh.positions().size() != n || mesh.velocities().size() != n || mesh.masses().size() != n)
        return "node arrays differ in size";
    if (const std::string bad = checkTetIndices(mesh.nodeCount(), mesh.tets()); !bad.empty())
        return bad;
    for (std::size_t i = 0; i < n; ++i) {
        if (!mesh.referencePositions()[i].allFinite() || !mesh.positions()[i].allFinite() ||
            !mesh.velocities()[i].allFinite())
            return "node " + std::to_string(i) + " has a non-finite coordinate or velocity";
        const double m = mesh.masses()[i];
        if (!std::isfinite(m) || m < 0)
            return "node " + std::to_string(i) + " has mass " + std::to_string(m);
        if (importedMesh && !(m > 0))
            return "imported node " + std::to_string(i) + " has zero mass";
    }
    std::vector<char> used(n, 0);
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        if (orient3d(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3])) <= 0)
            return "tet " + std::to_string(t) + " is not positively oriented";
        for (int v : q)
            used[static_cast<std::size_t>(v)] = 1;
    }
    if (importedMesh)
        if (const auto it = std::find(used.begin(), used.end(), 0); it != used.end())
            return "imported node " + std::to_string(it - used.begin()) + " is used by no tet";
    return {};
}

std::string checkSweep(const SweepSurface& sweep) {
    const int m = sweep.curveCount(), points = sweep.pointsPerCurve();
    if (m < 2 || points < 2)
        return "accepted a sweep with " + std::to_string(m) + " curves of " +
               std::to_string(points) + " points";
    const auto vertices = static_cast<std::size_t>(m) * static_cast<std::size_t>(points);
    if (sweep.vertices().size() != vertices)
        return "the sweep has " + std::to_string(sweep.vertices().size()) + " vertices, expected " +
               std::to_string(vertices);
    if (sweep.triangles().size() != 2 * static_cast<std::size_t>(m - 1) * (points - 1))
        return "the sweep has " + std::to_string(sweep.triangles().size()) + " triangles";
    for (const Vec3& p : sweep.vertices())
        if (!p.allFinite())
            return "a sweep vertex is not finite";
    for (const Tri& t : sweep.triangles())
        for (int v : t)
            if (v < 0 || static_cast<std::size_t>(v) >= vertices)
                return "a sweep triangle refers to vertex " + std::to_string(v);
    const auto curves = sweep.curves();
    if (curves.size() != static_cast<std::size_t>(m))
        return "curves() returns " + std::to_string(curves.size()) + " curves";
    return {};
}

std::string checkSurface(const TriangleSurface& surface) {
    if (surface.triangles.empty())
        return "accepted a surface without triangles";
    const auto n = static_cast<int>(surface.positions.size());
    for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
        const Tri& t = surface.triangles[f];
        for (int v : t)
            if (v < 0 || v >= n)
                return "triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                       " of " + std::to_string(n);
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
            return "triangle " + std::to_string(f) + " has a repeated corner";
    }
    for (const Vec3& p : surface.positions)
        if (!p.allFinite())
            return "a surface vertex is not finite";
    if (!surface.uvs.empty()) {
        if (surface.uvs.size() != surface.positions.size())
            return std::to_string(surface.uvs.size()) + " texture coordinates for " +
                   std::to_string(n) + " vertices";
        for (const Eigen::Vector2d& uv : surface.uvs)
            if (!uv.allFinite())
                return "a texture coordinate is not finite";
    }
    if (!surface.cutFaces.empty() || !surface.cutUvs.empty())
        return "a surface read from a file has cut-face data";
    return {};
}

} // namespace resect::fuzz
