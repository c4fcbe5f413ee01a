#include "scenario/assimp_guard.h"

#include "scenario/mesh_io_detail.h"

#include <QByteArray>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>
#include <vector>

namespace resect::detail {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------
// PLY (http://paulbourke.net/dataformats/ply/): "ply", "format ascii|binary_little_endian|
// binary_big_endian 1.0", then "element NAME COUNT" lines, each followed by its properties,
// "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME", then "end_header".

/// True if assimp might read the file as PLY, judged from its first bytes. assimp 5.2 checks
/// that the first line starts with "ply" in any case, but its line reader skips a first line
/// that begins with a line-end character ('\0', '\r', '\n', '\f'; seen in
/// tests/fuzz_regressions/surface_ply/hang-truncated-header-after-junk-line.ply). The test
/// here is wider: any line that starts in the first 256 bytes and begins, after blanks,
/// with "ply" in any case.
bool mayBeReadAsPly(std::string_view head) {
    const auto isLineEnd = [](char c) { return c == '\n' || c == '\r' || c == '\0' || c == '\f'; };
    const auto lower = [](char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    };
    constexpr std::size_t kLookAhead = 256;
    for (std::size_t line = 0; line < head.size() && line < kLookAhead;) {
        std::size_t i = line;
        while (i < head.size() && (head[i] == ' ' || head[i] == '\t' || head[i] == '\v'))
            ++i;
        if (head.size() - i >= 3 && lower(head[i]) == 'p' && lower(head[i + 1]) == 'l' &&
            lower(head[i + 2]) == 'y')
            return true;
        while (i < head.size() && !isLineEnd(head[i]))
            ++i;
        line = i + 1;
    }
    return false;
}

/// Bytes of a PLY scalar type; 0 if unknown.
int plyTypeSize(std::string_view type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
        return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
        return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64")
        return 8;
    return 0;
}

bool plyTypeSigned(std::string_view type) {
    return type == "char" || type == "int8" || type == "short" || type == "int16" ||
           type == "int" || type == "int32";
}

struct PlyProperty {
    bool list = false;
    int countSize = 0; ///< list: bytes of the count (binary)
    bool countSigned = false;
    int size = 0; ///< bytes of the value, or of each list item
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

/// At most 40 characters of `token` for a message, bytes outside printable ASCII as '?'.
std::string quoted(std::string_view token) {
    std::string text(token.substr(0, 40));
    for (char& c : text)
        if (c < 0x20 || c > 0x7e)
            c = '?';
    return text;
}

/// The leading decimal digits of `token` (saturating at 2^62); false if it has none.
bool leadingCount(std::string_view token, std::uint64_t& value) {
    value = 0;
    std::size_t i = 0;
    for (; i < token.size() && token[i] >= '0' && token[i] <= '9'; ++i)
        value = std::min<std::uint64_t>(value * 10 + static_cast<unsigned>(token[i] - '0'),
                                        std::uint64_t(1) << 62);
    return i > 0;
}

/// Walks the data of a PLY file as the header declares it; an error message if it cannot
/// hold what is declared, else empty. ASCII: one token per scalar, a count token then that
/// many tokens per list. Binary: the declared sizes, counts in the file's byte order.
std::string walkPlyData(std::string_view data, const std::vector<PlyElement>& elements, bool ascii,
                        bool bigEndian) {
    std::size_t pos = 0;
    const auto isBlank = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
    };
    const auto nextToken = [&](std::string_view& token) {
        while (pos < data.size() && isBlank(data[pos]))
            ++pos;
        const std::size_t start = pos;
        while (pos < data.size() && !isBlank(data[pos]))
            ++pos;
        token = data.substr(start, pos - start);
        return !token.empty();
    };
    for (const PlyElement& e : elements) {
        const std::string where = "element " + e.name;
        for (std::uint64_t i = 0; i < e.count; ++i) {
            for (const PlyProperty& p : e.properties) {
                if (ascii) {
                    std::string_view token;
                    if (!nextToken(token))
                        return "its data end in " + where + " " + std::to_string(i);
                    if (!p.list)
                        continue;
                    std::uint64_t n = 0;
                    if (!leadingCount(token, n))
                        return where + " " + std::to_string(i) + " has the list length '" +
                               quoted(token) + "'";
                    // Each value takes a character and a separator.
                    if (n > (data.size() - pos) / 2)
                        return where + " " + std::to_string(i) + " declares a list of " +
                               std::to_string(n) + " values, more than the file holds";
                    for (std::uint64_t k = 0; k < n; ++k)
                        if (!nextToken(token))
                            return "its data end in " + where + " " + std::to_string(i);
                    continue;
                }
                if (!p.list) {
                    if (data.size() - pos < static_cast<std::size_t>(p.size))
                        return "its data end in " + where + " " + std::to_string(i);
                    pos += static_cast<std::size_t>(p.size);
                    continue;
                }
                if (data.size() - pos < static_cast<std::size_t>(p.countSize))
                    return "its data end in " + where + " " + std::to_string(i);
                std::uint64_t n = 0;
                for (int k = 0; k < p.countSize; ++k) {
                    const int byte = bigEndian ? k : p.countSize - 1 - k;
                    n = (n << 8) |
                        static_cast<unsigned char>(data[pos + static_cast<std::size_t>(byte)]);
                }
                const bool negative = p.countSigned && (n >> (8 * p.countSize - 1)) != 0;
                pos += static_cast<std::size_t>(p.countSize);
                if (negative || n > (data.size() - pos) / static_cast<std::uint64_t>(p.size))
                    return where + " " + std::to_string(i) + " declares a list of " +
                           (negative ? std::string("negative length")
                                     : std::to_string(n) + " values, more than the file holds");
                pos += static_cast<std::size_t>(n) * static_cast<std::size_t>(p.size);
            }
        }
    }
    return {};
}

/// assimp 5.2's PLY reader loops forever on a header without end_header (a truncated file),
/// and works for as long as a list count says, however little data follows. See
/// assimp_guard.h.
Status checkPly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(256, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    if (!mayBeReadAsPly(head))
        return Status::success(); // not a PLY file: assimp decides
    std::string file;
    if (Status s = readWholeFile(path, file); !s)
        return s;
    const auto damaged = [&](const std::string& what) {
        return Status::error(path + ": damaged PLY file (" + what + ")");
    };

    // The header ends with a line that starts with "end_header" followed by a blank or a
    // line end: the characters assimp's own test accepts (not '\v', with which it hangs).
    // The header is ASCII in every PLY variant; far more than 1 MiB is damage.
    constexpr std::size_t kMaxHeaderBytes = 1 << 20;
    const std::string_view header = std::string_view(file).substr(0, kMaxHeaderBytes);
    const auto ends = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\0' || c == '\f';
    };
    std::size_t endHeader = std::string_view::npos;
    for (std::size_t at = header.find("\nend_header"); at != std::string_view::npos;
         at = header.find("\nend_header", at + 1)) {
        const std::size_t after = at + 11;
        if (after == header.size() || ends(header[after])) {
            endHeader = at + 1;
            break;
        }
    }
    if (endHeader == std::string_view::npos)
        return damaged("its header has no end_header line");

    // Elements and properties. Unknown lines are skipped, as assimp does.
    std::vector<PlyElement> elements;
    std::string_view format;
    LineReader lines(header.substr(0, endHeader));
    std::string_view line;
    std::vector<std::string_view> tok;
    while (lines.next(line)) {
        splitTokens(line, tok);
        if (tok.size() >= 2 && tok[0] == "format") {
            format = tok[1];
        } else if (!tok.empty() && tok[0] == "element") {
            // assimp's own parse of this line is loose: a count glued to the name is taken
            // as the count too. So no number on the line may exceed the file size.
            for (std::size_t k = 1; k < tok.size(); ++k) {
                std::uint64_t n = 0;
                if (leadingCount(tok[k], n) && n > file.size())
                    return damaged("an element declares " + quoted(tok[k]) +
                                   " items, more than a file of " + std::to_string(file.size()) +
                                   " bytes can hold");
            }
            PlyElement e;
            if (tok.size() < 3 || !leadingCount(tok[2], e.count))
                return damaged("an element line is not \"element NAME COUNT\"");
            e.name = quoted(tok[1]);
            elements.push_back(std::move(e));
        } else if (tok.size() >= 3 && tok[0] == "property" && !elements.empty()) {
            PlyProperty p;
            if (tok[1] == "list" && tok.size() >= 5) {
                p.list = true;
                p.countSize = plyTypeSize(tok[2]);
                p.countSigned = plyTypeSigned(tok[2]);
                p.size = plyTypeSize(tok[3]);
                if (p.countSize == 0 || p.countSize == 8 || p.size == 0)
                    return damaged("element " + elements.back().name +
                                   " has a list property of types '" + quoted(tok[2]) + "' and '" +
                                   quoted(tok[3]) + "'");
            } else {
                p.size = plyTypeSize(tok[1]);
                if (p.size == 0)
                    return damaged("element " + elements.back().name +
                                   " has a property of unknown type '" + quoted(tok[1]) + "'");
            }
            elements.back().properties.push_back(p);
        }
    }
    const bool ascii = format == "ascii";
    if (!ascii && format != "binary_little_endian" && format != "binary_big_endian")
        return damaged("its format is '" + quoted(format) +
                       "', not ascii, binary_little_endian or binary_big_endian");
    // The data start on the line after end_header.
    const std::size_t newline = file.find('\n', endHeader);
    const std::string_view data = newline == std::string::npos
                                      ? std::string_view()
                                      : std::string_view(file).substr(newline + 1);
    if (const std::string bad = walkPlyData(data, elements, ascii, format == "binary_big_endian");
        !bad.empty())
        return damaged(bad);
    return Status::success();
}

// ---------------------------------------------------------------------------------------
// OFF and glTF

/// assimp 5.2's OFF reader allocates (and initialises) its vertex and face arrays from the
/// counts in the header before reading them, so a few bytes declaring 2e9 vertices make it
/// allocate tens of gigabytes. It reads the counts with a loose parser: digits up to the
/// first other character, the keyword (OFF, COFF, NOFF, STOFF, 4OFF, nOFF, ...) optional and
/// not necessarily followed by a blank. So for a file with the .off extension or a first
/// token that holds "off" within its first six characters, the first three numbers after
/// the keyword and any '#' comment lines (dimension and counts, each read as the leading
/// digits of a token) must each be at most the file's size in bytes: every vertex or face
/// takes several bytes.
Status checkOffCounts(const std::string& path) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec)
        return Status::error(path + ": cannot read its size (" + ec.message() + ")");
    // The keyword and the counts come first; comments before them are short.
    std::string text(64 * 1024, '\0');
    std::ifstream in(path, std::ios::binary);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    std::vector<std::string_view> tokens;
    LineReader lines(text);
    std::string_view line;
    while (tokens.size() < 4 && lines.nextContent(line, '#')) {
        std::vector<std::string_view> more;
        splitTokens(line, more);
        tokens.insert(tokens.end(), more.begin(), more.end());
    }
    bool keyword = false;
    if (!tokens.empty()) {
        std::string first(tokens.front().substr(0, 6));
        std::transform(first.begin(), first.end(), first.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (const std::size_t at = first.find("off"); at != std::string::npos) {
            keyword = true;
            tokens.front().remove_prefix(at + 3); // numbers may follow the keyword directly
            if (tokens.front().empty())
                tokens.erase(tokens.begin());
        }
    }
    if (!keyword && lowerExtension(path) != ".off")
        return Status::success();
    for (std::size_t i = 0; i < tokens.size() && i < 3; ++i) {
        std::uintmax_t count = 0;
        std::size_t digits = 0;
        for (; digits < tokens[i].size() && tokens[i][digits] >= '0' && tokens[i][digits] <= '9';
             ++digits)
            count = std::min<std::uintmax_t>(count * 10 +
                                                 static_cast<unsigned>(tokens[i][digits] - '0'),
                                             std::uintmax_t(1) << 62);
        if (digits == 0)
            break; // not a number: assimp reports what is wrong
        if (count > size)
            return Status::error(path + ": damaged OFF file (its header declares " +
                                 std::string(tokens[i].substr(0, digits)) +
                                 " vertices or faces, more than a file of " + std::to_string(size) +
                                 " bytes can hold)");
    }
    return Status::success();
}

/// The JSON of a glTF file: the whole file for text glTF (first non-blank byte '{'), the
/// first chunk for binary glTF ("glTF" magic, then a 12-byte header; chunk: uint32 length,
/// "JSON", data). Empty if it is neither.
QByteArray gltfJson(const QByteArray& file) {
    if (file.startsWith("glTF")) {
        if (file.size() < 20 || file.mid(16, 4) != "JSON")
            return {};
        std::uint32_t length = 0;
        for (int k = 3; k >= 0; --k)
            length = (length << 8) | static_cast<unsigned char>(file[12 + k]);
        return file.mid(20,
                        static_cast<qsizetype>(std::min<std::uint64_t>(length, file.size() - 20)));
    }
    const QByteArray trimmed = file.left(64).trimmed();
    return trimmed.startsWith('{') ? file : QByteArray();
}

/// glTF primitive mode 2.
constexpr double kGltfLineLoop = 2;

/// assimp 5.2's glTF 2 reader dereferences a null pointer (SIGSEGV) for a LINE_LOOP primitive
/// without positions, and for one whose vertex data are damaged: LINE_LOOP primitives are
/// rejected (the surface reader drops lines anyway). A primitive without a POSITION
/// attribute has nothing to read either: reject every glTF file (text or binary, whatever
/// its extension, since assimp recognises glTF by content too) that has one. The JSON must
/// be valid: assimp's parser takes invalid UTF-8 that Qt's refuses, so a key "POSITI\xcfN"
/// would otherwise hide a primitive without positions from this check.
Status checkGltfPrimitives(const std::string& path) {
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly))
        return Status::success(); // assimp reports it
    const QByteArray head = file.peek(64);
    if (!head.startsWith("glTF") && !head.trimmed().startsWith('{'))
        return Status::success();
    const QByteArray json = gltfJson(file.readAll());
    if (json.isEmpty())
        return Status::success(); // no JSON chunk: assimp reports the damage
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        return Status::error(path + ": not valid glTF JSON (" + error.errorString().toStdString() +
                             " at offset " + std::to_string(error.offset) + ")");
    if (!doc.isObject())
        return Status::success(); // not glTF: assimp decides
    const QJsonArray meshes = doc.object().value("meshes").toArray();
    const QJsonArray accessors = doc.object().value("accessors").toArray();
    for (qsizetype m = 0; m < meshes.size(); ++m) {
        const QJsonArray primitives = meshes[m].toObject().value("primitives").toArray();
        for (qsizetype p = 0; p < primitives.size(); ++p) {
            const QJsonObject primitive = primitives[p].toObject();
            const std::string at =
                "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
            if (!primitive.value("attributes").toObject().contains("POSITION"))
                return Status::error(path + ": glTF " + at + " has no POSITION attribute");
            // Strips and fans need 3 vertices (line strips 2): assimp computes its face
            // count as count - 2 unchecked (an accessor count of 0 made it allocate 64 GB).
            const double mode = primitive.value("mode").toDouble(4);
            const QJsonValue used =
                primitive.contains("indices")
                    ? primitive.value("indices")
                    : primitive.value("attributes").toObject().value("POSITION");
            const double index = used.toDouble(-1);
            const double count = index >= 0 && index < static_cast<double>(accessors.size())
                                     ? accessors.at(static_cast<qsizetype>(index))
                                           .toObject()
                                           .value("count")
                                           .toDouble(0)
                                     : 0;
            if ((mode == 5 || mode == 6) && count < 3)
                return Status::error(path + ": glTF " + at +
                                     " is a triangle strip or fan of fewer than 3 vertices");
            if (mode == 3 && count < 2)
                return Status::error(path + ": glTF " + at +
                                     " is a line strip of fewer than 2 vertices");
            if (primitive.value("mode").toDouble(-1) == kGltfLineLoop)
                return Status::error(path + ": glTF " + at +
                                     " is a LINE_LOOP (mode 2), which is not read: only "
                                     "triangles are, and assimp 5.2 crashes on damaged loops");
        }
    }
    return Status::success();
}

} // namespace

Status checkAssimpInput(const std::string& path) {
    if (Status s = checkPly(path); !s)
        return s;
    if (Status s = checkOffCounts(path); !s)
        return s;
    return checkGltfPrimitives(path);
}

} // namespace resect::detail
