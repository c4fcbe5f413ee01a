#include "scenario/mesh_io_detail.h"

#include <exception>
#include <new>

#include "core/mesh/masses.h"
#include "core/mesh/material.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/topology.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace resect::detail {

Status guarded(const std::string& path, const char* action, const std::function<Status()>& body) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return Status::error(path + ": out of memory while " + action);
    } catch (const std::exception& e) {
        return Status::error(path + ": " + e.what());
    } catch (...) {
        return Status::error(path + ": unknown error while " + action);
    }
}

namespace fs = std::filesystem;

Status checkRegularFile(const std::string& path) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st))
        return Status::error(path + ": no such file");
    if (!fs::is_regular_file(st))
        return Status::error(path + ": not a regular file");
    return Status::success();
}

Status readWholeFile(const std::string& path, std::string& out) {
    if (Status s = checkRegularFile(path); !s)
        return s;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Status::error(path + ": cannot open for reading");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        return Status::error(path + ": read error");
    out = std::move(text);
    return Status::success();
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

namespace {
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}
} // namespace

void splitTokens(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i]))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && !isSpace(line[i]))
            ++i;
        if (i > start)
            out.push_back(line.substr(start, i - start));
    }
}

bool parseInt64(std::string_view token, std::int64_t& value) {
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    if (token.empty())
        return false;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

bool parseDouble(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    if (token.empty())
        return false;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

LineReader::LineReader(std::string_view text) : m_text(text) {
    m_totalLines = std::count(text.begin(), text.end(), '\n');
    if (!text.empty() && text.back() != '\n')
        ++m_totalLines;
}

bool LineReader::next(std::string_view& line) {
    if (m_pos >= m_text.size())
        return false;
    std::size_t end = m_text.find('\n', m_pos);
    if (end == std::string_view::npos)
        end = m_text.size();
    line = m_text.substr(m_pos, end - m_pos);
    if (!line.empty() && line.back() == '\r')
        line.remove_suffix(1);
    m_pos = end + 1;
    ++m_lineNumber;
    return true;
}

bool LineReader::nextContent(std::string_view& line, char comment) {
    while (next(line)) {
        if (comment != '\0') {
            const std::size_t c = line.find(comment);
            if (c != std::string_view::npos)
                line = line.substr(0, c);
        }
        if (std::any_of(line.begin(), line.end(), [](char ch) { return !isSpace(ch); }))
            return true;
    }
    return false;
}

Status finishImportedMesh(const std::string& path, ImportedMesh imported, TetMesh& out,
                          MeshReadReport* report) {
    std::vector<Vec3>& points = imported.points;
    std::vector<Tet>& tets = imported.tets;
    const auto label = [&](int t) {
        return imported.tetLabel ? imported.tetLabel(t) : "tet " + std::to_string(t);
    };
    if (tets.empty())
        return Status::error(path + ": no tetrahedra");
    if (const std::string bad = checkTetIndices(static_cast<int>(points.size()), tets);
        !bad.empty())
        return Status::error(path + ": " + bad);
    for (std::size_t n = 0; n < points.size(); ++n)
        if (!points[n].allFinite())
            return Status::error(path + ": node " + std::to_string(n) +
                                 " has a non-finite coordinate");
    // The optional per-node data: one value per point, finite (masses >= 0).
    const auto checkVectors = [&](const std::vector<Vec3>& values, const char* what) {
        if (values.empty())
            return Status::success();
        if (values.size() != points.size())
            return Status::error(path + ": " + what + " has " + std::to_string(values.size()) +
                                 " values, but there are " + std::to_string(points.size()) +
                                 " nodes");
        for (std::size_t n = 0; n < values.size(); ++n)
            if (!values[n].allFinite())
                return Status::error(path + ": " + what + " of node " + std::to_string(n) +
                                     " is not finite");
        return Status::success();
    };
    if (Status s = checkVectors(imported.reference, "reference_position"); !s)
        return s;
    if (Status s = checkVectors(imported.velocity, "velocity"); !s)
        return s;
    if (!imported.mass.empty()) {
        if (imported.mass.size() != points.size())
            return Status::error(path + ": mass has " + std::to_string(imported.mass.size()) +
                                 " values, but there are " + std::to_string(points.size()) +
                                 " nodes");
        for (std::size_t n = 0; n < imported.mass.size(); ++n)
            if (!std::isfinite(imported.mass[n]) || imported.mass[n] < 0)
                return Status::error(path + ": mass of node " + std::to_string(n) + " is " +
                                     std::to_string(imported.mass[n]) +
                                     "; masses must be finite and >= 0");
    }
    if (!imported.tetGroup.empty() && imported.tetGroup.size() != tets.size())
        return Status::error(path + ": group tags for " + std::to_string(imported.tetGroup.size()) +
                             " of " + std::to_string(tets.size()) + " tetrahedra");

    // Orientation, exact, in the reference configuration: positive is kept, negative is
    // repaired by swapping two nodes (which flips the sign of the determinant), zero volume
    // cannot be repaired.
    const std::vector<Vec3>& ref = imported.reference.empty() ? points : imported.reference;
    for (std::size_t t = 0; t < tets.size(); ++t) {
        Tet& q = tets[t];
        const int o = orient3d(ref[q[0]], ref[q[1]], ref[q[2]], ref[q[3]]);
        if (o == 0)
            return Status::error(path + ": " + label(static_cast<int>(t)) +
                                 " has zero volume (its four nodes are coplanar)");
        if (o < 0)
            std::swap(q[2], q[3]);
    }

    // Keep only nodes used by a tet, in file order: an unused node would get zero mass.
    std::vector<int> newIndex(points.size(), -1);
    for (const Tet& q : tets)
        for (int v : q)
            newIndex[v] = 0;
    std::vector<int> kept;
    kept.reserve(points.size());
    for (std::size_t n = 0; n < points.size(); ++n)
        if (newIndex[n] == 0) {
            newIndex[n] = static_cast<int>(kept.size());
            kept.push_back(static_cast<int>(n));
        }
    for (Tet& q : tets)
        for (int& v : q)
            v = newIndex[v];
    const auto pick = [&](const std::vector<Vec3>& from) {
        std::vector<Vec3> to(kept.size());
        for (std::size_t i = 0; i < kept.size(); ++i)
            to[i] = from[static_cast<std::size_t>(kept[i])];
        return to;
    };

    TetMesh mesh = TetMesh::fromArrays(pick(ref), std::move(tets));
    const std::vector<Vec3> current = pick(points);
    std::copy(current.begin(), current.end(), mesh.positions().begin());
    if (!imported.velocity.empty()) {
        const std::vector<Vec3> velocity = pick(imported.velocity);
        std::copy(velocity.begin(), velocity.end(), mesh.velocities().begin());
    }
    if (!imported.mass.empty()) {
        for (std::size_t i = 0; i < kept.size(); ++i)
            mesh.masses()[i] = imported.mass[static_cast<std::size_t>(kept[i])];
    } else if (Status s = computeCheckedMasses(path, mesh); !s) {
        return s;
    }
    out = std::move(mesh);
    if (report) {
        report->tetGroup = std::move(imported.tetGroup);
        for (MeshReadReport::Group& g : report->groups)
            if (g.dimension == 3)
                g.tets = std::count(report->tetGroup.begin(), report->tetGroup.end(), g.tag);
    }
    return Status::success();
}

TetAttributes tetAttributes(const TetMesh& mesh) {
    TetAttributes a;
    const std::vector<TetQuality> qualities = tetQualities(mesh);
    a.quality.resize(qualities.size());
    for (std::size_t t = 0; t < qualities.size(); ++t)
        a.quality[t] = qualities[t].radiusRatio;
    Components components = connectedComponents(mesh);
    a.piece = std::move(components.tetComponent);
    a.pieceCount = components.count;
    return a;
}

Status checkWritableMesh(const std::string& path, const TetMesh& mesh) {
    const auto n = static_cast<std::size_t>(mesh.nodeCount());
    if (mesh.positions().size() != n || mesh.velocities().size() != n || mesh.masses().size() != n)
        return Status::error(path + ": cannot write a mesh whose node arrays differ in size");
    if (const std::string bad = checkTetIndices(mesh.nodeCount(), mesh.tets()); !bad.empty())
        return Status::error(path + ": cannot write an invalid mesh: " + bad);
    return Status::success();
}

std::string exactText(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

Status computeCheckedMasses(const std::string& path, TetMesh& mesh) {
    computeLumpedMasses(mesh, Material{}.density);
    const std::span<const double> mass = mesh.masses();
    for (std::size_t n = 0; n < mass.size(); ++n)
        if (!std::isfinite(mass[n]) || !(mass[n] > 0))
            return Status::error(path + ": node " + std::to_string(n) + " gets mass " +
                                 std::to_string(mass[n]) +
                                 " from the volumes of its tets; the coordinates are too large "
                                 "or the tets too small for double precision");
    return Status::success();
}

} // namespace resect::detail
