#pragma once
// Internal: the byte layout of a `.poct` file (docs/file-format.md), shared by the writer and the
// reader. Everything little-endian. The header is parsed and checked here (structure, sizes, header
// checksum); section checksums and child masks are checked by the reader.
#include "stylos/core/octree/OctreeLevels.h"
#include "stylos/core/octree/PoctWriter.h"
#include "stylos/core/util/Result.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace stylos::core::octree::poct {

inline constexpr std::array<std::uint8_t, 8> Magic{0x89, 'P', 'O', 'C', 'T', '\r', '\n', 0x1A};
inline constexpr std::uint32_t Version = PoctFormatVersion;
inline constexpr std::size_t FixedHeaderBytes = 64;  ///< up to the cells-per-level table
inline constexpr std::size_t SectionEntryBytes = 48;
inline constexpr std::size_t ChecksumBytes = 8;      ///< header checksum at the end of the header
inline constexpr std::uint64_t SectionAlignment = 64;
inline constexpr std::size_t MaxLayers = 32;
inline constexpr std::size_t MaxNameLength = 15;
inline constexpr std::uint8_t MaxComponents = 16;
inline constexpr std::uint64_t MaxCellsPerLevel = std::uint64_t(1) << 48;

/** Field offsets in the fixed header. */
namespace field {
inline constexpr std::size_t Version = 8, HeaderBytes = 12, Origin = 16, Size = 40, Points = 48, Depth = 56,
                             NormalCode = 57, Reserved = 58, SectionCount = 60;
}

enum class SectionKind : std::uint8_t { Masks = 1, Normals = 2, Attribute = 3 };

struct SectionEntry {
    std::string name;
    SectionKind kind = SectionKind::Attribute;
    AttributeType type = AttributeType::UInt8;
    std::uint8_t components = 1;
    std::uint64_t offset = 0;
    std::uint64_t length = 0;
    std::uint64_t checksum = 0;
};

/** Everything the header holds. */
struct Header {
    RootBox box;
    int depth = 0;
    NormalCodeKind normalCode = NormalCodeKind::Octahedral16;
    std::uint64_t points = 0;
    std::vector<std::uint64_t> cellsPerLevel;
    std::vector<SectionEntry> sections;    ///< masks, normals, then the attribute layers
};

/** Bytes of one element of @p type (0 for an unknown type). */
std::size_t elementSize(AttributeType type);
std::uint64_t alignUp(std::uint64_t offset);
/** Header bytes of a file with @p depth and @p sections sections (checksum included). */
std::uint64_t headerBytes(int depth, std::size_t sections);

/** Empty when @p name is a valid layer name (ASCII letters, digits, '_', '-', '.', 1..15), else why not. */
std::string layerNameProblem(const std::string& name);

/**
 * The header of an octree: sections masks, normals, then one per layer (name, type, components
 * given), lengths from the cell counts, offsets packed 64-byte aligned after the header; checksums 0.
 */
Header planHeader(const OctreeDescription& description,
                  std::span<const SectionEntry> layers);

/** The header's bytes (headerBytes() of them), its checksum included. */
std::vector<std::uint8_t> serialiseHeader(const Header& header);

/** Size of the whole file the header describes (end of its last section). */
std::uint64_t fileBytes(const Header& header);

/**
 * Parses and checks the header of the file image @p bytes (the whole file): magic, version, sizes,
 * header checksum, cell counts, the section table and that the file is exactly as long as its sections
 * (padding must be zero). Errors name @p file: Empty, UnknownFormat, Unsupported, Truncated, Malformed.
 */
Result<Header> parseHeader(std::span<const std::uint8_t> bytes, const std::string& file);

} // namespace stylos::core::octree::poct
