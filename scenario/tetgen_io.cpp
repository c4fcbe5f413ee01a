// TetGen .node/.ele import (https://wias-berlin.de/software/tetgen/fformats.html).
//
//   .node: "numPoints 3 numAttributes numBoundaryMarkers (0 or 1)", then per point
//          "index x y z [attributes] [marker]"
//   .ele:  "numTets nodesPerTet (4 or 10) numAttributes", then per tet
//          "index n0 n1 n2 n3 [more nodes] [attributes]"
// '#' starts a comment that runs to the end of the line; blank lines are ignored. Point
// indices are consecutive from the first point's index, which must be 0 or 1; the .ele file
// uses the same base. Of a 10-node tet only the four corners (listed first) are used.
// Boundary markers are ignored. Point attributes are ignored, except in the files
// writeTetGen writes: a comment line kAttributeComment before the header and exactly 4
// attributes give the reference position and mass of each point. The first tet attribute
// (TetGen's region attribute, -A) becomes the tet's volume group if every tet has an
// integer one (0: no region).
//
// Writing (writeTetGen): .node "N 3 4 0" with attributes reference x y z and mass, .ele
// "T 4 1" with region attribute piece + 1; points numbered from 1, like TetGen's output.

#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace resect {
namespace {

using namespace detail;

constexpr char kComment = '#';
/// The comment line (before the header) that names the node attributes writeTetGen writes.
constexpr std::string_view kAttributeComment =
    "# resect attributes: reference_position.x reference_position.y reference_position.z mass";
constexpr std::int64_t kResectAttributes = 4;

/// `line` without leading and trailing blanks.
std::string_view trimmed(std::string_view line) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!line.empty() && blank(line.front()))
        line.remove_prefix(1);
    while (!line.empty() && blank(line.back()))
        line.remove_suffix(1);
    return line;
}

Status lineError(const std::string& path, const LineReader& lines, const std::string& what) {
    return Status::error(path + ": line " + std::to_string(lines.lineNumber()) + ": " + what);
}

/// The other file of the pair: same name with the extension `ext` (".node" or ".ele"),
/// upper-cased if the given extension is upper case.
std::string siblingPath(const std::string& path, const std::string& ext) {
    std::filesystem::path p(path);
    const std::string given = p.extension().string();
    const bool upper = given.size() > 1 && std::isupper(static_cast<unsigned char>(given[1]));
    std::string e = ext;
    if (upper)
        for (char& c : e)
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    p.replace_extension(e);
    return p.string();
}

/// Reads the .node file; `base` receives the index of the first point (0 or 1); the
/// reference positions and masses of our own files go to `imported`.
Status readNodeFile(const std::string& path, ImportedMesh& imported, int& base) {
    std::vector<Vec3>& points = imported.points;
    std::string text;
    if (Status s = readWholeFile(path, text); !s)
        return s;
    LineReader lines(text);
    std::string_view line;
    std::vector<std::string_view> tok;
    bool named = false; // the attribute comment came before the header
    for (;;) {
        if (!lines.next(line))
            return Status::error(path + ": empty file");
        const std::string_view t = trimmed(line);
        if (t == kAttributeComment)
            named = true;
        const std::string_view content = t.substr(0, t.find(kComment));
        if (!trimmed(content).empty()) {
            line = content;
            break;
        }
    }
    splitTokens(line, tok);
    std::int64_t count = 0, dim = 0, attributes = 0;
    if (tok.size() < 2 || !parseInt64(tok[0], count) || !parseInt64(tok[1], dim) ||
        (tok.size() >= 3 && !parseInt64(tok[2], attributes)))
        return lineError(path, lines,
                         "expected \"numPoints dimension numAttributes numBoundaryMarkers\"");
    const bool ours = named && attributes == kResectAttributes;
    if (dim != 3)
        return lineError(path, lines, "dimension " + std::to_string(dim) + ", expected 3");
    // One point per line: the count cannot exceed the lines that follow.
    if (count <= 0 || count > lines.remainingLines() || count > kMaxMeshItems)
        return lineError(path, lines,
                         "declares " + std::to_string(count) + " points, but " +
                             std::to_string(lines.remainingLines()) + " lines follow");
    points.reserve(static_cast<std::size_t>(count));
    if (ours) {
        imported.reference.reserve(static_cast<std::size_t>(count));
        imported.mass.reserve(static_cast<std::size_t>(count));
    }
    for (std::int64_t i = 0; i < count; ++i) {
        if (!lines.nextContent(line, kComment))
            return Status::error(path + ": unexpected end of file after " + std::to_string(i) +
                                 " of " + std::to_string(count) + " points");
        splitTokens(line, tok);
        std::int64_t index = 0;
        Vec3 p;
        if (tok.size() < 4 || !parseInt64(tok[0], index) || !parseDouble(tok[1], p.x()) ||
            !parseDouble(tok[2], p.y()) || !parseDouble(tok[3], p.z()))
            return lineError(path, lines, "expected \"index x y z\"");
        if (i == 0) {
            if (index != 0 && index != 1)
                return lineError(path, lines,
                                 "the first point index is " + std::to_string(index) +
                                     "; TetGen numbers points from 0 or 1");
            base = static_cast<int>(index);
        }
        if (index != base + i)
            return lineError(path, lines,
                             "point index " + std::to_string(index) + ", expected " +
                                 std::to_string(base + i) + " (indices must be consecutive)");
        if (!p.allFinite())
            return lineError(path, lines,
                             "point " + std::to_string(index) + " has a non-finite coordinate");
        points.push_back(p);
        if (ours) {
            Vec3 r;
            double m = 0;
            if (tok.size() < 8 || !parseDouble(tok[4], r.x()) || !parseDouble(tok[5], r.y()) ||
                !parseDouble(tok[6], r.z()) || !parseDouble(tok[7], m))
                return lineError(path, lines,
                                 "expected \"index x y z\" and the attributes reference_position "
                                 "x y z and mass");
            if (!r.allFinite())
                return lineError(path, lines, "point " + std::to_string(index) +
                                                  " has a non-finite reference position");
            // The simulation needs positive masses; a zero or negative one is damage.
            if (!std::isfinite(m) || !(m > 0))
                return lineError(path, lines, "point " + std::to_string(index) + " has mass " +
                                                  std::to_string(m) +
                                                  "; masses must be finite and positive");
            imported.reference.push_back(r);
            imported.mass.push_back(m);
        }
    }
    return Status::success();
}

/// Reads the .ele file; `regions` receives each tet's first attribute if every tet has an
/// integer one (else it stays empty).
Status readEleFile(const std::string& path, int base, std::int64_t pointCount,
                   std::vector<Tet>& tets, std::vector<std::int64_t>& numbers,
                   std::vector<std::int64_t>& regions) {
    std::string text;
    if (Status s = readWholeFile(path, text); !s)
        return s;
    LineReader lines(text);
    std::string_view line;
    std::vector<std::string_view> tok;
    if (!lines.nextContent(line, kComment))
        return Status::error(path + ": empty file");
    splitTokens(line, tok);
    std::int64_t count = 0, perTet = 0, attributes = 0;
    if (tok.size() < 2 || !parseInt64(tok[0], count) || !parseInt64(tok[1], perTet) ||
        (tok.size() >= 3 && !parseInt64(tok[2], attributes)))
        return lineError(path, lines, "expected \"numTetrahedra nodesPerTet numAttributes\"");
    bool integerRegions = attributes > 0;
    if (perTet != 4 && perTet != 10)
        return lineError(path, lines,
                         std::to_string(perTet) + " nodes per tetrahedron, expected 4 or 10");
    if (count <= 0 || count > lines.remainingLines() || count > kMaxMeshItems)
        return lineError(path, lines,
                         "declares " + std::to_string(count) + " tetrahedra, but " +
                             std::to_string(lines.remainingLines()) + " lines follow");
    tets.reserve(static_cast<std::size_t>(count));
    numbers.reserve(static_cast<std::size_t>(count));
    for (std::int64_t i = 0; i < count; ++i) {
        if (!lines.nextContent(line, kComment))
            return Status::error(path + ": unexpected end of file after " + std::to_string(i) +
                                 " of " + std::to_string(count) + " tetrahedra");
        splitTokens(line, tok);
        std::int64_t v[5];
        bool ok = tok.size() >= static_cast<std::size_t>(1 + perTet);
        for (int k = 0; ok && k < 5; ++k)
            ok = parseInt64(tok[k], v[k]);
        if (!ok)
            return lineError(path, lines,
                             "expected \"index\" and " + std::to_string(perTet) + " node indices");
        Tet t;
        for (int k = 0; k < 4; ++k) {
            const std::int64_t n = v[k + 1] - base;
            if (n < 0 || n >= pointCount)
                return lineError(path, lines,
                                 "tetrahedron " + std::to_string(v[0]) + " refers to point " +
                                     std::to_string(v[k + 1]) + ", which is not in the .node file");
            t[k] = static_cast<int>(n);
        }
        tets.push_back(t);
        numbers.push_back(v[0]);
        if (integerRegions) {
            double region = 0;
            const auto at = static_cast<std::size_t>(1 + perTet);
            integerRegions = tok.size() > at && parseDouble(tok[at], region) &&
                             std::fabs(region) < 1e15 && region == std::floor(region);
            regions.push_back(static_cast<std::int64_t>(region));
        }
    }
    if (!integerRegions)
        regions.clear();
    return Status::success();
}

} // namespace

Status readTetGen(const std::string& path, TetMesh& out, MeshReadReport* report) {
    try {
        const std::string ext = lowerExtension(path);
        std::string nodePath, elePath;
        if (ext == ".node") {
            nodePath = path;
            elePath = siblingPath(path, ".ele");
        } else if (ext == ".ele") {
            elePath = path;
            nodePath = siblingPath(path, ".node");
        } else {
            return Status::error(path + ": a TetGen mesh needs a .node or .ele file name");
        }
        if (Status s = checkRegularFile(path); !s)
            return s;
        const std::string& other = (ext == ".node") ? elePath : nodePath;
        if (Status s = checkRegularFile(other); !s)
            return Status::error(s.message() + " (the other half of the TetGen pair " + path + ")");

        ImportedMesh imported;
        int base = 0;
        if (Status s = readNodeFile(nodePath, imported, base); !s)
            return s;
        std::vector<std::int64_t> numbers;
        if (Status s = readEleFile(elePath, base, static_cast<std::int64_t>(imported.points.size()),
                                   imported.tets, numbers, imported.tetGroup);
            !s)
            return s;
        imported.tetLabel = [numbers = std::move(numbers)](int t) {
            return "tetrahedron " + std::to_string(numbers[static_cast<std::size_t>(t)]);
        };
        MeshReadReport local;
        local.format = "TetGen";
        for (std::int64_t tag : imported.tetGroup) {
            const auto same = [&](const MeshReadReport::Group& g) { return g.tag == tag; };
            if (tag != 0 &&
                std::find_if(local.groups.begin(), local.groups.end(), same) == local.groups.end())
                local.groups.push_back({3, tag, "", 0});
        }
        if (local.groups.empty())
            imported.tetGroup.clear();
        if (Status s = finishImportedMesh(elePath, std::move(imported), out, &local); !s)
            return s;
        if (report)
            *report = std::move(local);
        return Status::success();
    } catch (const std::bad_alloc&) {
        return Status::error(path + ": out of memory while reading");
    } catch (const std::exception& e) {
        return Status::error(path + ": " + e.what());
    }
}


namespace {

std::string nodeText(const TetMesh& mesh) {
    std::string s = std::string(kAttributeComment) + "\n" + std::to_string(mesh.nodeCount()) +
                    " 3 " + std::to_string(kResectAttributes) + " 0\n";
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const Vec3& p = mesh.positions()[static_cast<std::size_t>(n)];
        const Vec3& r = mesh.referencePositions()[static_cast<std::size_t>(n)];
        s += std::to_string(n + 1) + " " + exactText(p.x()) + " " + exactText(p.y()) + " " +
             exactText(p.z()) + " " + exactText(r.x()) + " " + exactText(r.y()) + " " +
             exactText(r.z()) + " " + exactText(mesh.masses()[static_cast<std::size_t>(n)]) + "\n";
    }
    return s;
}

std::string eleText(const TetMesh& mesh) {
    const TetAttributes attributes = tetAttributes(mesh);
    std::string s = "# region attribute: piece + 1\n" + std::to_string(mesh.tetCount()) + " 4 1\n";
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        s += std::to_string(t + 1) + " " + std::to_string(q[0] + 1) + " " +
             std::to_string(q[1] + 1) + " " + std::to_string(q[2] + 1) + " " +
             std::to_string(q[3] + 1) + " " +
             std::to_string(attributes.piece[static_cast<std::size_t>(t)] + 1) + "\n";
    }
    return s;
}

} // namespace

Status writeTetGen(const std::string& path, const TetMesh& mesh) {
    return guarded(path, "writing", [&]() -> Status {
        const std::string ext = lowerExtension(path);
        if (ext != ".node" && ext != ".ele")
            return Status::error(path + ": a TetGen mesh needs a .node or .ele file name");
        if (Status s = checkWritableMesh(path, mesh); !s)
            return s;
        const std::string nodePath = ext == ".node" ? path : siblingPath(path, ".node");
        const std::string elePath = ext == ".ele" ? path : siblingPath(path, ".ele");
        if (Status s = writeFileAtomically(nodePath, nodeText(mesh)); !s)
            return s;
        return writeFileAtomically(elePath, eleText(mesh));
    });
}

} // namespace resect
