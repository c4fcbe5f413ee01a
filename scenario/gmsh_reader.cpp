// Gmsh .msh import, format 4.1 ASCII (https://gmsh.info/doc/texinfo/gmsh.html, section
// "MSH file format"). Only 4-node tetrahedra (element type 4) are read; every other
// element type (points, lines, triangles, higher-order elements, ...) is skipped.
//
// Layout read here (one record per line, as Gmsh writes it):
//   $MeshFormat / "4.1 0 8" / $EndMeshFormat
//   $Nodes / numEntityBlocks numNodes minNodeTag maxNodeTag
//     per block: entityDim entityTag parametric numNodesInBlock,
//                numNodesInBlock lines with a node tag, then as many lines "x y z [u v w]"
//   $EndNodes
//   $Elements / numEntityBlocks numElements minElementTag maxElementTag
//     per block: entityDim entityTag elementType numElementsInBlock,
//                numElementsInBlock lines "elementTag nodeTag..."
//   $EndElements
// Other sections ($PhysicalNames, $Entities, ...) are skipped. Node tags may be any
// positive integers (not necessarily contiguous); they are mapped to indices.

#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

#include <algorithm>
#include <exception>
#include <string>
#include <unordered_map>
#include <vector>

namespace resect {
namespace {

using namespace detail;

constexpr int kGmshTetType = 4;

class GmshParser {
public:
    GmshParser(const std::string& path, std::string_view text) : m_path(path), m_lines(text) {}

    Status parse(ImportedMesh& mesh);

private:
    Status error(const std::string& what) const {
        return Status::error(m_path + ": line " + std::to_string(m_lines.lineNumber()) + ": " +
                             what);
    }
    /// Next line split into tokens; error if the file ends.
    Status nextTokens(const char* context);
    /// Parses the current tokens as exactly `count` integers (or at least, if !exact).
    bool integers(std::size_t count, std::int64_t* values, bool exact = true) const;

    Status parseFormat();
    Status parseNodes();
    Status parseElements();
    Status skipSection(std::string_view name);

    std::string m_path;
    LineReader m_lines;
    std::string_view m_line;
    std::vector<std::string_view> m_tokens;

    bool m_haveNodes = false;
    std::vector<Vec3> m_points;
    std::unordered_map<std::int64_t, int> m_nodeIndex; // node tag -> index into m_points
    std::vector<Tet> m_tets;
    std::vector<std::int64_t> m_tetTags;
    std::vector<std::int64_t> m_skippedTypes;
};

Status GmshParser::nextTokens(const char* context) {
    if (!m_lines.next(m_line))
        return Status::error(m_path + ": unexpected end of file in " + context);
    splitTokens(m_line, m_tokens);
    return Status::success();
}

bool GmshParser::integers(std::size_t count, std::int64_t* values, bool exact) const {
    if (exact ? m_tokens.size() != count : m_tokens.size() < count)
        return false;
    for (std::size_t i = 0; i < count; ++i)
        if (!parseInt64(m_tokens[i], values[i]))
            return false;
    return true;
}

Status GmshParser::parseFormat() {
    if (!m_lines.nextContent(m_line))
        return Status::error(m_path + ": empty file");
    splitTokens(m_line, m_tokens);
    if (m_tokens.size() != 1 || m_tokens[0] != "$MeshFormat")
        return Status::error(m_path +
                             ": not a Gmsh mesh file (it does not start with $MeshFormat)");
    if (Status s = nextTokens("$MeshFormat"); !s)
        return s;
    std::int64_t fileType = -1;
    if (m_tokens.size() < 2 || !parseInt64(m_tokens[1], fileType))
        return error("expected \"version file-type data-size\" after $MeshFormat");
    const std::string version(m_tokens[0]);
    if (version.rfind("4.1", 0) != 0 || fileType != 0)
        return Status::error(m_path + ": Gmsh format " + version +
                             (fileType == 1   ? " binary"
                              : fileType == 0 ? " ASCII"
                                              : "") +
                             "; only Gmsh 4 ASCII is supported (format 4.1, file-type 0)");
    if (Status s = nextTokens("$MeshFormat"); !s)
        return s;
    if (m_tokens.size() != 1 || m_tokens[0] != "$EndMeshFormat")
        return error("expected $EndMeshFormat");
    return Status::success();
}

Status GmshParser::parseNodes() {
    if (m_haveNodes)
        return error("a second $Nodes section");
    m_haveNodes = true;
    if (Status s = nextTokens("$Nodes"); !s)
        return s;
    std::int64_t header[4];
    if (!integers(4, header))
        return error("expected \"numEntityBlocks numNodes minNodeTag maxNodeTag\"");
    const std::int64_t numBlocks = header[0], numNodes = header[1];
    // Every node takes two lines (its tag and its coordinates), every block one more: the
    // counts cannot exceed what the rest of the file holds.
    const std::int64_t remaining = m_lines.remainingLines();
    if (numBlocks < 0 || numNodes < 0 || numBlocks > remaining || numNodes > remaining / 2 ||
        numNodes > kMaxMeshItems)
        return error("$Nodes declares " + std::to_string(numBlocks) + " blocks and " +
                     std::to_string(numNodes) + " nodes, but only " + std::to_string(remaining) +
                     " lines follow");
    m_points.reserve(static_cast<std::size_t>(numNodes));
    m_nodeIndex.reserve(static_cast<std::size_t>(numNodes));

    std::vector<std::int64_t> tags;
    for (std::int64_t b = 0; b < numBlocks; ++b) {
        if (Status s = nextTokens("$Nodes"); !s)
            return s;
        std::int64_t block[4];
        if (!integers(4, block))
            return error("expected \"entityDim entityTag parametric numNodesInBlock\"");
        const std::int64_t inBlock = block[3];
        if (inBlock < 0 || inBlock > numNodes - static_cast<std::int64_t>(m_points.size()))
            return error("node block of " + std::to_string(inBlock) +
                         " nodes exceeds the declared total of " + std::to_string(numNodes));
        tags.clear();
        for (std::int64_t i = 0; i < inBlock; ++i) {
            if (Status s = nextTokens("$Nodes"); !s)
                return s;
            std::int64_t tag = 0;
            if (!integers(1, &tag) || tag <= 0)
                return error("expected a positive node tag");
            tags.push_back(tag);
        }
        for (std::int64_t i = 0; i < inBlock; ++i) {
            if (Status s = nextTokens("$Nodes"); !s)
                return s;
            Vec3 p;
            if (m_tokens.size() < 3 || !parseDouble(m_tokens[0], p.x()) ||
                !parseDouble(m_tokens[1], p.y()) || !parseDouble(m_tokens[2], p.z()))
                return error("expected node coordinates \"x y z\"");
            if (!p.allFinite())
                return error("node " + std::to_string(tags[i]) + " has a non-finite coordinate");
            const auto [it, inserted] =
                m_nodeIndex.try_emplace(tags[i], static_cast<int>(m_points.size()));
            if (!inserted)
                return error("node tag " + std::to_string(tags[i]) + " appears twice");
            m_points.push_back(p);
        }
    }
    if (static_cast<std::int64_t>(m_points.size()) != numNodes)
        return error("$Nodes declares " + std::to_string(numNodes) + " nodes but its blocks hold " +
                     std::to_string(m_points.size()));
    if (Status s = nextTokens("$Nodes"); !s)
        return s;
    if (m_tokens.size() != 1 || m_tokens[0] != "$EndNodes")
        return error("expected $EndNodes");
    return Status::success();
}

Status GmshParser::parseElements() {
    if (!m_haveNodes)
        return error("$Elements before $Nodes");
    if (Status s = nextTokens("$Elements"); !s)
        return s;
    std::int64_t header[4];
    if (!integers(4, header))
        return error("expected \"numEntityBlocks numElements minElementTag maxElementTag\"");
    const std::int64_t numBlocks = header[0], numElements = header[1];
    const std::int64_t remaining = m_lines.remainingLines();
    if (numBlocks < 0 || numElements < 0 || numBlocks > remaining || numElements > remaining ||
        numElements > kMaxMeshItems)
        return error("$Elements declares " + std::to_string(numBlocks) + " blocks and " +
                     std::to_string(numElements) + " elements, but only " +
                     std::to_string(remaining) + " lines follow");

    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < numBlocks; ++b) {
        if (Status s = nextTokens("$Elements"); !s)
            return s;
        std::int64_t block[4];
        if (!integers(4, block))
            return error("expected \"entityDim entityTag elementType numElementsInBlock\"");
        const std::int64_t type = block[2], inBlock = block[3];
        if (inBlock < 0 || inBlock > numElements - seen)
            return error("element block of " + std::to_string(inBlock) +
                         " elements exceeds the declared total of " + std::to_string(numElements));
        seen += inBlock;
        if (type == kGmshTetType)
            m_tets.reserve(m_tets.size() + static_cast<std::size_t>(inBlock));
        else if (std::find(m_skippedTypes.begin(), m_skippedTypes.end(), type) ==
                 m_skippedTypes.end())
            m_skippedTypes.push_back(type);
        for (std::int64_t i = 0; i < inBlock; ++i) {
            if (Status s = nextTokens("$Elements"); !s)
                return s;
            if (type != kGmshTetType)
                continue;
            std::int64_t v[5];
            if (!integers(5, v))
                return error("expected \"elementTag node node node node\" for a tetrahedron");
            Tet t;
            for (int k = 0; k < 4; ++k) {
                const auto it = m_nodeIndex.find(v[k + 1]);
                if (it == m_nodeIndex.end())
                    return error("element " + std::to_string(v[0]) + " refers to node " +
                                 std::to_string(v[k + 1]) + ", which is not in $Nodes");
                t[k] = it->second;
            }
            m_tets.push_back(t);
            m_tetTags.push_back(v[0]);
        }
    }
    if (Status s = nextTokens("$Elements"); !s)
        return s;
    if (m_tokens.size() != 1 || m_tokens[0] != "$EndElements")
        return error("expected $EndElements");
    return Status::success();
}

Status GmshParser::skipSection(std::string_view name) {
    const std::string end = "$End" + std::string(name.substr(1));
    while (m_lines.next(m_line)) {
        splitTokens(m_line, m_tokens);
        if (m_tokens.size() == 1 && m_tokens[0] == end)
            return Status::success();
    }
    return Status::error(m_path + ": section " + std::string(name) + " has no " + end);
}

Status GmshParser::parse(ImportedMesh& mesh) {
    if (Status s = parseFormat(); !s)
        return s;
    bool haveElements = false;
    while (m_lines.nextContent(m_line)) {
        splitTokens(m_line, m_tokens);
        if (m_tokens.size() != 1 || m_tokens[0].empty() || m_tokens[0].front() != '$')
            return error("expected a section such as $Nodes or $Elements");
        const std::string_view name = m_tokens[0];
        Status s;
        if (name == "$Nodes") {
            s = parseNodes();
        } else if (name == "$Elements") {
            if (haveElements)
                return error("a second $Elements section");
            haveElements = true;
            s = parseElements();
        } else {
            s = skipSection(name);
        }
        if (!s)
            return s;
    }
    if (!m_haveNodes)
        return Status::error(m_path + ": no $Nodes section");
    if (!haveElements)
        return Status::error(m_path + ": no $Elements section");
    if (m_tets.empty()) {
        std::string types;
        for (std::int64_t t : m_skippedTypes)
            types += (types.empty() ? "" : ", ") + std::to_string(t);
        return Status::error(m_path + ": no 4-node tetrahedra (Gmsh element type 4)" +
                             (types.empty() ? std::string() : "; element types found: " + types));
    }
    mesh.points = std::move(m_points);
    mesh.tets = std::move(m_tets);
    mesh.tetLabel = [tags = std::move(m_tetTags)](int t) {
        return "element " + std::to_string(tags[static_cast<std::size_t>(t)]);
    };
    return Status::success();
}

} // namespace

Status readGmsh(const std::string& path, TetMesh& out) {
    try {
        std::string text;
        if (Status s = readWholeFile(path, text); !s)
            return s;
        ImportedMesh imported;
        GmshParser parser(path, text);
        if (Status s = parser.parse(imported); !s)
            return s;
        return finishImportedMesh(path, std::move(imported), out);
    } catch (const std::bad_alloc&) {
        return Status::error(path + ": out of memory while reading");
    } catch (const std::exception& e) {
        return Status::error(path + ": " + e.what());
    }
}

} // namespace resect
