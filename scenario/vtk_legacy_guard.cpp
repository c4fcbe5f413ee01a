#include "scenario/vtk_legacy_guard.h"

#include "scenario/mesh_io_detail.h"

#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>

namespace resect::detail {
namespace {

/// An ASCII value needs at least one character and one separator: a count of values larger
/// than half the bytes left cannot be backed by the file.
constexpr std::int64_t kMinAsciiBytesPerValue = 2;
/// VTK reads names and keywords into 256-byte buffers.
constexpr std::size_t kMaxTokenLength = 255;
/// Components of one array (FIELD, SCALARS, TEXTURE_COORDINATES): far more than any writer
/// uses, small enough that components * tuples cannot overflow.
constexpr std::int64_t kMaxComponents = 1 << 16;

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

bool equalsNoCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

/// A data type as VTK's legacy reader names it (after lower-casing), with its size in the
/// binary variant.
struct DataType {
    std::string_view name;
    int size;
    bool integer;
    bool isSigned;
};
constexpr std::array<DataType, 13> kDataTypes{{
    {"unsigned_char", 1, true, false},
    {"char", 1, true, true},
    {"short", 2, true, true},
    {"unsigned_short", 2, true, false},
    {"int", 4, true, true},
    {"unsigned_int", 4, true, false},
    {"long", 8, true, true},
    {"unsigned_long", 8, true, false},
    {"vtktypeint64", 8, true, true},
    {"vtktypeuint64", 8, true, false},
    {"vtkidtype", 8, true, true},
    {"float", 4, false, true},
    {"double", 8, false, true},
}};
constexpr DataType kUnsignedChar = kDataTypes[0];
constexpr DataType kFloat = kDataTypes[11];

/// An array kept for VTK, written to it as a FIELD array.
struct KeptArray {
    std::string name;
    std::int64_t components = 0;
    std::int64_t tuples = 0;
    std::string_view type;
    std::string_view data; ///< the file's bytes: binary values or ASCII text
};

class Parser {
public:
    Parser(const std::string& path, std::string_view bytes, VtkLegacyFile& out)
        : m_path(path), m_bytes(bytes), m_out(out) {}

    Status run() {
        if (Status s = header(); !s)
            return s;
        std::string_view word;
        while (token(word)) {
            Status s = section(word);
            if (!s)
                return s;
        }
        if (m_pointCount < 0)
            return error("no POINTS section");
        if (m_cellCount < 0)
            return error("no CELLS section");
        if (m_typeCount < 0)
            return error("no CELL_TYPES section");
        emit();
        return Status::success();
    }

private:
    // --- tokens ---

    /// The next whitespace-separated token; false at the end of the file.
    bool token(std::string_view& t) {
        while (m_pos < m_bytes.size() && isSpace(m_bytes[m_pos]))
            ++m_pos;
        if (m_pos >= m_bytes.size())
            return false;
        const std::size_t start = m_pos;
        while (m_pos < m_bytes.size() && !isSpace(m_bytes[m_pos]))
            ++m_pos;
        m_tokenStart = start;
        t = m_bytes.substr(start, m_pos - start);
        return true;
    }

    Status expect(std::string_view& t, const std::string& what) {
        if (!token(t))
            return error("unexpected end of file, expected " + what);
        if (t.size() > kMaxTokenLength)
            return error(what + " is longer than " + std::to_string(kMaxTokenLength) +
                         " characters");
        return Status::success();
    }

    Status count(std::int64_t& value, const std::string& what, std::int64_t max) {
        std::string_view t;
        if (Status s = expect(t, what); !s)
            return s;
        if (!parseInt64(t, value) || value < 0)
            return error(what + " '" + std::string(t) + "' is not a count");
        if (value > max)
            return error(what + " " + std::to_string(value) + " is larger than " +
                         std::to_string(max));
        return Status::success();
    }

    Status dataType(const DataType*& type, const std::string& section) {
        std::string_view t;
        if (Status s = expect(t, "the data type of " + section); !s)
            return s;
        for (const DataType& d : kDataTypes)
            if (equalsNoCase(t, d.name)) {
                type = &d;
                return Status::success();
            }
        return error(section + " has data type '" + std::string(t) +
                     "'; only numeric types (char to double, no bit, string or variant "
                     "arrays) are read");
    }

    /// Line number of the last token, for errors.
    std::int64_t line() const {
        return 1 + std::count(m_bytes.begin(),
                              m_bytes.begin() + static_cast<std::ptrdiff_t>(
                                                    std::min(m_tokenStart, m_bytes.size())),
                              '\n');
    }

    Status error(const std::string& what) const {
        return Status::error(m_path + ": line " + std::to_string(line()) + ": " + what);
    }

    std::int64_t remaining() const {
        return static_cast<std::int64_t>(m_bytes.size() - std::min(m_pos, m_bytes.size()));
    }

    // --- values ---

    /// Skips `count` values of `type` (section names them in errors) and returns their bytes
    /// in `raw`: binary, after the rest of the keyword's line, count * size bytes; ASCII,
    /// count tokens.
    Status values(const std::string& section, const DataType& type, std::int64_t count,
                  std::string_view& raw) {
        raw = {};
        if (count == 0)
            return Status::success();
        if (m_binary) {
            const std::size_t eol = m_bytes.find('\n', m_pos);
            if (eol == std::string_view::npos)
                return error(section + ": the binary data is missing");
            m_pos = eol + 1;
            if (count > remaining() / type.size)
                return error(section + " declares " + std::to_string(count) + " values of " +
                             std::to_string(type.size) + " bytes, but only " +
                             std::to_string(remaining()) + " bytes follow (truncated file?)");
            const auto size = static_cast<std::size_t>(count * type.size);
            raw = m_bytes.substr(m_pos, size);
            m_pos += size;
            return Status::success();
        }
        if (count > (remaining() + 1) / kMinAsciiBytesPerValue)
            return error(section + " declares " + std::to_string(count) +
                         " values, more than the " + std::to_string(remaining()) +
                         " bytes that follow can hold");
        std::string_view t;
        std::size_t first = 0;
        for (std::int64_t i = 0; i < count; ++i) {
            if (!token(t))
                return error(section + ": unexpected end of file after " + std::to_string(i) +
                             " of " + std::to_string(count) + " values");
            if (i == 0)
                first = m_tokenStart;
        }
        raw = m_bytes.substr(first, m_pos - first);
        return Status::success();
    }

    /// ASCII values that VTK will read: each must be a finite number (C++ streams, which VTK
    /// reads with, fail on "nan" and "inf"; the error then names neither value nor line).
    Status checkNumbers(const std::string& section, std::string_view raw) const {
        if (m_binary)
            return Status::success();
        std::size_t i = 0;
        while (i < raw.size()) {
            while (i < raw.size() && isSpace(raw[i]))
                ++i;
            const std::size_t start = i;
            while (i < raw.size() && !isSpace(raw[i]))
                ++i;
            if (i == start)
                break;
            const std::string_view t = raw.substr(start, i - start);
            double v = 0;
            if (!parseDouble(t, v) || !std::isfinite(v))
                return Status::error(
                    m_path + ": line " +
                    std::to_string(1 + std::count(m_bytes.begin(),
                                                  m_bytes.begin() + (raw.data() - m_bytes.data()) +
                                                      static_cast<std::ptrdiff_t>(start),
                                                  '\n')) +
                    ": " + section + ": '" + std::string(t.substr(0, 40)) +
                    "' is not a finite number");
        }
        return Status::success();
    }

    /// `count` integer values of `type`, parsed (binary: big-endian).
    Status intValues(const std::string& section, const DataType& type, std::int64_t count,
                     std::vector<std::int64_t>& out) {
        if (!type.integer)
            return error(section + " has data type " + std::string(type.name) +
                         "; expected an integer type");
        std::string_view raw;
        if (Status s = values(section, type, count, raw); !s)
            return s;
        out.clear();
        out.reserve(static_cast<std::size_t>(count));
        if (m_binary) {
            for (std::int64_t i = 0; i < count; ++i) {
                std::uint64_t u = 0;
                for (int b = 0; b < type.size; ++b)
                    u = (u << 8) | static_cast<unsigned char>(raw[static_cast<std::size_t>(
                                       i * type.size + b)]);
                std::int64_t v = 0;
                if (type.isSigned && type.size < 8 && (u >> (8 * type.size - 1)) != 0)
                    v = static_cast<std::int64_t>(u) - (std::int64_t(1) << (8 * type.size));
                else if (!type.isSigned && u > static_cast<std::uint64_t>(
                                                   std::numeric_limits<std::int64_t>::max()))
                    return error(section + ": value " + std::to_string(u) + " is too large");
                else
                    v = static_cast<std::int64_t>(u);
                out.push_back(v);
            }
            return Status::success();
        }
        std::vector<std::string_view> tokens;
        splitTokens(raw, tokens);
        for (std::string_view t : tokens) {
            std::int64_t v = 0;
            if (!parseInt64(t, v))
                return error(section + ": '" + std::string(t) + "' is not an integer");
            out.push_back(v);
        }
        return Status::success();
    }

    // --- structure ---

    Status header() {
        constexpr std::string_view kMagic = "# vtk DataFile Version";
        m_tokenStart = 0;
        const std::size_t eol1 = m_bytes.find('\n');
        const std::string_view first = m_bytes.substr(0, eol1);
        if (first.substr(0, kMagic.size()) != kMagic)
            return error("not a legacy VTK file (the first line is not \"" +
                         std::string(kMagic) + " X.Y\")");
        std::vector<std::string_view> tok;
        splitTokens(first.substr(kMagic.size()), tok);
        const std::string_view version = tok.empty() ? std::string_view() : tok[0];
        const std::size_t dot = version.find('.');
        std::int64_t major = 0, minor = 0;
        if (dot == std::string_view::npos || !parseInt64(version.substr(0, dot), major) ||
            !parseInt64(version.substr(dot + 1), minor) || major < 1 || major > 5 || minor < 0 ||
            minor > 9 || major * 10 + minor > 51)
            return error("version '" + std::string(version) +
                         "'; legacy VTK versions 1.0 to 5.1 are read");
        m_out.majorVersion = static_cast<int>(major);
        m_out.minorVersion = static_cast<int>(minor);
        if (eol1 == std::string_view::npos)
            return error("the file ends after its first line");
        const std::size_t eol2 = m_bytes.find('\n', eol1 + 1); // the title: any text
        if (eol2 == std::string_view::npos)
            return error("the file ends after its title line");
        m_pos = eol2 + 1;
        std::string_view t;
        if (Status s = expect(t, "ASCII or BINARY"); !s)
            return s;
        if (equalsNoCase(t, "ASCII"))
            m_binary = false;
        else if (equalsNoCase(t, "BINARY"))
            m_binary = true;
        else
            return error("expected ASCII or BINARY, found '" + std::string(t) + "'");
        m_out.binary = m_binary;
        if (Status s = expect(t, "DATASET"); !s)
            return s;
        if (!equalsNoCase(t, "DATASET"))
            return error("expected DATASET UNSTRUCTURED_GRID, found '" + std::string(t) + "'");
        if (Status s = expect(t, "the dataset type"); !s)
            return s;
        if (!equalsNoCase(t, "UNSTRUCTURED_GRID"))
            return error("dataset type " + std::string(t) +
                         "; a tet mesh is a DATASET UNSTRUCTURED_GRID");
        return Status::success();
    }

    Status section(std::string_view word) {
        const std::string w(word.substr(0, kMaxTokenLength));
        if (equalsNoCase(word, "POINTS"))
            return points();
        if (equalsNoCase(word, "CELLS"))
            return cells();
        if (equalsNoCase(word, "CELL_TYPES"))
            return cellTypes();
        if (equalsNoCase(word, "POINT_DATA") || equalsNoCase(word, "CELL_DATA"))
            return dataSection(equalsNoCase(word, "POINT_DATA"));
        if (equalsNoCase(word, "FIELD"))
            return field();
        if (equalsNoCase(word, "METADATA"))
            return metadata();
        if (m_attributes == Attributes::None)
            return error("unknown section '" + w + "'");
        return attribute(word);
    }

    Status points() {
        if (m_pointCount >= 0)
            return error("a second POINTS section");
        std::int64_t n = 0;
        if (Status s = count(n, "the number of points", kMaxMeshItems); !s)
            return s;
        const DataType* type = nullptr;
        if (Status s = dataType(type, "POINTS"); !s)
            return s;
        m_pointCount = n;
        m_pointType = type->name;
        if (Status s = values("POINTS", *type, 3 * n, m_pointData); !s)
            return s;
        return checkNumbers("POINTS", m_pointData);
    }

    Status cells() {
        if (m_cellCount >= 0)
            return error("a second CELLS section");
        std::int64_t a = 0, b = 0;
        if (Status s = count(a, "the first count of CELLS", kMaxMeshItems); !s)
            return s;
        if (Status s = count(b, "the second count of CELLS", std::numeric_limits<std::int32_t>::max()); !s)
            return s;
        if (m_out.majorVersion >= 5)
            return cellsWithOffsets(a, b);
        // Up to 4.2: a cells, b values, each cell "n id1 ... idn" (int).
        std::vector<std::int64_t> v;
        if (Status s = intValues("CELLS", kDataTypes[4], b, v); !s)
            return s;
        m_offsets.assign(1, 0);
        m_connectivity.clear();
        m_connectivity.reserve(v.size());
        for (std::size_t i = 0; i < v.size();) {
            const std::int64_t n = v[i];
            const auto left = static_cast<std::int64_t>(v.size() - i - 1);
            if (n < 0 || n > left)
                return error("CELLS: cell " + std::to_string(m_offsets.size() - 1) +
                             " declares " + std::to_string(n) + " nodes, but " +
                             std::to_string(left) + " values are left");
            m_connectivity.insert(m_connectivity.end(), v.begin() + static_cast<std::ptrdiff_t>(i + 1),
                                  v.begin() + static_cast<std::ptrdiff_t>(i + 1 + static_cast<std::size_t>(n)));
            m_offsets.push_back(static_cast<std::int64_t>(m_connectivity.size()));
            i += static_cast<std::size_t>(n) + 1;
        }
        if (static_cast<std::int64_t>(m_offsets.size()) - 1 != a)
            return error("CELLS declares " + std::to_string(a) + " cells, but its " +
                         std::to_string(b) + " values hold " +
                         std::to_string(m_offsets.size() - 1));
        m_cellCount = a;
        return checkIds();
    }

    /// Version 5: CELLS (cells + 1) connectivitySize, OFFSETS type, CONNECTIVITY type.
    Status cellsWithOffsets(std::int64_t offsetCount, std::int64_t size) {
        if (offsetCount < 1)
            return error("CELLS declares " + std::to_string(offsetCount) +
                         " offsets; there must be one more than cells");
        std::string_view t;
        const DataType* type = nullptr;
        if (Status s = expect(t, "OFFSETS"); !s)
            return s;
        if (!equalsNoCase(t, "OFFSETS"))
            return error("expected OFFSETS after CELLS in a version 5 file, found '" +
                         std::string(t) + "'");
        if (Status s = dataType(type, "OFFSETS"); !s)
            return s;
        if (Status s = intValues("OFFSETS", *type, offsetCount, m_offsets); !s)
            return s;
        if (Status s = expect(t, "CONNECTIVITY"); !s)
            return s;
        if (!equalsNoCase(t, "CONNECTIVITY"))
            return error("expected CONNECTIVITY after OFFSETS, found '" + std::string(t) + "'");
        if (Status s = dataType(type, "CONNECTIVITY"); !s)
            return s;
        if (Status s = intValues("CONNECTIVITY", *type, size, m_connectivity); !s)
            return s;
        if (m_offsets.front() != 0 || m_offsets.back() != size)
            return error("OFFSETS must run from 0 to the CONNECTIVITY size " +
                         std::to_string(size));
        for (std::size_t i = 1; i < m_offsets.size(); ++i)
            if (m_offsets[i] < m_offsets[i - 1])
                return error("OFFSETS decrease at cell " + std::to_string(i - 1));
        m_cellCount = offsetCount - 1;
        return checkIds();
    }

    Status checkIds() {
        for (std::size_t i = 0; i < m_connectivity.size(); ++i)
            if (m_connectivity[i] < 0 || m_connectivity[i] > kMaxMeshItems)
                return error("CELLS: node id " + std::to_string(m_connectivity[i]) +
                             " is out of range");
        return Status::success();
    }

    Status cellTypes() {
        if (m_typeCount >= 0)
            return error("a second CELL_TYPES section");
        std::int64_t n = 0;
        if (Status s = count(n, "the number of cell types", kMaxMeshItems); !s)
            return s;
        if (m_cellCount >= 0 && n != m_cellCount)
            return error("CELL_TYPES lists " + std::to_string(n) + " types for " +
                         std::to_string(m_cellCount) + " cells");
        if (Status s = intValues("CELL_TYPES", kDataTypes[4], n, m_types); !s)
            return s;
        for (std::size_t c = 0; c < m_types.size(); ++c)
            if (m_types[c] < 0 || m_types[c] >= VTK_NUMBER_OF_CELL_TYPES ||
                m_types[c] == VTK_POLYHEDRON)
                return error("CELL_TYPES: cell " + std::to_string(c) + " has type " +
                             std::to_string(m_types[c]) +
                             (m_types[c] == VTK_POLYHEDRON ? " (VTK_POLYHEDRON, not read)"
                                                           : ", which VTK does not know"));
        m_typeCount = n;
        return Status::success();
    }

    Status dataSection(bool pointData) {
        const std::string name = pointData ? "POINT_DATA" : "CELL_DATA";
        std::int64_t n = 0;
        if (Status s = count(n, "the count of " + name, kMaxMeshItems); !s)
            return s;
        const std::int64_t expected = pointData ? m_pointCount : m_cellCount;
        if (expected < 0)
            return error(name + " before " + (pointData ? "POINTS" : "CELLS"));
        if (n != expected)
            return error(name + " " + std::to_string(n) + " does not match the " +
                         std::to_string(expected) + (pointData ? " points" : " cells"));
        m_attributes = pointData ? Attributes::Point : Attributes::Cell;
        m_attributeTuples = n;
        return Status::success();
    }

    bool keep(std::string_view name) const {
        if (m_attributes == Attributes::Point)
            return std::find(std::begin(kVtkPointArrays), std::end(kVtkPointArrays), name) !=
                   std::end(kVtkPointArrays);
        if (m_attributes == Attributes::Cell)
            return std::find(std::begin(kVtkCellArrays), std::end(kVtkCellArrays), name) !=
                   std::end(kVtkCellArrays);
        return false;
    }

    /// An array of an attribute section or a FIELD: kept (as a FIELD array) or skipped.
    Status array(const std::string& kind, std::string_view name, std::int64_t components,
                 std::int64_t tuples, const DataType& type) {
        const std::string label = kind + " '" + std::string(name) + "'";
        std::string_view raw;
        if (components > 0 && tuples > std::numeric_limits<std::int64_t>::max() / components)
            return error(label + " is too large");
        if (Status s = values(label, type, components * tuples, raw); !s)
            return s;
        if (keep(name)) {
            std::vector<KeptArray>& list =
                m_attributes == Attributes::Point ? m_pointArrays : m_cellArrays;
            const auto same = [&](const KeptArray& k) { return k.name == name; };
            if (std::find_if(list.begin(), list.end(), same) == list.end()) {
                if (Status s = checkNumbers(label, raw); !s)
                    return s;
                list.push_back({std::string(name), components, tuples, type.name, raw});
                return Status::success();
            }
        }
        m_out.skipped.push_back(label);
        return Status::success();
    }

    Status attribute(std::string_view word) {
        const std::string kind(word);
        std::string_view name, t;
        if (Status s = expect(name, "the name of " + kind); !s)
            return s;
        const DataType* type = nullptr;
        const std::int64_t n = m_attributeTuples;
        if (equalsNoCase(word, "SCALARS")) {
            if (Status s = dataType(type, kind); !s)
                return s;
            // "SCALARS name type [components]" then "LOOKUP_TABLE tableName".
            if (Status s = expect(t, "LOOKUP_TABLE"); !s)
                return s;
            std::int64_t components = 1;
            if (!equalsNoCase(t, "LOOKUP_TABLE")) {
                if (!parseInt64(t, components) || components < 1 || components > kMaxComponents)
                    return error(kind + " '" + std::string(name) + "': '" + std::string(t) +
                                 "' is not a number of components (1 to " +
                                 std::to_string(kMaxComponents) + ")");
                if (Status s = expect(t, "LOOKUP_TABLE"); !s)
                    return s;
                if (!equalsNoCase(t, "LOOKUP_TABLE"))
                    return error(kind + " '" + std::string(name) +
                                 "' needs a LOOKUP_TABLE line, found '" + std::string(t) + "'");
            }
            if (Status s = expect(t, "the lookup table's name"); !s)
                return s;
            return array(kind, name, components, n, *type);
        }
        if (equalsNoCase(word, "VECTORS") || equalsNoCase(word, "NORMALS") ||
            equalsNoCase(word, "TENSORS") || equalsNoCase(word, "TENSORS6") ||
            equalsNoCase(word, "GLOBAL_IDS") || equalsNoCase(word, "PEDIGREE_IDS")) {
            if (Status s = dataType(type, kind); !s)
                return s;
            const std::int64_t components = equalsNoCase(word, "TENSORS")    ? 9
                                             : equalsNoCase(word, "TENSORS6") ? 6
                                             : (equalsNoCase(word, "GLOBAL_IDS") ||
                                                equalsNoCase(word, "PEDIGREE_IDS"))
                                                 ? 1
                                                 : 3;
            return array(kind, name, components, n, *type);
        }
        if (equalsNoCase(word, "TEXTURE_COORDINATES")) {
            std::int64_t dim = 0;
            if (Status s = count(dim, "the dimension of " + kind, 3); !s)
                return s;
            if (dim < 1)
                return error(kind + " of dimension 0");
            if (Status s = dataType(type, kind); !s)
                return s;
            return array(kind, name, dim, n, *type);
        }
        if (equalsNoCase(word, "COLOR_SCALARS")) {
            std::int64_t components = 0;
            if (Status s = count(components, "the number of values of " + kind, kMaxComponents); !s)
                return s;
            m_out.skipped.push_back(kind + " '" + std::string(name) + "'");
            std::string_view raw;
            return values(kind, m_binary ? kUnsignedChar : kFloat, components * n, raw);
        }
        if (equalsNoCase(word, "LOOKUP_TABLE")) {
            std::int64_t size = 0;
            if (Status s = count(size, "the size of " + kind, kMaxMeshItems); !s)
                return s;
            m_out.skipped.push_back(kind + " '" + std::string(name) + "'");
            std::string_view raw;
            return values(kind, m_binary ? kUnsignedChar : kFloat, 4 * size, raw);
        }
        return error("unknown section '" + kind + "'");
    }

    /// FIELD name numArrays, then per array "name components tuples type" and its values
    /// (or NULL_ARRAY). Outside POINT_DATA / CELL_DATA the arrays are the dataset's: skipped.
    Status field() {
        std::string_view name;
        if (Status s = expect(name, "the name of FIELD"); !s)
            return s;
        std::int64_t arrays = 0;
        if (Status s = count(arrays, "the number of FIELD arrays", kMaxComponents); !s)
            return s;
        for (std::int64_t i = 0; i < arrays; ++i) {
            std::string_view arrayName;
            if (Status s = expect(arrayName, "the name of a FIELD array"); !s)
                return s;
            if (arrayName == "NULL_ARRAY")
                continue;
            std::int64_t components = 0, tuples = 0;
            if (Status s = count(components, "the components of FIELD array '" +
                                                 std::string(arrayName) + "'", kMaxComponents);
                !s)
                return s;
            if (Status s = count(tuples, "the tuples of FIELD array '" +
                                             std::string(arrayName) + "'", kMaxMeshItems);
                !s)
                return s;
            const DataType* type = nullptr;
            if (Status s = dataType(type, "FIELD array '" + std::string(arrayName) + "'"); !s)
                return s;
            if (Status s = array("FIELD array", arrayName, components, tuples, *type); !s)
                return s;
            // An array's METADATA block, if any, is skipped with it.
            const std::size_t save = m_pos, saveStart = m_tokenStart;
            std::string_view next;
            if (token(next) && equalsNoCase(next, "METADATA")) {
                if (Status s = metadata(); !s)
                    return s;
            } else {
                m_pos = save;
                m_tokenStart = saveStart;
            }
        }
        return Status::success();
    }

    /// METADATA (component names, information keys): up to the next blank line, skipped.
    Status metadata() {
        const std::size_t eol = m_bytes.find('\n', m_pos);
        m_pos = eol == std::string_view::npos ? m_bytes.size() : eol + 1;
        while (m_pos < m_bytes.size()) {
            std::size_t end = m_bytes.find('\n', m_pos);
            if (end == std::string_view::npos)
                end = m_bytes.size();
            const std::string_view l = m_bytes.substr(m_pos, end - m_pos);
            m_pos = std::min(end + 1, m_bytes.size());
            if (std::all_of(l.begin(), l.end(), isSpace))
                break;
        }
        if (std::find(m_out.skipped.begin(), m_out.skipped.end(), "METADATA") ==
            m_out.skipped.end())
            m_out.skipped.push_back("METADATA");
        return Status::success();
    }

    // --- the file for VTK ---

    void appendInts(const std::vector<std::int64_t>& v, int size) {
        std::string& s = m_out.forVtk;
        if (m_binary) {
            for (std::int64_t x : v)
                for (int b = size - 1; b >= 0; --b)
                    s.push_back(static_cast<char>((static_cast<std::uint64_t>(x) >> (8 * b)) & 0xff));
        } else {
            for (std::int64_t x : v) {
                s += std::to_string(x);
                s.push_back('\n');
            }
        }
        s.push_back('\n');
    }

    void appendArrays(const char* section, std::int64_t n, const std::vector<KeptArray>& list) {
        if (list.empty())
            return;
        std::string& s = m_out.forVtk;
        s += std::string(section) + " " + std::to_string(n) + "\nFIELD FieldData " +
             std::to_string(list.size()) + "\n";
        for (const KeptArray& a : list) {
            s += a.name + " " + std::to_string(a.components) + " " + std::to_string(a.tuples) +
                 " " + std::string(a.type) + "\n";
            s += a.data;
            s += "\n";
        }
    }

    void emit() {
        std::string& s = m_out.forVtk;
        s = "# vtk DataFile Version 5.1\nchecked by resect\n";
        s += m_binary ? "BINARY\n" : "ASCII\n";
        s += "DATASET UNSTRUCTURED_GRID\nPOINTS " + std::to_string(m_pointCount) + " " +
             std::string(m_pointType) + "\n";
        s += m_pointData;
        s += "\nCELLS " + std::to_string(m_offsets.size()) + " " +
             std::to_string(m_connectivity.size()) + "\nOFFSETS vtktypeint64\n";
        appendInts(m_offsets, 8);
        s += "CONNECTIVITY vtktypeint64\n";
        appendInts(m_connectivity, 8);
        s += "CELL_TYPES " + std::to_string(m_types.size()) + "\n";
        appendInts(m_types, 4);
        appendArrays("CELL_DATA", m_cellCount, m_cellArrays);
        appendArrays("POINT_DATA", m_pointCount, m_pointArrays);
    }

    enum class Attributes { None, Point, Cell };

    const std::string& m_path;
    std::string_view m_bytes;
    VtkLegacyFile& m_out;
    std::size_t m_pos = 0;
    std::size_t m_tokenStart = 0;
    bool m_binary = false;
    std::int64_t m_pointCount = -1, m_cellCount = -1, m_typeCount = -1;
    std::string_view m_pointType, m_pointData;
    std::vector<std::int64_t> m_offsets, m_connectivity, m_types;
    Attributes m_attributes = Attributes::None;
    std::int64_t m_attributeTuples = 0;
    std::vector<KeptArray> m_pointArrays, m_cellArrays;
};

} // namespace

Status checkVtkLegacyFile(const std::string& path, std::string_view bytes, VtkLegacyFile& out) {
    VtkLegacyFile result;
    Parser parser(path, bytes, result);
    if (Status s = parser.run(); !s)
        return s;
    if (result.forVtk.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return Status::error(path + ": too large for VTK's legacy reader (2 GiB)");
    out = std::move(result);
    return Status::success();
}

Status vtkArrayOfShape(const std::string& path, vtkFieldData* data, const char* what,
                       const char* name, int components, long long tuples, vtkDataArray*& array) {
    array = nullptr;
    vtkAbstractArray* abstract = data ? data->GetAbstractArray(name) : nullptr;
    if (!abstract)
        return Status::success();
    array = vtkDataArray::SafeDownCast(abstract);
    if (!array)
        return Status::error(path + ": " + what + " '" + name + "' is not numeric");
    if (array->GetNumberOfComponents() != components)
        return Status::error(path + ": " + what + " '" + name + "' has " +
                             std::to_string(array->GetNumberOfComponents()) +
                             " components, expected " + std::to_string(components));
    if (array->GetNumberOfTuples() != tuples)
        return Status::error(path + ": " + what + " '" + name + "' has " +
                             std::to_string(array->GetNumberOfTuples()) + " values, but there are " +
                             std::to_string(tuples) +
                             (std::string_view(what).find("cell") != std::string_view::npos
                                  ? " cells"
                                  : " points"));
    return Status::success();
}

Status vtkArrayToVectors(const std::string& path, vtkDataArray* array, const char* what,
                         std::vector<Vec3>& out) {
    const vtkIdType n = array->GetNumberOfTuples();
    std::vector<Vec3> values(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i) {
        Vec3 v(array->GetComponent(i, 0), array->GetComponent(i, 1), array->GetComponent(i, 2));
        if (!v.allFinite())
            return Status::error(path + ": " + what + " of point " + std::to_string(i) +
                                 " is not finite");
        values[static_cast<std::size_t>(i)] = v;
    }
    out = std::move(values);
    return Status::success();
}

Status gridNodeData(const std::string& path, vtkUnstructuredGrid* grid, std::vector<Vec3>& reference,
                    std::vector<double>& mass, std::vector<Vec3>& velocity) {
    vtkPointData* pd = grid->GetPointData();
    const vtkIdType n = grid->GetNumberOfPoints();
    vtkDataArray *refArray = nullptr, *massArray = nullptr, *velArray = nullptr;
    if (Status s = vtkArrayOfShape(path, pd, "point array", "reference_position", 3, n, refArray); !s)
        return s;
    if (Status s = vtkArrayOfShape(path, pd, "point array", "mass", 1, n, massArray); !s)
        return s;
    if (Status s = vtkArrayOfShape(path, pd, "point array", "velocity", 3, n, velArray); !s)
        return s;
    reference.clear();
    mass.clear();
    velocity.clear();
    if (refArray)
        if (Status s = vtkArrayToVectors(path, refArray, "reference_position", reference); !s)
            return s;
    if (velArray)
        if (Status s = vtkArrayToVectors(path, velArray, "velocity", velocity); !s)
            return s;
    if (massArray) {
        mass.resize(static_cast<std::size_t>(n));
        for (vtkIdType i = 0; i < n; ++i)
            mass[static_cast<std::size_t>(i)] = massArray->GetComponent(i, 0);
    }
    return Status::success();
}

} // namespace resect::detail
