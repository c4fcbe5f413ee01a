// Gmsh .msh import: formats 2.2 and 4.1, ASCII and binary (https://gmsh.info/doc/texinfo/
// gmsh.html, section "MSH file format"; 2.2 in the "Legacy formats" appendix). The
// $MeshFormat line decides the variant (2, 2.0 and 2.1 share 2.2's layout); 4.0 and 1.x
// are refused by name.
//
// Layouts read here (sizes in binary files: int 4 bytes, size_t and double 8 bytes, little
// endian; "ASCII" headers stay text in binary files):
//   $MeshFormat  "version file-type data-size" [binary: int 1 for the endianness]
//   $PhysicalNames (ASCII in both)  count, then "dim tag \"name\"" per group
//   2.2 $Nodes     count (ASCII), then per node: tag(int) x y z
//   2.2 $Elements  count (ASCII), then ASCII: "tag type numTags tag... node..." per line;
//                  binary: blocks of header (type, count, numTags) + elements
//                  (tag, tags..., nodes...), all int. The first tag is the physical group.
//   4.1 $Entities  numPoints numCurves numSurfaces numVolumes (size_t), then per entity:
//                  tag(int), a point X Y Z or a box of 6 doubles, numPhysicalTags(size_t)
//                  physicalTag(int)..., and for curves, surfaces and volumes
//                  numBounding(size_t) boundingTag(int)...
//   4.1 $Nodes     numBlocks numNodes minTag maxTag (size_t); per block entityDim
//                  entityTag parametric (int) numNodesInBlock (size_t), the block's tags
//                  (size_t), then its coordinates x y z [u v w as parametric and dim ask]
//   4.1 $Elements  numBlocks numElements minTag maxTag (size_t); per block entityDim
//                  entityTag elementType (int) numElementsInBlock (size_t), then per
//                  element tag node... (size_t). An element's groups are its entity's
//                  physical tags.
//   $NodeData      string tags (the first is the view's name), real tags, integer tags
//                  (time step, components, count, ...), all ASCII; then per node
//                  nodeTag(int) value(double)... Views reference_position (3), mass (1) and
//                  velocity (3), as gmsh_writer.cpp writes them, are read; others ignored.
// Other sections ($ElementData, $Comments, $Periodic, ...) are skipped. 4-node tets (type
// 4) are kept, 10-node tets (type 11) are read as their corners, every other element is
// dropped and counted in the report. Node tags may be any positive integers.
//
// Hostile input: every count is checked against the bytes left in the file before anything
// is allocated (a record needs at least 2 bytes per ASCII number, its exact size in binary),
// every binary read is bounds-checked, and every error names the file and the line (ASCII)
// or byte offset (binary).

#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <exception>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace resect {
namespace {

using namespace detail;

static_assert(std::endian::native == std::endian::little,
              "the binary Gmsh reader assumes a little-endian host");

constexpr int kGmshTet4 = 4;
constexpr int kGmshTet10 = 11;

/// Gmsh element types (the manual's list): node count, dimension and a name for reports.
struct ElementKind {
    int type;
    int nodes;
    int dimension;
    const char* name;
};
constexpr ElementKind kElementKinds[] = {
    {1, 2, 1, "2-node line"},
    {2, 3, 2, "3-node triangle"},
    {3, 4, 2, "4-node quadrangle"},
    {4, 4, 3, "4-node tetrahedron"},
    {5, 8, 3, "8-node hexahedron"},
    {6, 6, 3, "6-node prism"},
    {7, 5, 3, "5-node pyramid"},
    {8, 3, 1, "3-node line"},
    {9, 6, 2, "6-node triangle"},
    {10, 9, 2, "9-node quadrangle"},
    {11, 10, 3, "10-node tetrahedron"},
    {12, 27, 3, "27-node hexahedron"},
    {13, 18, 3, "18-node prism"},
    {14, 14, 3, "14-node pyramid"},
    {15, 1, 0, "1-node point"},
    {16, 8, 2, "8-node quadrangle"},
    {17, 20, 3, "20-node hexahedron"},
    {18, 15, 3, "15-node prism"},
    {19, 13, 3, "13-node pyramid"},
    {20, 9, 2, "9-node triangle"},
    {21, 10, 2, "10-node triangle"},
    {22, 12, 2, "12-node triangle"},
    {23, 15, 2, "15-node triangle"},
    {24, 15, 2, "15-node incomplete triangle"},
    {25, 21, 2, "21-node triangle"},
    {26, 4, 1, "4-node line"},
    {27, 5, 1, "5-node line"},
    {28, 6, 1, "6-node line"},
    {29, 20, 3, "20-node tetrahedron"},
    {30, 35, 3, "35-node tetrahedron"},
    {31, 56, 3, "56-node tetrahedron"},
    {92, 64, 3, "64-node hexahedron"},
    {93, 125, 3, "125-node hexahedron"},
};

const ElementKind* findKind(std::int64_t type) {
    for (const ElementKind& k : kElementKinds)
        if (k.type == type)
            return &k;
    return nullptr;
}

std::string kindName(std::int64_t type) {
    const ElementKind* k = findKind(type);
    return k ? std::string(k->name) : "element type " + std::to_string(type);
}

/// The node data views the project's writer adds, with their component counts.
struct KnownView {
    const char* name;
    int components;
};
constexpr KnownView kKnownViews[] = {{"reference_position", 3}, {"mass", 1}, {"velocity", 3}};

/// A node data view as read: per value, the node tag and `components` doubles.
struct NodeView {
    int components = 0;
    std::vector<std::int64_t> tags;
    std::vector<double> values;
};

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/// A cursor over the whole file: ASCII tokens (line aware) and little-endian binary fields.
/// Errors are located at the mark: the start of the last token or binary field read.
class Cursor {
public:
    Cursor(const std::string& path, std::string_view text) : m_path(path), m_text(text) {}

    bool binaryFile = false; ///< set by $MeshFormat: locations become byte offsets

    Status error(const std::string& what) const {
        const std::string where = binaryFile ? "byte offset " + std::to_string(m_mark)
                                             : "line " + std::to_string(m_markLine);
        return Status::error(m_path + ": " + where + ": " + what);
    }
    std::int64_t remaining() const { return static_cast<std::int64_t>(m_text.size() - m_pos); }
    std::size_t offset() const { return m_pos; }

    /// Next whitespace-separated token; with `sameLine`, only if it is on the current line.
    bool token(std::string_view& out, bool sameLine = false) {
        while (m_pos < m_text.size() && isSpace(m_text[m_pos])) {
            if (m_text[m_pos] == '\n') {
                if (sameLine)
                    return false;
                ++m_line;
            }
            ++m_pos;
        }
        m_mark = m_pos;
        m_markLine = m_line;
        if (m_pos >= m_text.size())
            return false;
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !isSpace(m_text[m_pos]))
            ++m_pos;
        out = m_text.substr(start, m_pos - start);
        return true;
    }
    /// True if only blanks remain on the current line.
    bool lineRestBlank() const {
        for (std::size_t p = m_pos; p < m_text.size() && m_text[p] != '\n'; ++p)
            if (!isSpace(m_text[p]))
                return false;
        return true;
    }
    /// Skips the rest of the current line.
    void skipLineRest() {
        while (m_pos < m_text.size() && m_text[m_pos] != '\n')
            ++m_pos;
    }
    /// Skips the next non-blank line (an ASCII record of unknown length).
    bool skipRecord() {
        std::string_view first;
        if (!token(first))
            return false;
        skipLineRest();
        return true;
    }
    /// A double-quoted string on the current line ("name"; no quotes inside).
    bool quoted(std::string& out, bool sameLine = true) {
        std::string_view t;
        if (!token(t, sameLine) || t.front() != '"')
            return false;
        const std::size_t open = m_mark;
        const std::size_t close = m_text.find('"', open + 1);
        const std::size_t eol = m_text.find('\n', open);
        if (close == std::string_view::npos || (eol != std::string_view::npos && close > eol))
            return false;
        out.assign(m_text.substr(open + 1, close - open - 1));
        m_pos = close + 1;
        return true;
    }
    /// Ends the ASCII line before binary data: blanks, then one line feed.
    bool startBinary() {
        while (m_pos < m_text.size() && m_text[m_pos] != '\n' && isSpace(m_text[m_pos]))
            ++m_pos;
        if (m_pos >= m_text.size() || m_text[m_pos] != '\n')
            return false;
        ++m_pos;
        ++m_line;
        return true;
    }
    bool raw(void* out, std::size_t bytes) {
        m_mark = m_pos;
        if (bytes > m_text.size() - m_pos)
            return false;
        std::memcpy(out, m_text.data() + m_pos, bytes);
        m_pos += bytes;
        return true;
    }
    /// Moves past the line "end" that starts a line at or after the cursor.
    bool skipTo(std::string_view end) {
        std::size_t p = m_pos;
        while ((p = m_text.find(end, p)) != std::string_view::npos) {
            const std::size_t after = p + end.size();
            if ((p == 0 || m_text[p - 1] == '\n') &&
                (after == m_text.size() || isSpace(m_text[after]))) {
                m_line += std::count(m_text.begin() + static_cast<std::ptrdiff_t>(m_pos),
                                     m_text.begin() + static_cast<std::ptrdiff_t>(after), '\n');
                m_pos = after;
                return true;
            }
            p = after;
        }
        return false;
    }

private:
    std::string m_path;
    std::string_view m_text;
    std::size_t m_pos = 0;
    std::int64_t m_line = 1;
    std::size_t m_mark = 0;
    std::int64_t m_markLine = 1;
};

/// Parses a whole .msh file into nodes, tets, groups and views; see the file comment.
class GmshParser {
public:
    GmshParser(const std::string& path, std::string_view text) : m_path(path), m_in(path, text) {}

    Status parse();
    /// Moves the result into `mesh` and `report` (after a successful parse()).
    Status result(ImportedMesh& mesh, MeshReadReport& report);

private:
    // --- fields: `sameLine` asks ASCII fields to continue the current record's line
    Status unexpectedEnd() const { return m_in.error("unexpected end of file in " + m_section); }
    Status expected(const std::string& what, bool sameLine) {
        if (sameLine && m_in.lineRestBlank())
            return m_in.error("expected " + what + ", but the line ends");
        if (m_in.remaining() == 0)
            return unexpectedEnd();
        return m_in.error("expected " + what);
    }
    Status textInt(std::int64_t& v, const std::string& what, bool sameLine) {
        std::string_view t;
        if (!m_in.token(t, sameLine) || !parseInt64(t, v))
            return expected(what, sameLine);
        return Status::success();
    }
    Status textDouble(double& v, const std::string& what, bool sameLine) {
        std::string_view t;
        if (!m_in.token(t, sameLine) || !parseDouble(t, v))
            return expected(what, sameLine);
        return Status::success();
    }
    /// An int field (4 bytes in binary).
    Status dataInt(std::int64_t& v, const std::string& what, bool sameLine) {
        if (!m_binary)
            return textInt(v, what, sameLine);
        std::int32_t x = 0;
        if (!m_in.raw(&x, sizeof x))
            return unexpectedEnd();
        v = x;
        return Status::success();
    }
    /// A size_t field (8 bytes in binary).
    Status dataSize(std::int64_t& v, const std::string& what, bool sameLine) {
        if (!m_binary)
            return textInt(v, what, sameLine);
        std::uint64_t x = 0;
        if (!m_in.raw(&x, sizeof x))
            return unexpectedEnd();
        if (x > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            return m_in.error(what + " " + std::to_string(x) + " is too large");
        v = static_cast<std::int64_t>(x);
        return Status::success();
    }
    Status dataDouble(double& v, const std::string& what, bool sameLine) {
        if (!m_binary)
            return textDouble(v, what, sameLine);
        if (!m_in.raw(&v, sizeof v))
            return unexpectedEnd();
        return Status::success();
    }
    /// The binary data of a section starts after its ASCII header line.
    Status startBinary() {
        if (m_binary && !m_in.startBinary())
            return m_in.error("expected a line feed before the binary data of " + m_section);
        return Status::success();
    }
    /// Ok if `count` records of at least `bytesEach` bytes fit in the rest of the file.
    Status fits(std::int64_t count, std::int64_t bytesEach, const std::string& what) const {
        if (count < 0 || count > m_in.remaining() / bytesEach)
            return m_in.error(what + ", but only " + std::to_string(m_in.remaining()) +
                              " bytes follow");
        return Status::success();
    }
    /// Bytes a record of `fields` numbers needs at least: exact in binary, "1 " in ASCII.
    std::int64_t minBytes(std::int64_t binaryBytes, std::int64_t asciiFields) const {
        return m_binary ? binaryBytes : 2 * asciiFields;
    }
    Status expectEnd();

    // --- sections
    Status parseFormat();
    Status parsePhysicalNames();
    Status parseEntities();
    Status parseNodes22();
    Status parseNodes41();
    Status parseNodeBlock41(std::int64_t total);
    Status parseElements22();
    Status parseElementBlock22(std::int64_t total, std::int64_t& seen);
    Status parseElements41();
    Status parseElementBlock41(std::int64_t total, std::int64_t& seen);
    struct ViewHeader {
        std::string name;
        std::int64_t components = 0;
        std::int64_t values = 0;
    };
    Status parseViewHeader(ViewHeader& header);
    Status parseNodeData();
    Status parseSection(std::string_view name);

    // --- records
    Status addNode(std::int64_t tag, const Vec3& p);
    /// Reads the node tags of one element of `kind` (size_t tags in 4.1, int in 2.2).
    Status readElementNodes(std::int64_t tag, const ElementKind& kind, bool sizeTags,
                            std::vector<std::int64_t>& nodes);
    Status addElement(std::int64_t tag, const ElementKind& kind,
                      const std::vector<std::int64_t>& nodes, std::int64_t group);
    void noteGroup(int dimension, std::int64_t tag);
    void noteType(std::int64_t type) {
        if (m_elementTypeSet.insert(type).second)
            m_elementTypes.push_back(type);
    }
    Status resolveView(const char* name, int components, std::vector<double>& out) const;
    void removeDuplicateTets();

    std::string m_path;
    Cursor m_in;
    std::string m_section = "$MeshFormat";
    bool m_v41 = false;
    bool m_binary = false;
    std::string m_formatName;

    bool m_haveNodes = false;
    bool m_haveElements = false;
    std::vector<Vec3> m_points;
    std::unordered_map<std::int64_t, int> m_nodeIndex; // node tag -> index into m_points
    std::vector<Tet> m_tets;
    std::vector<std::int64_t> m_tetTags;
    std::vector<std::int64_t> m_tetGroups;
    std::int64_t m_tet10 = 0;
    std::vector<std::int64_t> m_elementTypes; // every type met, once, in order met
    std::set<std::int64_t> m_elementTypeSet;
    std::map<std::int64_t, std::int64_t> m_dropped; // element type -> elements left out
    MeshReadReport m_report;

    std::vector<std::pair<int, std::int64_t>> m_groupOrder; // (dim, tag), first met
    std::set<std::pair<int, std::int64_t>> m_groupSet;
    std::map<std::pair<int, std::int64_t>, std::string> m_names;
    std::map<std::pair<int, std::int64_t>, std::int64_t> m_entityGroup; // first physical tag
    std::map<std::string, NodeView> m_views;
};

Status GmshParser::expectEnd() {
    const std::string end = "$End" + m_section.substr(1);
    std::string_view t;
    if (!m_in.token(t))
        return unexpectedEnd();
    if (t != end)
        return m_in.error("expected " + end);
    return Status::success();
}

Status GmshParser::parseFormat() {
    std::string_view t;
    if (!m_in.token(t))
        return Status::error(m_path + ": empty file");
    if (t == "$NOD" || t == "$NOE")
        return Status::error(m_path + ": Gmsh format 1.0 is not supported; save the mesh from "
                                      "Gmsh as format 4.1 or 2.2");
    if (t != "$MeshFormat")
        return Status::error(m_path +
                             ": not a Gmsh mesh file (it does not start with $MeshFormat)");
    std::string_view version;
    std::int64_t fileType = -1, dataSize = 0;
    if (!m_in.token(version))
        return unexpectedEnd();
    if (version == "2.2" || version == "2" || version == "2.0" || version == "2.1") {
        m_v41 = false;
    } else if (version == "4.1") {
        m_v41 = true;
    } else {
        double v = 0;
        if (!parseDouble(version, v))
            return m_in.error("expected \"version file-type data-size\" after $MeshFormat");
        return Status::error(m_path + ": Gmsh format " + std::string(version) +
                             " is not supported; save the mesh from Gmsh as format 4.1 or 2.2 "
                             "(gmsh -save -format msh41)");
    }
    if (Status s = textInt(fileType, "the file-type (0 ASCII, 1 binary)", true); !s)
        return s;
    if (fileType != 0 && fileType != 1)
        return m_in.error("file-type " + std::to_string(fileType) +
                          " is neither 0 (ASCII) nor 1 (binary)");
    if (Status s = textInt(dataSize, "the data-size", true); !s)
        return s;
    m_binary = fileType == 1;
    m_formatName = "Gmsh " + std::string(version) + (m_binary ? " binary" : " ASCII");
    if (m_binary) {
        m_in.binaryFile = true;
        if (dataSize != 8)
            return m_in.error("data-size " + std::to_string(dataSize) +
                              " is not supported; only 8 (8-byte doubles and sizes)");
        if (Status s = startBinary(); !s)
            return s;
        std::int32_t one = 0;
        if (!m_in.raw(&one, sizeof one))
            return unexpectedEnd();
        if (one == 0x01000000)
            return m_in.error("the file is big-endian (its endianness check reads 16777216); "
                              "only little-endian binary files are supported");
        if (one != 1)
            return m_in.error("expected the endianness check integer 1 after the header, found " +
                              std::to_string(one));
    }
    return expectEnd();
}

Status GmshParser::parsePhysicalNames() {
    std::int64_t count = 0;
    if (Status s = textInt(count, "the number of physical names", false); !s)
        return s;
    if (Status s = fits(count, 7, "$PhysicalNames declares " + std::to_string(count) + " names");
        !s)
        return s;
    for (std::int64_t i = 0; i < count; ++i) {
        std::int64_t dim = 0, tag = 0;
        std::string name;
        if (Status s = textInt(dim, "a physical group's dimension", false); !s)
            return s;
        if (dim < 0 || dim > 3)
            return m_in.error("physical group dimension " + std::to_string(dim) +
                              " is not 0, 1, 2 or 3");
        if (Status s = textInt(tag, "a physical group's tag", true); !s)
            return s;
        if (!m_in.quoted(name))
            return expected("a quoted physical group name", true);
        m_names[{static_cast<int>(dim), tag}] = name;
        noteGroup(static_cast<int>(dim), tag);
    }
    return expectEnd();
}

void GmshParser::noteGroup(int dimension, std::int64_t tag) {
    const std::pair<int, std::int64_t> key{dimension, tag};
    if (m_groupSet.insert(key).second)
        m_groupOrder.push_back(key);
}

Status GmshParser::parseEntities() {
    if (Status s = startBinary(); !s)
        return s;
    std::int64_t counts[4];
    for (int d = 0; d < 4; ++d)
        if (Status s = dataSize(counts[d], "an entity count", d > 0); !s)
            return s;
    for (int d = 0; d < 4; ++d)
        if (Status s = fits(counts[d], minBytes(36, 5),
                            "$Entities declares " + std::to_string(counts[d]) +
                                " entities of dimension " + std::to_string(d));
            !s)
            return s;
    for (int dim = 0; dim < 4; ++dim)
        for (std::int64_t e = 0; e < counts[dim]; ++e) {
            std::int64_t tag = 0, numTags = 0, value = 0;
            double box = 0;
            if (Status s = dataInt(tag, "an entity tag", false); !s)
                return s;
            for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
                if (Status s = dataDouble(box, "an entity coordinate", true); !s)
                    return s;
            for (int list = 0; list < (dim == 0 ? 1 : 2); ++list) {
                // First the physical tags, then (not for points) the bounding entities.
                if (Status s = dataSize(numTags, "a tag count", true); !s)
                    return s;
                if (Status s = fits(numTags, minBytes(4, 1),
                                    "entity " + std::to_string(tag) + " declares " +
                                        std::to_string(numTags) + " tags");
                    !s)
                    return s;
                for (std::int64_t k = 0; k < numTags; ++k) {
                    if (Status s = dataInt(value, "a tag", true); !s)
                        return s;
                    if (list == 0) {
                        m_entityGroup.try_emplace({dim, tag}, value);
                        noteGroup(dim, value);
                    }
                }
            }
        }
    return expectEnd();
}

Status GmshParser::addNode(std::int64_t tag, const Vec3& p) {
    if (tag <= 0)
        return m_in.error("node tag " + std::to_string(tag) + " is not positive");
    if (!p.allFinite())
        return m_in.error("node " + std::to_string(tag) + " has a non-finite coordinate");
    if (m_points.size() >= static_cast<std::size_t>(kMaxMeshItems))
        return m_in.error("more nodes than a mesh can index");
    const auto [it, inserted] = m_nodeIndex.try_emplace(tag, static_cast<int>(m_points.size()));
    if (!inserted)
        return m_in.error("node tag " + std::to_string(tag) + " appears twice");
    m_points.push_back(p);
    return Status::success();
}

Status GmshParser::parseNodes22() {
    std::int64_t count = 0;
    if (Status s = textInt(count, "the number of nodes", false); !s)
        return s;
    if (Status s =
            fits(count, minBytes(28, 4), "$Nodes declares " + std::to_string(count) + " nodes");
        !s)
        return s;
    if (Status s = startBinary(); !s)
        return s;
    m_points.reserve(static_cast<std::size_t>(count));
    m_nodeIndex.reserve(static_cast<std::size_t>(count));
    for (std::int64_t i = 0; i < count; ++i) {
        std::int64_t tag = 0;
        Vec3 p;
        if (Status s = dataInt(tag, "a node tag", false); !s)
            return s;
        for (int k = 0; k < 3; ++k)
            if (Status s = dataDouble(p[k], "node coordinates \"x y z\"", true); !s)
                return s;
        if (Status s = addNode(tag, p); !s)
            return s;
    }
    return expectEnd();
}

Status GmshParser::parseNodes41() {
    if (Status s = startBinary(); !s)
        return s;
    std::int64_t header[4];
    for (int k = 0; k < 4; ++k)
        if (Status s =
                dataSize(header[k], "\"numEntityBlocks numNodes minNodeTag maxNodeTag\"", k > 0);
            !s)
            return s;
    const std::int64_t numBlocks = header[0], numNodes = header[1];
    const std::string declared = "$Nodes declares " + std::to_string(numBlocks) + " blocks and " +
                                 std::to_string(numNodes) + " nodes";
    if (Status s = fits(numBlocks, minBytes(20, 4), declared); !s)
        return s;
    if (Status s = fits(numNodes, minBytes(32, 4), declared); !s)
        return s;
    m_points.reserve(static_cast<std::size_t>(numNodes));
    m_nodeIndex.reserve(static_cast<std::size_t>(numNodes));
    for (std::int64_t b = 0; b < numBlocks; ++b)
        if (Status s = parseNodeBlock41(numNodes); !s)
            return s;
    if (static_cast<std::int64_t>(m_points.size()) != numNodes)
        return m_in.error(declared + " but its blocks hold " + std::to_string(m_points.size()));
    return expectEnd();
}

Status GmshParser::parseNodeBlock41(std::int64_t total) {
    std::int64_t dim = 0, entity = 0, parametric = 0, inBlock = 0;
    if (Status s = dataInt(dim, "\"entityDim entityTag parametric numNodesInBlock\"", false); !s)
        return s;
    if (Status s = dataInt(entity, "an entity tag", true); !s)
        return s;
    if (Status s = dataInt(parametric, "the parametric flag", true); !s)
        return s;
    if (Status s = dataSize(inBlock, "the number of nodes in the block", true); !s)
        return s;
    if (dim < 0 || dim > 3 || (parametric != 0 && parametric != 1))
        return m_in.error("node block with entity dimension " + std::to_string(dim) +
                          " and parametric flag " + std::to_string(parametric));
    const std::int64_t have = static_cast<std::int64_t>(m_points.size());
    if (inBlock < 0 || inBlock > total - have)
        return m_in.error("node block of " + std::to_string(inBlock) +
                          " nodes exceeds the declared total of " + std::to_string(total));
    const int extra = parametric ? static_cast<int>(dim) : 0; // u, v, w
    std::vector<std::int64_t> tags(static_cast<std::size_t>(inBlock));
    for (std::int64_t& tag : tags)
        if (Status s = dataSize(tag, "a node tag", false); !s)
            return s;
    for (std::int64_t i = 0; i < inBlock; ++i) {
        Vec3 p;
        double uvw = 0;
        for (int k = 0; k < 3; ++k)
            if (Status s = dataDouble(p[k], "node coordinates \"x y z\"", k > 0); !s)
                return s;
        for (int k = 0; k < extra; ++k)
            if (Status s = dataDouble(uvw, "parametric coordinates", true); !s)
                return s;
        if (Status s = addNode(tags[static_cast<std::size_t>(i)], p); !s)
            return s;
    }
    return Status::success();
}

Status GmshParser::readElementNodes(std::int64_t tag, const ElementKind& kind, bool sizeTags,
                                    std::vector<std::int64_t>& nodes) {
    nodes.resize(static_cast<std::size_t>(kind.nodes));
    const std::string what = "the " + std::to_string(kind.nodes) + " node tags of element " +
                             std::to_string(tag) + " (a " + kind.name + ")";
    for (std::int64_t& n : nodes)
        if (Status s = sizeTags ? dataSize(n, what, true) : dataInt(n, what, true); !s)
            return s;
    if (!m_binary && !m_in.lineRestBlank())
        return m_in.error("element " + std::to_string(tag) + " has more than the " +
                          std::to_string(kind.nodes) + " node tags of a " + kind.name);
    return Status::success();
}

Status GmshParser::addElement(std::int64_t tag, const ElementKind& kind,
                              const std::vector<std::int64_t>& nodes, std::int64_t group) {
    if (group != 0)
        noteGroup(kind.dimension, group);
    if (kind.type != kGmshTet4 && kind.type != kGmshTet10) {
        ++m_dropped[kind.type];
        return Status::success();
    }
    if (m_tets.size() >= static_cast<std::size_t>(kMaxMeshItems))
        return m_in.error("more tetrahedra than a mesh can index");
    Tet t;
    for (int k = 0; k < 4; ++k) { // a 10-node tet's corners are its first 4 nodes
        const auto it = m_nodeIndex.find(nodes[static_cast<std::size_t>(k)]);
        if (it == m_nodeIndex.end())
            return m_in.error("element " + std::to_string(tag) + " refers to node " +
                              std::to_string(nodes[static_cast<std::size_t>(k)]) +
                              ", which is not in $Nodes");
        t[k] = it->second;
    }
    if (kind.type == kGmshTet10)
        ++m_tet10;
    m_tets.push_back(t);
    m_tetTags.push_back(tag);
    m_tetGroups.push_back(group);
    return Status::success();
}

Status GmshParser::parseElements22() {
    std::int64_t count = 0;
    if (Status s = textInt(count, "the number of elements", false); !s)
        return s;
    if (Status s = fits(count, minBytes(8, 4),
                        "$Elements declares " + std::to_string(count) + " elements");
        !s)
        return s;
    if (Status s = startBinary(); !s)
        return s;
    std::int64_t seen = 0;
    while (seen < count)
        if (Status s = parseElementBlock22(count, seen); !s)
            return s;
    return expectEnd();
}

/// 2.2: in binary one block (header type, count, numTags, then its elements); in ASCII one
/// element line "tag type numTags tag... node...".
Status GmshParser::parseElementBlock22(std::int64_t total, std::int64_t& seen) {
    std::int64_t type = 0, inBlock = 1, numTags = 0, tag = 0;
    if (m_binary) {
        if (Status s = dataInt(type, "an element block header", false); !s)
            return s;
        if (Status s = dataInt(inBlock, "an element block header", false); !s)
            return s;
        if (Status s = dataInt(numTags, "an element block header", false); !s)
            return s;
        if (inBlock < 1 || inBlock > total - seen)
            return m_in.error("element block of " + std::to_string(inBlock) +
                              " elements exceeds the declared total of " + std::to_string(total));
        if (!findKind(type))
            return m_in.error("element type " + std::to_string(type) +
                              " is unknown; its size in a binary file is unknown");
        if (numTags < 0 || numTags > m_in.remaining() / 4)
            return m_in.error("element block with " + std::to_string(numTags) + " tags");
        if (Status s = fits(inBlock, 4 * (1 + numTags + findKind(type)->nodes),
                            "element block of " + std::to_string(inBlock) + " elements");
            !s)
            return s;
    }
    std::vector<std::int64_t> nodes;
    for (std::int64_t i = 0; i < inBlock; ++i, ++seen) {
        if (Status s = dataInt(tag, "an element line \"tag type numTags tags nodes\"", false); !s)
            return s;
        if (!m_binary) {
            if (Status s = textInt(type, "the element type", true); !s)
                return s;
            if (Status s = textInt(numTags, "the number of tags", true); !s)
                return s;
            if (numTags < 0 || numTags > m_in.remaining() / 2)
                return m_in.error("element " + std::to_string(tag) + " declares " +
                                  std::to_string(numTags) + " tags");
        }
        std::int64_t group = 0, value = 0;
        for (std::int64_t k = 0; k < numTags; ++k) {
            if (Status s = dataInt(value, "an element tag", true); !s)
                return s;
            if (k == 0)
                group = value; // the physical group; 0: none
        }
        const ElementKind* kind = findKind(type);
        if (!kind) { // ASCII only: the rest of the line is the element
            noteType(type);
            ++m_dropped[type];
            m_in.skipLineRest();
            continue;
        }
        noteType(type);
        if (Status s = readElementNodes(tag, *kind, false, nodes); !s)
            return s;
        if (Status s = addElement(tag, *kind, nodes, group); !s)
            return s;
    }
    return Status::success();
}

Status GmshParser::parseElements41() {
    if (Status s = startBinary(); !s)
        return s;
    std::int64_t header[4];
    for (int k = 0; k < 4; ++k)
        if (Status s = dataSize(
                header[k], "\"numEntityBlocks numElements minElementTag maxElementTag\"", k > 0);
            !s)
            return s;
    const std::int64_t numBlocks = header[0], numElements = header[1];
    const std::string declared = "$Elements declares " + std::to_string(numBlocks) +
                                 " blocks and " + std::to_string(numElements) + " elements";
    if (Status s = fits(numBlocks, minBytes(20, 4), declared); !s)
        return s;
    if (Status s = fits(numElements, minBytes(16, 2), declared); !s)
        return s;
    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < numBlocks; ++b)
        if (Status s = parseElementBlock41(numElements, seen); !s)
            return s;
    if (seen != numElements)
        return m_in.error(declared + " but its blocks hold " + std::to_string(seen));
    return expectEnd();
}

Status GmshParser::parseElementBlock41(std::int64_t total, std::int64_t& seen) {
    std::int64_t dim = 0, entity = 0, type = 0, inBlock = 0;
    if (Status s = dataInt(dim, "\"entityDim entityTag elementType numElementsInBlock\"", false);
        !s)
        return s;
    if (Status s = dataInt(entity, "an entity tag", true); !s)
        return s;
    if (Status s = dataInt(type, "an element type", true); !s)
        return s;
    if (Status s = dataSize(inBlock, "the number of elements in the block", true); !s)
        return s;
    if (inBlock < 0 || inBlock > total - seen)
        return m_in.error("element block of " + std::to_string(inBlock) +
                          " elements exceeds the declared total of " + std::to_string(total));
    seen += inBlock;
    noteType(type);
    const ElementKind* kind = findKind(type);
    if (!kind) {
        if (m_binary)
            return m_in.error("element type " + std::to_string(type) +
                              " is unknown; its size in a binary file is unknown");
        for (std::int64_t i = 0; i < inBlock; ++i)
            if (!m_in.skipRecord())
                return unexpectedEnd();
        m_dropped[type] += inBlock;
        return Status::success();
    }
    if (Status s = fits(inBlock, minBytes(8 * (1 + kind->nodes), 1 + kind->nodes),
                        "element block of " + std::to_string(inBlock) + " elements");
        !s)
        return s;
    const auto groupIt = m_entityGroup.find({static_cast<int>(dim), entity});
    const std::int64_t group = groupIt == m_entityGroup.end() ? 0 : groupIt->second;
    if (kind->type == kGmshTet4 || kind->type == kGmshTet10) {
        m_tets.reserve(m_tets.size() + static_cast<std::size_t>(inBlock));
        m_tetTags.reserve(m_tets.capacity());
        m_tetGroups.reserve(m_tets.capacity());
    }
    std::vector<std::int64_t> nodes;
    for (std::int64_t i = 0; i < inBlock; ++i) {
        std::int64_t tag = 0;
        if (Status s = dataSize(tag, "an element line \"tag node...\"", false); !s)
            return s;
        if (Status s = readElementNodes(tag, *kind, true, nodes); !s)
            return s;
        if (Status s = addElement(tag, *kind, nodes, group); !s)
            return s;
    }
    return Status::success();
}

/// The ASCII header of a view: string tags (the first is its name), real tags, integer
/// tags (time step, components, count, ...).
Status GmshParser::parseViewHeader(ViewHeader& header) {
    std::int64_t count = 0;
    std::string& name = header.name;
    if (Status s = textInt(count, "the number of string tags", false); !s)
        return s;
    if (Status s = fits(count, 3, "$NodeData declares " + std::to_string(count) + " string tags");
        !s)
        return s;
    for (std::int64_t i = 0; i < count; ++i) {
        std::string text;
        if (!m_in.quoted(text, false))
            return expected("a quoted string tag", false);
        if (i == 0)
            name = text;
    }
    std::int64_t numReals = 0, numInts = 0;
    double real = 0;
    if (Status s = textInt(numReals, "the number of real tags", false); !s)
        return s;
    if (Status s =
            fits(numReals, 2, "$NodeData declares " + std::to_string(numReals) + " real tags");
        !s)
        return s;
    for (std::int64_t i = 0; i < numReals; ++i)
        if (Status s = textDouble(real, "a real tag", false); !s)
            return s;
    if (Status s = textInt(numInts, "the number of integer tags", false); !s)
        return s;
    if (numInts < 3 || numInts > m_in.remaining() / 2)
        return m_in.error("$NodeData has " + std::to_string(numInts) +
                          " integer tags; expected at least 3 (time step, components, count)");
    std::vector<std::int64_t> ints(static_cast<std::size_t>(numInts));
    for (std::int64_t& v : ints)
        if (Status s = textInt(v, "an integer tag", false); !s)
            return s;
    const std::int64_t components = ints[1], values = ints[2];
    header.components = components;
    header.values = values;
    if (components < 1 || components > 9)
        return m_in.error("node data view '" + name + "' has " + std::to_string(components) +
                          " components; Gmsh allows 1 to 9");
    for (const KnownView& known : kKnownViews)
        if (name == known.name && components != known.components)
            return m_in.error("node data view '" + name + "' has " + std::to_string(components) +
                              " components; expected " + std::to_string(known.components));
    if (Status s =
            fits(values, minBytes(4 + 8 * components, 1 + components),
                 "node data view '" + name + "' declares " + std::to_string(values) + " values");
        !s)
        return s;
    return Status::success();
}

Status GmshParser::parseNodeData() {
    ViewHeader header;
    if (Status s = parseViewHeader(header); !s)
        return s;
    const std::string& name = header.name;
    const std::int64_t components = header.components, values = header.values;
    if (Status s = startBinary(); !s)
        return s;
    // The first view of a name counts (later time steps are ignored); unknown names are read
    // and dropped.
    const bool keep = std::any_of(std::begin(kKnownViews), std::end(kKnownViews),
                                  [&](const KnownView& k) { return name == k.name; }) &&
                      !m_views.count(name);
    NodeView view;
    view.components = static_cast<int>(components);
    if (keep) {
        view.tags.reserve(static_cast<std::size_t>(values));
        view.values.reserve(static_cast<std::size_t>(values * components));
    }
    for (std::int64_t i = 0; i < values; ++i) {
        std::int64_t tag = 0;
        if (Status s = dataInt(tag, "a node tag", false); !s)
            return s;
        if (keep)
            view.tags.push_back(tag);
        for (std::int64_t c = 0; c < components; ++c) {
            double v = 0;
            if (Status s = dataDouble(v, "a value", true); !s)
                return s;
            if (keep)
                view.values.push_back(v);
        }
    }
    if (keep)
        m_views.emplace(name, std::move(view));
    return expectEnd();
}

Status GmshParser::parseSection(std::string_view name) {
    m_section = std::string(name);
    if (name == "$PhysicalNames")
        return parsePhysicalNames();
    if (name == "$Entities" && m_v41)
        return parseEntities();
    if (name == "$Nodes") {
        if (m_haveNodes)
            return m_in.error("a second $Nodes section");
        m_haveNodes = true;
        return m_v41 ? parseNodes41() : parseNodes22();
    }
    if (name == "$Elements") {
        if (!m_haveNodes)
            return m_in.error("$Elements before $Nodes");
        if (m_haveElements)
            return m_in.error("a second $Elements section");
        m_haveElements = true;
        return m_v41 ? parseElements41() : parseElements22();
    }
    if (name == "$NodeData")
        return parseNodeData();
    const std::string end = "$End" + std::string(name.substr(1));
    if (!m_in.skipTo(end))
        return Status::error(m_path + ": section " + std::string(name) + " has no " + end);
    return Status::success();
}

Status GmshParser::parse() {
    if (Status s = parseFormat(); !s)
        return s;
    std::string_view name;
    while (m_in.token(name)) {
        if (name.size() < 2 || name.front() != '$' || name.substr(0, 4) == "$End")
            return m_in.error("expected a section such as $Nodes or $Elements");
        if (Status s = parseSection(name); !s)
            return s;
    }
    if (!m_haveNodes)
        return Status::error(m_path + ": no $Nodes section");
    if (!m_haveElements)
        return Status::error(m_path + ": no $Elements section");
    if (m_tets.empty()) {
        std::string types;
        constexpr std::size_t kListed = 10; // a hostile file may hold millions of types
        for (std::size_t i = 0; i < std::min(m_elementTypes.size(), kListed); ++i)
            types += (types.empty() ? "" : ", ") + std::to_string(m_elementTypes[i]);
        if (m_elementTypes.size() > kListed)
            types += " and " + std::to_string(m_elementTypes.size() - kListed) + " more";
        return Status::error(m_path + ": no 4-node tetrahedra (Gmsh element type 4)" +
                             (types.empty() ? std::string() : "; element types found: " + types));
    }
    return Status::success();
}

/// Gmsh 2.2 writes an element once per physical group it is in: keep the first copy.
void GmshParser::removeDuplicateTets() {
    std::set<Tet> seen; // sorted node sets
    std::size_t kept = 0;
    for (std::size_t t = 0; t < m_tets.size(); ++t) {
        Tet key = m_tets[t];
        std::sort(key.begin(), key.end());
        if (!seen.insert(key).second)
            continue;
        m_tets[kept] = m_tets[t];
        m_tetTags[kept] = m_tetTags[t];
        m_tetGroups[kept] = m_tetGroups[t];
        ++kept;
    }
    const std::size_t removed = m_tets.size() - kept;
    m_tets.resize(kept);
    m_tetTags.resize(kept);
    m_tetGroups.resize(kept);
    if (removed > 0)
        m_report.notes.push_back("removed " + std::to_string(removed) +
                                 " duplicate tetrahedra (Gmsh 2.2 lists an element once per "
                                 "physical group it belongs to; the first copy is kept)");
}

Status GmshParser::resolveView(const char* name, int components, std::vector<double>& out) const {
    const auto it = m_views.find(name);
    if (it == m_views.end())
        return Status::success();
    const NodeView& view = it->second;
    out.assign(m_points.size() * static_cast<std::size_t>(components), 0.0);
    std::vector<char> given(m_points.size(), 0);
    for (std::size_t i = 0; i < view.tags.size(); ++i) {
        const auto node = m_nodeIndex.find(view.tags[i]);
        if (node == m_nodeIndex.end())
            return Status::error(m_path + ": node data view '" + name + "' has a value for node " +
                                 std::to_string(view.tags[i]) + ", which is not in $Nodes");
        if (given[static_cast<std::size_t>(node->second)]++)
            return Status::error(m_path + ": node data view '" + name + "' gives node " +
                                 std::to_string(view.tags[i]) + " two values");
        std::copy_n(view.values.begin() + static_cast<std::ptrdiff_t>(i * components), components,
                    out.begin() + static_cast<std::ptrdiff_t>(node->second) * components);
    }
    if (view.tags.size() != m_points.size())
        return Status::error(m_path + ": node data view '" + name + "' has " +
                             std::to_string(view.tags.size()) + " values for " +
                             std::to_string(m_points.size()) + " nodes");
    return Status::success();
}

Status GmshParser::result(ImportedMesh& mesh, MeshReadReport& report) {
    std::vector<double> reference, velocity;
    if (Status s = resolveView("reference_position", 3, reference); !s)
        return s;
    if (Status s = resolveView("velocity", 3, velocity); !s)
        return s;
    if (Status s = resolveView("mass", 1, mesh.mass); !s)
        return s;
    const auto toVec3 = [](const std::vector<double>& v) {
        std::vector<Vec3> p(v.size() / 3);
        for (std::size_t i = 0; i < p.size(); ++i)
            p[i] = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        return p;
    };
    mesh.reference = toVec3(reference);
    mesh.velocity = toVec3(velocity);

    if (!m_v41)
        removeDuplicateTets();
    if (m_tet10 > 0)
        m_report.notes.push_back("read " + std::to_string(m_tet10) +
                                 " 10-node tetrahedra as their 4 corner nodes (the mid-edge "
                                 "nodes are left out)");
    m_report.format = m_formatName;
    for (std::int64_t type : m_elementTypes) // built here: drop() searches, which is quadratic
        if (const auto it = m_dropped.find(type); it != m_dropped.end() && it->second > 0)
            m_report.dropped.push_back({kindName(type), it->second});
    for (const auto& key : m_groupOrder) {
        MeshReadReport::Group g;
        g.dimension = key.first;
        g.tag = key.second;
        const auto name = m_names.find(key);
        if (name != m_names.end())
            g.name = name->second;
        m_report.groups.push_back(std::move(g));
    }
    if (std::any_of(m_tetGroups.begin(), m_tetGroups.end(), [](std::int64_t g) { return g != 0; }))
        mesh.tetGroup = std::move(m_tetGroups);
    mesh.points = std::move(m_points);
    mesh.tets = std::move(m_tets);
    mesh.tetLabel = [tags = std::move(m_tetTags)](int t) {
        return "element " + std::to_string(tags[static_cast<std::size_t>(t)]);
    };
    report = std::move(m_report);
    return Status::success();
}

} // namespace

Status readGmsh(const std::string& path, TetMesh& out, MeshReadReport* report) {
    return guarded(path, "reading", [&]() -> Status {
        std::string text;
        if (Status s = readWholeFile(path, text); !s)
            return s;
        ImportedMesh imported;
        MeshReadReport local;
        {
            GmshParser parser(path, text);
            if (Status s = parser.parse(); !s)
                return s;
            if (Status s = parser.result(imported, local); !s)
                return s;
        }
        TetMesh mesh;
        if (Status s = finishImportedMesh(path, std::move(imported), mesh, &local); !s)
            return s;
        out = std::move(mesh);
        if (report)
            *report = std::move(local);
        return Status::success();
    });
}

} // namespace resect
