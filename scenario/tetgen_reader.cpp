// TetGen .node/.ele import (https://wias-berlin.de/software/tetgen/fformats.html).
//
//   .node: "numPoints 3 numAttributes numBoundaryMarkers (0 or 1)", then per point
//          "index x y z [attributes] [marker]"
//   .ele:  "numTets nodesPerTet (4 or 10) numAttributes", then per tet
//          "index n0 n1 n2 n3 [more nodes] [attributes]"
// '#' starts a comment that runs to the end of the line; blank lines are ignored. Point
// indices are consecutive from the first point's index, which must be 0 or 1; the .ele file
// uses the same base. Attributes and boundary markers are ignored; of a 10-node tet only
// the four corners (listed first) are used.

#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

#include <cctype>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace resect {
namespace {

using namespace detail;

constexpr char kComment = '#';

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

/// Reads the .node file; `base` receives the index of the first point (0 or 1).
Status readNodeFile(const std::string& path, std::vector<Vec3>& points, int& base) {
    std::string text;
    if (Status s = readWholeFile(path, text); !s)
        return s;
    LineReader lines(text);
    std::string_view line;
    std::vector<std::string_view> tok;
    if (!lines.nextContent(line, kComment))
        return Status::error(path + ": empty file");
    splitTokens(line, tok);
    std::int64_t count = 0, dim = 0;
    if (tok.size() < 2 || !parseInt64(tok[0], count) || !parseInt64(tok[1], dim))
        return lineError(path, lines,
                         "expected \"numPoints dimension numAttributes numBoundaryMarkers\"");
    if (dim != 3)
        return lineError(path, lines, "dimension " + std::to_string(dim) + ", expected 3");
    // One point per line: the count cannot exceed the lines that follow.
    if (count <= 0 || count > lines.remainingLines() || count > kMaxMeshItems)
        return lineError(path, lines,
                         "declares " + std::to_string(count) + " points, but " +
                             std::to_string(lines.remainingLines()) + " lines follow");
    points.reserve(static_cast<std::size_t>(count));
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
    }
    return Status::success();
}

Status readEleFile(const std::string& path, int base, std::int64_t pointCount,
                   std::vector<Tet>& tets, std::vector<std::int64_t>& numbers) {
    std::string text;
    if (Status s = readWholeFile(path, text); !s)
        return s;
    LineReader lines(text);
    std::string_view line;
    std::vector<std::string_view> tok;
    if (!lines.nextContent(line, kComment))
        return Status::error(path + ": empty file");
    splitTokens(line, tok);
    std::int64_t count = 0, perTet = 0;
    if (tok.size() < 2 || !parseInt64(tok[0], count) || !parseInt64(tok[1], perTet))
        return lineError(path, lines, "expected \"numTetrahedra nodesPerTet numAttributes\"");
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
    }
    return Status::success();
}

} // namespace

Status readTetGen(const std::string& path, TetMesh& out) {
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
        if (Status s = readNodeFile(nodePath, imported.points, base); !s)
            return s;
        std::vector<std::int64_t> numbers;
        if (Status s = readEleFile(elePath, base, static_cast<std::int64_t>(imported.points.size()),
                                   imported.tets, numbers);
            !s)
            return s;
        imported.tetLabel = [numbers = std::move(numbers)](int t) {
            return "tetrahedron " + std::to_string(numbers[static_cast<std::size_t>(t)]);
        };
        return finishImportedMesh(elePath, std::move(imported), out);
    } catch (const std::bad_alloc&) {
        return Status::error(path + ": out of memory while reading");
    } catch (const std::exception& e) {
        return Status::error(path + ": " + e.what());
    }
}

} // namespace resect
