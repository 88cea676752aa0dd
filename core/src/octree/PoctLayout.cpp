#include "PoctLayout.h"

#include "stylos/core/util/Hash64.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <set>

static_assert(std::endian::native == std::endian::little, "the .poct code assumes a little-endian host");

namespace stylos::core::octree::poct {

namespace {

template <typename T>
T get(const std::uint8_t* p)
{
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template <typename T>
void put(std::uint8_t* p, T v)
{
    std::memcpy(p, &v, sizeof v);
}

std::string byteAt(std::uint64_t offset)
{
    return "byte " + std::to_string(offset);
}

/** The section table entry at @p p, or why it cannot be read. */
SectionEntry readEntry(const std::uint8_t* p)
{
    SectionEntry e;
    const char* name = reinterpret_cast<const char*>(p);
    e.name.assign(name, strnlen(name, 16));
    e.kind = static_cast<SectionKind>(p[16]);
    e.type = static_cast<AttributeType>(p[17]);
    e.components = p[18];
    e.offset = get<std::uint64_t>(p + 24);
    e.length = get<std::uint64_t>(p + 32);
    e.checksum = get<std::uint64_t>(p + 40);
    return e;
}

/** Empty when the entry's name field and reserved bytes are canonical (NUL-padded, zero). */
bool entryPaddingIsZero(const std::uint8_t* p, std::size_t nameLength)
{
    for (std::size_t i = nameLength; i < 16; ++i)
        if (p[i] != 0) return false;
    for (std::size_t i = 19; i < 24; ++i)
        if (p[i] != 0) return false;
    return true;
}

} // namespace

std::size_t elementSize(AttributeType type)
{
    switch (type) {
    case AttributeType::UInt8: return 1;
    case AttributeType::UInt16: return 2;
    case AttributeType::Float32: return 4;
    }
    return 0;
}

std::uint64_t alignUp(std::uint64_t offset)
{
    return (offset + SectionAlignment - 1) / SectionAlignment * SectionAlignment;
}

std::uint64_t headerBytes(int depth, std::size_t sections)
{
    return FixedHeaderBytes + 8 * (static_cast<std::uint64_t>(depth) + 1) + SectionEntryBytes * sections +
           ChecksumBytes;
}

std::string layerNameProblem(const std::string& name)
{
    if (name.empty()) return "an attribute layer name cannot be empty";
    if (name.size() > MaxNameLength)
        return "attribute layer name \"" + name + "\" is longer than " + std::to_string(MaxNameLength) + " characters";
    for (char c : name) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                        c == '-' || c == '.';
        if (!ok) return "attribute layer name \"" + name + "\" may hold only ASCII letters, digits, '_', '-' and '.'";
    }
    if (name == "masks" || name == "normals") return "attribute layer name \"" + name + "\" is reserved for the cells";
    return {};
}

Header planHeader(const OctreeDescription& description, std::span<const SectionEntry> layers)
{
    Header h;
    h.box = description.box;
    h.depth = description.depth;
    h.normalCode = description.normalCode;
    h.points = description.points;
    h.cellsPerLevel = description.cellsPerLevel;
    std::uint64_t inner = 0, all = 0;
    for (std::size_t l = 0; l < h.cellsPerLevel.size(); ++l) {
        all += h.cellsPerLevel[l];
        if (static_cast<int>(l) < h.depth) inner += h.cellsPerLevel[l];
    }
    const std::uint64_t leaves = h.cellsPerLevel.back();
    h.sections.push_back({"masks", SectionKind::Masks, AttributeType::UInt8, 1, 0, inner, 0});
    h.sections.push_back({"normals", SectionKind::Normals, AttributeType::UInt16, 1, 0, 2 * all, 0});
    for (const SectionEntry& layer : layers) {
        SectionEntry e = layer;
        e.kind = SectionKind::Attribute;
        e.length = leaves * e.components * elementSize(e.type);
        h.sections.push_back(e);
    }
    std::uint64_t at = headerBytes(h.depth, h.sections.size());
    for (SectionEntry& e : h.sections) {
        e.offset = alignUp(at);
        at = e.offset + e.length;
    }
    return h;
}

std::uint64_t fileBytes(const Header& header)
{
    const SectionEntry& last = header.sections.back();
    return last.offset + last.length;
}

std::vector<std::uint8_t> serialiseHeader(const Header& h)
{
    std::vector<std::uint8_t> out(headerBytes(h.depth, h.sections.size()), 0);
    std::uint8_t* p = out.data();
    std::memcpy(p, Magic.data(), Magic.size());
    put<std::uint32_t>(p + field::Version, Version);
    put<std::uint32_t>(p + field::HeaderBytes, static_cast<std::uint32_t>(out.size()));
    for (int a = 0; a < 3; ++a) put<double>(p + field::Origin + 8 * a, h.box.origin[a]);
    put<double>(p + field::Size, h.box.size);
    put<std::uint64_t>(p + field::Points, h.points);
    p[field::Depth] = static_cast<std::uint8_t>(h.depth);
    p[field::NormalCode] = static_cast<std::uint8_t>(h.normalCode);
    put<std::uint32_t>(p + field::SectionCount, static_cast<std::uint32_t>(h.sections.size()));
    std::uint8_t* q = p + FixedHeaderBytes;
    for (std::uint64_t c : h.cellsPerLevel) {
        put<std::uint64_t>(q, c);
        q += 8;
    }
    for (const SectionEntry& e : h.sections) {
        std::memcpy(q, e.name.data(), std::min<std::size_t>(e.name.size(), MaxNameLength));
        q[16] = static_cast<std::uint8_t>(e.kind);
        q[17] = static_cast<std::uint8_t>(e.type);
        q[18] = e.components;
        put<std::uint64_t>(q + 24, e.offset);
        put<std::uint64_t>(q + 32, e.length);
        put<std::uint64_t>(q + 40, e.checksum);
        q += SectionEntryBytes;
    }
    put<std::uint64_t>(q, xxh64(p, out.size() - ChecksumBytes));
    return out;
}

Result<Header> parseHeader(std::span<const std::uint8_t> bytes, const std::string& file)
{
    const std::uint64_t size = bytes.size();
    const std::uint8_t* p = bytes.data();
    auto error = [&](ErrorCode code, const std::string& position, const std::string& problem) {
        return Error::at(code, file, position, problem);
    };
    if (size == 0) return error(ErrorCode::Empty, "", "empty file");
    if (std::memcmp(p, Magic.data(), std::min<std::size_t>(size, Magic.size())) != 0)
        return error(ErrorCode::UnknownFormat, "byte 0", "not a packed octree (.poct) file: bad magic");
    if (size < FixedHeaderBytes)
        return error(ErrorCode::Truncated, byteAt(size),
                     "file ends inside the " + std::to_string(FixedHeaderBytes) + "-byte header");
    const auto version = get<std::uint32_t>(p + field::Version);
    if (version == 0) return error(ErrorCode::Malformed, byteAt(field::Version), "version 0 is not a valid version");
    if (version > Version)
        return error(ErrorCode::Unsupported, byteAt(field::Version),
                     "version " + std::to_string(version) + " is newer than this program reads (version " +
                         std::to_string(Version) + ")");
    const int depth = p[field::Depth];
    if (depth < MinOctreeDepth || depth > MaxOctreeDepth)
        return error(ErrorCode::Malformed, byteAt(field::Depth), "depth " + std::to_string(depth) + " out of range");
    const auto sectionCount = get<std::uint32_t>(p + field::SectionCount);
    if (sectionCount < 2 || sectionCount > 2 + MaxLayers)
        return error(ErrorCode::Malformed, byteAt(field::SectionCount),
                     "section count " + std::to_string(sectionCount) + " out of range");
    const auto declaredHeader = get<std::uint32_t>(p + field::HeaderBytes);
    const std::uint64_t expectedHeader = headerBytes(depth, sectionCount);
    if (declaredHeader != expectedHeader)
        return error(ErrorCode::Malformed, byteAt(field::HeaderBytes),
                     "header size " + std::to_string(declaredHeader) + " does not match depth and section count (" +
                         std::to_string(expectedHeader) + ")");
    if (size < expectedHeader)
        return error(ErrorCode::Truncated, byteAt(size),
                     "file ends inside the " + std::to_string(expectedHeader) + "-byte header");
    const std::uint64_t stored = get<std::uint64_t>(p + expectedHeader - ChecksumBytes);
    if (xxh64(p, expectedHeader - ChecksumBytes) != stored)
        return error(ErrorCode::Malformed, byteAt(expectedHeader - ChecksumBytes),
                     "header checksum mismatch: the header or section table is corrupted");

    // From here on the header is what the writer wrote; what follows checks the writer's rules.
    Header h;
    h.depth = depth;
    const std::uint8_t code = p[field::NormalCode];
    if (code > static_cast<std::uint8_t>(NormalCodeKind::Octahedral16))
        return error(ErrorCode::Unsupported, byteAt(field::NormalCode), "unknown normal code " + std::to_string(code));
    h.normalCode = static_cast<NormalCodeKind>(code);
    if (get<std::uint16_t>(p + field::Reserved) != 0)
        return error(ErrorCode::Malformed, byteAt(field::Reserved), "reserved bytes are not zero");
    for (int a = 0; a < 3; ++a) h.box.origin[a] = get<double>(p + field::Origin + 8 * a);
    h.box.size = get<double>(p + field::Size);
    if (!std::isfinite(h.box.origin[0]) || !std::isfinite(h.box.origin[1]) || !std::isfinite(h.box.origin[2]) ||
        !std::isfinite(h.box.size) || !(h.box.size > 0))
        return error(ErrorCode::Malformed, byteAt(field::Origin), "root box is not finite with a positive size");
    h.points = get<std::uint64_t>(p + field::Points);

    std::uint64_t inner = 0, all = 0;
    for (int l = 0; l <= depth; ++l) {
        const std::uint64_t at = FixedHeaderBytes + 8 * static_cast<std::uint64_t>(l);
        const auto c = get<std::uint64_t>(p + at);
        const std::uint64_t parent = l == 0 ? 1 : h.cellsPerLevel.back();
        if ((l == 0 && c != 1) || c == 0 || c > 8 * parent || c > MaxCellsPerLevel)
            return error(ErrorCode::Malformed, byteAt(at),
                         "level " + std::to_string(l) + " cannot have " + std::to_string(c) + " cells");
        h.cellsPerLevel.push_back(c);
        all += c;
        if (l < depth) inner += c;
    }
    const std::uint64_t leaves = h.cellsPerLevel.back();

    std::set<std::string> names;
    std::uint64_t end = expectedHeader;
    for (std::uint32_t s = 0; s < sectionCount; ++s) {
        const std::uint64_t at = FixedHeaderBytes + 8 * (static_cast<std::uint64_t>(depth) + 1) + SectionEntryBytes * s;
        SectionEntry e = readEntry(p + at);
        const std::string which = "section " + std::to_string(s) + " (\"" + e.name + "\")";
        if (!entryPaddingIsZero(p + at, e.name.size()) || e.name.size() > MaxNameLength)
            return error(ErrorCode::Malformed, byteAt(at), which + ": reserved bytes are not zero");
        std::uint64_t expectedLength = 0;
        if (s == 0) {
            if (e.name != "masks" || e.kind != SectionKind::Masks || e.type != AttributeType::UInt8 ||
                e.components != 1)
                return error(ErrorCode::Malformed, byteAt(at), which + ": the first section must be the child masks");
            expectedLength = inner;
        } else if (s == 1) {
            if (e.name != "normals" || e.kind != SectionKind::Normals || e.type != AttributeType::UInt16 ||
                e.components != 1)
                return error(ErrorCode::Malformed, byteAt(at), which + ": the second section must be the normals");
            expectedLength = 2 * all;
        } else {
            if (e.kind != SectionKind::Attribute)
                return error(ErrorCode::Malformed, byteAt(at), which + ": unknown section kind");
            if (const std::string problem = layerNameProblem(e.name); !problem.empty())
                return error(ErrorCode::Malformed, byteAt(at), which + ": " + problem);
            if (!names.insert(e.name).second)
                return error(ErrorCode::Malformed, byteAt(at), which + ": duplicate attribute layer name");
            if (elementSize(e.type) == 0)
                return error(ErrorCode::Unsupported, byteAt(at),
                             which + ": unknown element type " + std::to_string(static_cast<int>(e.type)));
            if (e.components < 1 || e.components > MaxComponents)
                return error(ErrorCode::Malformed, byteAt(at),
                             which + ": " + std::to_string(e.components) + " components per leaf");
            if (e.name == "colour" && (e.type != AttributeType::UInt8 || e.components != 3))
                return error(ErrorCode::Malformed, byteAt(at), which + ": colour must be 3 × UInt8");
            expectedLength = leaves * e.components * elementSize(e.type);
        }
        if (e.length != expectedLength)
            return error(ErrorCode::Malformed, byteAt(at),
                         which + ": length " + std::to_string(e.length) + " instead of " +
                             std::to_string(expectedLength));
        if (e.offset != alignUp(end))
            return error(ErrorCode::Malformed, byteAt(at),
                         which + ": offset " + std::to_string(e.offset) + " instead of " +
                             std::to_string(alignUp(end)));
        end = e.offset + e.length;
        h.sections.push_back(std::move(e));
    }
    if (size < end)
        return error(ErrorCode::Truncated, byteAt(size),
                     "file is " + std::to_string(size) + " bytes but its sections end at byte " + std::to_string(end));
    if (size > end)
        return error(ErrorCode::Malformed, byteAt(end),
                     std::to_string(size - end) + " unexpected bytes after the last section");
    // Padding between the header and the sections, and between sections, must be zero.
    std::uint64_t gap = expectedHeader;
    for (const SectionEntry& e : h.sections) {
        for (std::uint64_t i = gap; i < e.offset; ++i)
            if (p[i] != 0)
                return error(ErrorCode::Malformed, byteAt(i), "padding before section \"" + e.name + "\" is not zero");
        gap = e.offset + e.length;
    }
    return h;
}

} // namespace stylos::core::octree::poct
