#include "scenario/vtk_xml_guard.h"

#include "scenario/mesh_io_detail.h"

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

namespace resect::detail {
namespace {

/// No compressor VTK writes with shrinks real point or cell data by more than 1024:1
/// (zlib's limit is about 1032:1 on constant data; actual meshes compress by less than
/// 10:1), so a Piece declaring more than kMaxItemsPerFileByte values per byte of file
/// cannot be backed by its data and is rejected before VTK allocates for it.
constexpr std::uint64_t kMaxItemsPerFileByte = 1024;

/// VTK decompresses block by block into a buffer of the block size (32 KiB by default);
/// larger blocks than this are taken as damage, not as a writer's choice.
constexpr std::uint64_t kMaxBlockBytes = std::uint64_t(1) << 30;

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// Value of attribute `name` in the text of one XML start tag; false if absent.
bool attribute(std::string_view tag, std::string_view name, std::string_view& value) {
    for (std::size_t at = tag.find(name); at != std::string_view::npos;
         at = tag.find(name, at + 1)) {
        if (at == 0 || !isSpace(tag[at - 1]))
            continue;
        std::size_t i = at + name.size();
        while (i < tag.size() && isSpace(tag[i]))
            ++i;
        if (i >= tag.size() || tag[i] != '=')
            continue;
        ++i;
        while (i < tag.size() && isSpace(tag[i]))
            ++i;
        if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\''))
            continue;
        const char quote = tag[i++];
        const std::size_t end = tag.find(quote, i);
        if (end == std::string_view::npos)
            return false;
        value = tag.substr(i, end - i);
        return true;
    }
    return false;
}

/// Parses an unsigned decimal attribute the way VTK does (std::istream >>): leading blanks,
/// an optional '+', then the digits up to the first other character, so "4.9" is 4 (a
/// stricter parse let a damaged offset="4.9" past the checks below while VTK read offset 4).
/// False if absent or without digits (VTK then fails to read it); beyond 19 digits the value
/// saturates.
bool unsignedAttribute(std::string_view tag, std::string_view name, std::uint64_t& value) {
    std::string_view text;
    if (!attribute(tag, name, text))
        return false;
    while (!text.empty() && isSpace(text.front()))
        text.remove_prefix(1);
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    std::size_t digits = 0;
    value = 0;
    for (; digits < text.size() && text[digits] >= '0' && text[digits] <= '9'; ++digits)
        value =
            digits >= 19 ? UINT64_MAX : value * 10 + static_cast<std::uint64_t>(text[digits] - '0');
    return digits > 0;
}

/// The start tags `<name ...>` in `xml`, each without the angle brackets, with the offset
/// just past its '>'.
struct StartTag {
    std::string_view text;
    std::size_t end;
};
std::vector<StartTag> startTags(std::string_view xml, std::string_view name) {
    std::vector<StartTag> tags;
    std::string open(1, '<'); // (not "<" + std::string(name): GCC 12 warns -Wrestrict on it)
    open += name;
    for (std::size_t at = xml.find(open); at != std::string_view::npos;
         at = xml.find(open, at + 1)) {
        const std::size_t after = at + open.size();
        if (after < xml.size() && !isSpace(xml[after]) && xml[after] != '>' && xml[after] != '/')
            continue; // a longer name with the same prefix
        const std::size_t close = xml.find('>', after);
        if (close == std::string_view::npos)
            break;
        tags.push_back({xml.substr(after, close - after), close + 1});
    }
    return tags;
}

int base64Value(char c) {
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    if (c == '+')
        return 62;
    if (c == '/')
        return 63;
    return -1;
}

/// Where a binary DataArray's bytes start and how they are stored.
struct BinarySource {
    std::string_view file;
    std::size_t start = 0;
    bool base64 = false;

    /// Bytes of the decoded stream that remain from `start` (an upper bound).
    std::uint64_t available() const {
        const std::uint64_t left = start < file.size() ? file.size() - start : 0;
        return base64 ? left / 4 * 3 : left;
    }

    /// The first `count` bytes of the decoded stream; false if the file ends first or the
    /// base64 text is invalid (VTK then fails to read it too, safely).
    bool read(std::size_t count, std::vector<unsigned char>& out) const {
        out.clear();
        if (!base64) {
            if (start > file.size() || file.size() - start < count)
                return false;
            out.assign(file.begin() + static_cast<std::ptrdiff_t>(start),
                       file.begin() + static_cast<std::ptrdiff_t>(start + count));
            return true;
        }
        const std::size_t chars = (count + 2) / 3 * 4;
        if (start > file.size() || file.size() - start < chars)
            return false;
        for (std::size_t i = 0; i < chars && out.size() < count; i += 4) {
            int v[4];
            int valid = 0;
            for (int k = 0; k < 4; ++k) {
                const char c = file[start + i + k];
                v[k] = c == '=' ? 0 : base64Value(c);
                if (v[k] < 0)
                    return false;
                if (c != '=')
                    ++valid;
            }
            const unsigned triple = (unsigned(v[0]) << 18) | (unsigned(v[1]) << 12) |
                                    (unsigned(v[2]) << 6) | unsigned(v[3]);
            const unsigned char bytes[3] = {static_cast<unsigned char>(triple >> 16),
                                            static_cast<unsigned char>(triple >> 8),
                                            static_cast<unsigned char>(triple)};
            for (int k = 0; k < valid - 1 && out.size() < count; ++k)
                out.push_back(bytes[k]);
        }
        return out.size() == count;
    }
};

/// Word `i` of a header of `wordSize`-byte unsigned integers.
std::uint64_t headerWord(const std::vector<unsigned char>& bytes, std::size_t i, int wordSize,
                         bool bigEndian) {
    std::uint64_t v = 0;
    for (int k = 0; k < wordSize; ++k) {
        const int byte = bigEndian ? k : wordSize - 1 - k;
        v = (v << 8) | bytes[i * wordSize + static_cast<std::size_t>(byte)];
    }
    return v;
}

/// Checks one compressed array's header: [blocks][blockSize][lastBlockSize][sizes...].
/// Returns an empty string if it is consistent (or unreadable, which VTK reports itself).
std::string checkCompressionHeader(const BinarySource& src, int wordSize, bool bigEndian) {
    std::vector<unsigned char> bytes;
    if (!src.read(3 * static_cast<std::size_t>(wordSize), bytes))
        return {};
    const std::uint64_t blocks = headerWord(bytes, 0, wordSize, bigEndian);
    const std::uint64_t blockSize = headerWord(bytes, 1, wordSize, bigEndian);
    const std::uint64_t lastSize = headerWord(bytes, 2, wordSize, bigEndian);
    const std::uint64_t available = src.available();
    if (blocks > available / static_cast<std::uint64_t>(wordSize))
        return "declares " + std::to_string(blocks) + " compressed blocks";
    if (blocks == 0)
        return lastSize == 0 ? std::string() : "has a partial block but no blocks";
    if (blockSize == 0 || blockSize > kMaxBlockBytes)
        return "has a block size of " + std::to_string(blockSize);
    if (lastSize > blockSize)
        return "has a last block larger than its block size";
    if (!src.read((3 + static_cast<std::size_t>(blocks)) * static_cast<std::size_t>(wordSize),
                  bytes))
        return {};
    std::uint64_t total = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
        const std::uint64_t size = headerWord(bytes, 3 + b, wordSize, bigEndian);
        if (size > available || total + size > available)
            return "declares more compressed data than the file holds";
        total += size;
    }
    return {};
}

} // namespace

Status checkVtkXmlFile(const std::string& path) {
    std::string text;
    if (Status s = readWholeFile(path, text); !s)
        return s;
    if (text.empty())
        return Status::error(path + ": empty file");
    const std::string_view file(text);
    const std::uint64_t limit = static_cast<std::uint64_t>(file.size()) * kMaxItemsPerFileByte;

    // The XML part ends where appended binary data begin ('_' after <AppendedData ...>).
    std::string_view xml = file;
    std::size_t appendedStart = std::string_view::npos;
    bool appendedBase64 = false;
    if (const auto appended = startTags(file, "AppendedData"); !appended.empty()) {
        xml = file.substr(0, appended.front().end);
        std::string_view encoding;
        appendedBase64 =
            attribute(appended.front().text, "encoding", encoding) && encoding == "base64";
        const std::size_t underscore = file.find('_', appended.front().end);
        if (underscore != std::string_view::npos)
            appendedStart = underscore + 1;
    }

    // Declared sizes: VTK allocates Piece-sized arrays before reading them.
    std::uint64_t largestPiece = 0;
    for (const StartTag& piece : startTags(xml, "Piece")) {
        for (const char* name : {"NumberOfPoints", "NumberOfCells"}) {
            std::string_view raw;
            if (!attribute(piece.text, name, raw))
                continue;
            std::uint64_t declared = 0;
            if (!unsignedAttribute(piece.text, name, declared))
                continue; // not a number: VTK reports it
            if (declared > static_cast<std::uint64_t>(kMaxMeshItems) || declared > limit)
                return Status::error(path + ": declares " + name + "=\"" + std::string(raw) +
                                     "\", more than a file of " + std::to_string(file.size()) +
                                     " bytes can hold");
            largestPiece = std::max(largestPiece, declared);
        }
    }

    std::string_view fileTag;
    if (const auto root = startTags(xml, "VTKFile"); !root.empty())
        fileTag = root.front().text;
    std::string_view compressor, headerType, byteOrder;
    const bool compressed = attribute(fileTag, "compressor", compressor) && !compressor.empty();
    const int wordSize =
        attribute(fileTag, "header_type", headerType) && headerType == "UInt64" ? 8 : 4;
    const bool bigEndian = attribute(fileTag, "byte_order", byteOrder) && byteOrder == "BigEndian";

    for (const StartTag& array : startTags(xml, "DataArray")) {
        std::string_view name = "(unnamed)";
        attribute(array.text, "Name", name);
        std::uint64_t components = 1, tuples = 0;
        unsignedAttribute(array.text, "NumberOfComponents", components);
        const bool hasTuples = unsignedAttribute(array.text, "NumberOfTuples", tuples);
        if ((components > 0 && largestPiece > limit / components) ||
            (hasTuples && components > 0 && tuples > limit / components))
            return Status::error(path + ": array '" + std::string(name) +
                                 "' declares more values than a file of " +
                                 std::to_string(file.size()) + " bytes can hold");
        if (!compressed)
            continue; // VTK bounds uncompressed reads by the size stored with the data

        std::string_view format;
        attribute(array.text, "format", format);
        BinarySource src{file, 0, true};
        // VTK reads appended data wherever an array has an offset attribute, whatever its
        // format says (a damaged format="..." hid an appended array from this check:
        // tests/fuzz_regressions/vtu/huge-block-size-array-without-format.vtu).
        std::string_view offsetText;
        if (format == "appended" || attribute(array.text, "offset", offsetText)) {
            std::uint64_t offset = 0;
            if (appendedStart == std::string_view::npos ||
                !unsignedAttribute(array.text, "offset", offset))
                continue; // VTK reports the missing data
            if (offset > file.size() - appendedStart)
                continue; // seeking past the end fails safely in VTK
            src.start = appendedStart + static_cast<std::size_t>(offset);
            src.base64 = appendedBase64;
        } else if (format == "binary") {
            std::size_t i = array.end;
            while (i < file.size() && isSpace(file[i]))
                ++i;
            src.start = i;
        } else {
            continue; // ascii
        }
        if (const std::string bad = checkCompressionHeader(src, wordSize, bigEndian); !bad.empty())
            return Status::error(path + ": damaged compressed data: array '" + std::string(name) +
                                 "' " + bad);
    }
    return Status::success();
}

} // namespace resect::detail
