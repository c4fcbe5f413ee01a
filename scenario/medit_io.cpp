// Medit .mesh, ASCII (the format of mmg, TetWild and fTetWild; P. J. Frey, "MEDIT: an
// interactive mesh visualization software", INRIA RT-0253, and libMeshb's keyword list).
//
//   MeshVersionFormatted 1|2
//   Dimension 3
//   Vertices     n, then n records "x y z ref"
//   Tetrahedra   n, then n records "v1 v2 v3 v4 ref" (1-based vertex numbers)
//   Triangles, Edges, Quadrilaterals, Hexahedra, Prisms, Pyramids, ...   (dropped, counted)
//   Corners, Ridges, RequiredVertices, Normals, Tangents, ...             (ignored)
//   End
// Keywords are case-insensitive; a count may follow on the same or the next line; '#'
// starts a comment that runs to the end of the line. Tet references become volume groups
// (tag = reference; 0 means none). The binary variant .meshb is refused.
//
// Writing: MeshVersionFormatted 2 (doubles), Vertices = current positions with reference 0,
// the boundary Triangles (outward, reference piece + 1) and Tetrahedra (reference
// piece + 1), doubles as their shortest exact text.

#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

#include "core/mesh/topology.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

namespace resect {
namespace {

using namespace detail;

constexpr char kComment = '#';
/// Records hold at least one value and a separator per number.
constexpr std::int64_t kMinBytesPerNumber = 2;

/// A section the reader skips: its keyword, the numbers per record, and, for elements,
/// what the read report calls them ("" for lists that are not elements).
struct SkippedSection {
    std::string_view keyword;
    int numbers;
    std::string_view element;
};
constexpr std::array<SkippedSection, 26> kSkipped{{
    {"Edges", 3, "2-node edge"},
    {"Triangles", 4, "3-node triangle"},
    {"Quadrilaterals", 5, "4-node quadrilateral"},
    {"Hexahedra", 9, "8-node hexahedron"},
    {"Prisms", 7, "6-node prism"},
    {"Pyramids", 6, "5-node pyramid"},
    {"EdgesP2", 4, "3-node edge"},
    {"TrianglesP2", 7, "6-node triangle"},
    {"QuadrilateralsQ2", 10, "9-node quadrilateral"},
    {"TetrahedraP2", 11, "10-node tetrahedron"},
    {"HexahedraQ2", 28, "27-node hexahedron"},
    {"Corners", 1, ""},
    {"Ridges", 1, ""},
    {"RequiredVertices", 1, ""},
    {"RequiredEdges", 1, ""},
    {"RequiredTriangles", 1, ""},
    {"RequiredQuadrilaterals", 1, ""},
    {"RequiredTetrahedra", 1, ""},
    {"RequiredHexahedra", 1, ""},
    {"Normals", 3, ""},
    {"Tangents", 3, ""},
    {"NormalAtVertices", 2, ""},
    {"TangentAtVertices", 2, ""},
    {"NormalAtTriangleVertices", 3, ""},
    {"NormalAtQuadrilateralVertices", 3, ""},
    {"TangentAtEdges", 3, ""},
}};

bool equalsNoCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

/// The tokens of a text with '#' comments, with the line of the last one for errors.
class Tokens {
public:
    explicit Tokens(std::string_view text) : m_text(text) {}
    bool next(std::string_view& t) {
        while (m_pos < m_text.size()) {
            const char c = m_text[m_pos];
            if (c == '\n') {
                ++m_line;
                ++m_pos;
            } else if (c == kComment) {
                const std::size_t eol = m_text.find('\n', m_pos);
                m_pos = eol == std::string_view::npos ? m_text.size() : eol;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {
                ++m_pos;
            } else {
                const std::size_t start = m_pos;
                while (m_pos < m_text.size() && !isSeparator(m_text[m_pos]))
                    ++m_pos;
                t = m_text.substr(start, m_pos - start);
                return true;
            }
        }
        return false;
    }
    /// 1-based line of the last token.
    std::int64_t line() const { return m_line; }
    /// An upper bound on the numbers left in the text.
    std::int64_t remainingNumbers() const {
        return static_cast<std::int64_t>(m_text.size() - m_pos + 1) / kMinBytesPerNumber;
    }

private:
    static bool isSeparator(char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f' ||
               c == kComment;
    }
    std::string_view m_text;
    std::size_t m_pos = 0;
    std::int64_t m_line = 1;
};

/// True if `text` starts like a binary .meshb file: the int32 1 (the byte-order code).
bool looksLikeMeshb(std::string_view text) {
    return text.size() >= 4 && (text.substr(0, 4) == std::string_view("\1\0\0\0", 4) ||
                                text.substr(0, 4) == std::string_view("\0\0\0\1", 4));
}

class MeditReader {
public:
    MeditReader(const std::string& path, std::string_view text)
        : m_path(path), m_text(text), m_tokens(text) {}

    Status read(ImportedMesh& imported, MeshReadReport& report) {
        if (Status s = header(); !s)
            return s;
        std::string_view word;
        bool ended = false;
        while (!ended && m_tokens.next(word)) {
            if (equalsNoCase(word, "End")) {
                ended = true;
            } else if (equalsNoCase(word, "Vertices")) {
                if (Status s = vertices(imported); !s)
                    return s;
            } else if (equalsNoCase(word, "Tetrahedra")) {
                if (Status s = tetrahedra(imported, report); !s)
                    return s;
            } else if (Status s = skip(word, report); !s) {
                return s;
            }
        }
        if (!m_sawVertices)
            return Status::error(m_path + ": no Vertices section");
        if (!m_sawTets)
            return Status::error(m_path + ": no Tetrahedra section");
        const auto nv = static_cast<std::int64_t>(imported.points.size());
        for (std::size_t t = 0; t < m_vertexNumbers.size(); ++t)
            for (std::int64_t v : m_vertexNumbers[t])
                if (v < 1 || v > nv)
                    return Status::error(m_path + ": tetrahedron " + std::to_string(t + 1) +
                                         " refers to vertex " + std::to_string(v) + ", but there are " +
                                         std::to_string(nv) + " vertices (numbered from 1)");
        imported.tets.reserve(m_vertexNumbers.size());
        for (const auto& q : m_vertexNumbers)
            imported.tets.push_back(Tet{static_cast<int>(q[0] - 1), static_cast<int>(q[1] - 1),
                                        static_cast<int>(q[2] - 1), static_cast<int>(q[3] - 1)});
        imported.tetLabel = [](int t) { return "tetrahedron " + std::to_string(t + 1); };
        return Status::success();
    }

private:
    Status error(const std::string& what) const {
        return Status::error(m_path + ": line " + std::to_string(m_tokens.line()) + ": " + what);
    }

    Status expect(std::string_view& t, const std::string& what) {
        if (!m_tokens.next(t))
            return Status::error(m_path + ": unexpected end of file, expected " + what);
        return Status::success();
    }

    Status integer(std::int64_t& v, const std::string& what) {
        std::string_view t;
        if (Status s = expect(t, what); !s)
            return s;
        if (!parseInt64(t, v))
            return error("expected " + what + ", found '" + std::string(t.substr(0, 40)) + "'");
        return Status::success();
    }

    Status number(double& v, const std::string& what) {
        std::string_view t;
        if (Status s = expect(t, what); !s)
            return s;
        if (!parseDouble(t, v))
            return error("expected " + what + ", found '" + std::string(t.substr(0, 40)) + "'");
        return Status::success();
    }

    /// The record count after a keyword: not negative and not more than the rest of the
    /// file can hold at `numbers` numbers per record.
    Status recordCount(std::string_view keyword, int numbers, std::int64_t& n) {
        const std::string k(keyword);
        if (Status s = integer(n, "the number of " + k); !s)
            return s;
        const std::int64_t bound = m_tokens.remainingNumbers() / numbers;
        if (n < 0 || n > kMaxMeshItems || n > bound)
            return error(k + " declares " + std::to_string(n) +
                         " records, more than the rest of the file can hold");
        return Status::success();
    }

    Status header() {
        if (looksLikeMeshb(m_text))
            return Status::error(m_path + ": a binary Medit file (.meshb); only ASCII .mesh is "
                                          "read (convert it, e.g. with mmg or gmsh)");
        std::string_view t;
        if (!m_tokens.next(t))
            return Status::error(m_path + ": empty file");
        if (!equalsNoCase(t, "MeshVersionFormatted"))
            return error("expected MeshVersionFormatted, found '" + std::string(t.substr(0, 40)) +
                         "'");
        std::int64_t version = 0;
        if (Status s = integer(version, "the format version"); !s)
            return s;
        if (version != 1 && version != 2)
            return error("MeshVersionFormatted " + std::to_string(version) +
                         "; versions 1 and 2 are read");
        if (!m_tokens.next(t) || !equalsNoCase(t, "Dimension"))
            return error("expected Dimension after MeshVersionFormatted");
        std::int64_t dimension = 0;
        if (Status s = integer(dimension, "the dimension"); !s)
            return s;
        if (dimension != 3)
            return error("Dimension " + std::to_string(dimension) +
                         "; a tet mesh has Dimension 3");
        return Status::success();
    }

    Status vertices(ImportedMesh& imported) {
        if (m_sawVertices)
            return error("a second Vertices section");
        m_sawVertices = true;
        std::int64_t n = 0;
        if (Status s = recordCount("Vertices", 4, n); !s)
            return s;
        imported.points.reserve(static_cast<std::size_t>(n));
        for (std::int64_t i = 0; i < n; ++i) {
            Vec3 p;
            std::int64_t ref = 0;
            const std::string what = "vertex " + std::to_string(i + 1);
            if (Status s = number(p.x(), "the x of " + what); !s)
                return s;
            if (Status s = number(p.y(), "the y of " + what); !s)
                return s;
            if (Status s = number(p.z(), "the z of " + what); !s)
                return s;
            if (Status s = integer(ref, "the reference of " + what); !s)
                return s;
            if (!p.allFinite())
                return error(what + " has a non-finite coordinate");
            imported.points.push_back(p);
        }
        return Status::success();
    }

    Status tetrahedra(ImportedMesh& imported, MeshReadReport& report) {
        if (m_sawTets)
            return error("a second Tetrahedra section");
        m_sawTets = true;
        std::int64_t n = 0;
        if (Status s = recordCount("Tetrahedra", 5, n); !s)
            return s;
        m_vertexNumbers.reserve(static_cast<std::size_t>(n));
        imported.tetGroup.reserve(static_cast<std::size_t>(n));
        bool anyRef = false;
        for (std::int64_t i = 0; i < n; ++i) {
            std::array<std::int64_t, 4> q{};
            std::int64_t ref = 0;
            const std::string what = "tetrahedron " + std::to_string(i + 1);
            for (int k = 0; k < 4; ++k)
                if (Status s = integer(q[k], "vertex " + std::to_string(k + 1) + " of " + what); !s)
                    return s;
            if (Status s = integer(ref, "the reference of " + what); !s)
                return s;
            m_vertexNumbers.push_back(q);
            imported.tetGroup.push_back(ref);
            if (ref != 0) {
                anyRef = true;
                const auto same = [&](const MeshReadReport::Group& g) { return g.tag == ref; };
                if (std::find_if(report.groups.begin(), report.groups.end(), same) ==
                    report.groups.end())
                    report.groups.push_back({3, ref, "", 0});
            }
        }
        if (!anyRef)
            imported.tetGroup.clear();
        return Status::success();
    }

    Status skip(std::string_view word, MeshReadReport& report) {
        const auto it = std::find_if(kSkipped.begin(), kSkipped.end(), [&](const SkippedSection& s) {
            return equalsNoCase(word, s.keyword);
        });
        if (it == kSkipped.end()) {
            if (word.find('\0') != std::string_view::npos)
                return error("binary data in an ASCII .mesh file (a binary .meshb file? only "
                             "ASCII .mesh is read)");
            return error("unknown keyword '" + std::string(word.substr(0, 40)) + "'");
        }
        std::int64_t n = 0;
        if (Status s = recordCount(it->keyword, it->numbers, n); !s)
            return s;
        std::string_view t;
        for (std::int64_t i = 0; i < n * it->numbers; ++i) {
            if (Status s = expect(t, "the records of " + std::string(it->keyword)); !s)
                return s;
            double v = 0;
            if (!parseDouble(t, v))
                return error(std::string(it->keyword) + ": '" + std::string(t.substr(0, 40)) +
                             "' is not a number");
        }
        if (!it->element.empty() && n > 0)
            report.drop(std::string(it->element), n);
        return Status::success();
    }

    const std::string& m_path;
    std::string_view m_text;
    Tokens m_tokens;
    bool m_sawVertices = false, m_sawTets = false;
    std::vector<std::array<std::int64_t, 4>> m_vertexNumbers;
};

Status readImpl(const std::string& path, TetMesh& out, MeshReadReport* report) {
    if (lowerExtension(path) == ".meshb")
        return Status::error(path + ": binary Medit (.meshb) is not read; convert it to ASCII "
                                    ".mesh (e.g. with mmg or gmsh)");
    std::string text;
    if (Status s = readWholeFile(path, text); !s)
        return s;
    MeshReadReport local;
    local.format = "Medit";
    ImportedMesh imported;
    MeditReader reader(path, text);
    if (Status s = reader.read(imported, local); !s)
        return s;
    if (Status s = finishImportedMesh(path, std::move(imported), out, &local); !s)
        return s;
    if (report)
        *report = std::move(local);
    return Status::success();
}

std::string meditText(const TetMesh& mesh) {
    const TetAttributes attributes = tetAttributes(mesh);
    const std::vector<BoundaryFace> faces = boundaryFaces(mesh);
    std::string s = "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" +
                    std::to_string(mesh.nodeCount()) + "\n";
    for (const Vec3& p : mesh.positions())
        s += exactText(p.x()) + " " + exactText(p.y()) + " " + exactText(p.z()) + " 0\n";
    s += "\nTriangles\n" + std::to_string(faces.size()) + "\n";
    for (const BoundaryFace& f : faces)
        s += std::to_string(f.nodes[0] + 1) + " " + std::to_string(f.nodes[1] + 1) + " " +
             std::to_string(f.nodes[2] + 1) + " " +
             std::to_string(attributes.piece[static_cast<std::size_t>(f.tet)] + 1) + "\n";
    s += "\nTetrahedra\n" + std::to_string(mesh.tetCount()) + "\n";
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        s += std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " +
             std::to_string(q[2] + 1) + " " + std::to_string(q[3] + 1) + " " +
             std::to_string(attributes.piece[static_cast<std::size_t>(t)] + 1) + "\n";
    }
    s += "\nEnd\n";
    return s;
}

} // namespace

Status readMedit(const std::string& path, TetMesh& out, MeshReadReport* report) {
    return guarded(path, "reading", [&] { return readImpl(path, out, report); });
}

Status writeMedit(const std::string& path, const TetMesh& mesh) {
    return guarded(path, "writing", [&] {
        if (Status s = checkWritableMesh(path, mesh); !s)
            return s;
        return writeFileAtomically(path, meditText(mesh));
    });
}

} // namespace resect
