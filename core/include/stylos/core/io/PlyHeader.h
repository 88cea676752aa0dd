#pragma once
/** @file
 * @brief The header of a PLY file: encoding, elements with their properties (scalar or list, every
 *        PLY scalar type), comments. Parsing is strict: an unknown keyword, type or encoding, a missing
 *        end_header or a vertex element without x y z is refused with the line number.
 */
#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::io {

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyEncoding : std::uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

/** Bytes of one value of @p type. */
std::size_t plyTypeSize(PlyType type);
/** "float", "float32", "uchar", "uint8"... → type; nullopt for an unknown name. */
std::optional<PlyType> plyTypeFromName(std::string_view name);
/** The canonical PLY 1.0 name ("float", "uchar"...). */
const char* plyTypeName(PlyType type);

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;      ///< value type (of each item for a list)
    bool isList = false;
    PlyType countType = PlyType::UInt8;   ///< type of the item count of a list
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    bool hasLists() const;
    /** Bytes per record in a binary file; only meaningful without list properties. */
    std::size_t recordBytes() const;
    /** Index of the property named @p name, or -1. */
    int find(std::string_view name) const;
};

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    std::vector<std::string> comments;
    std::uint64_t dataOffset = 0;   ///< byte offset of the first data byte
    std::uint64_t headerLines = 0;  ///< lines up to and including end_header
    int vertexElement = -1;         ///< index in elements of "vertex"

    /**
     * @brief Parses the header from the start of @p file, leaving the file at the first data byte.
     * @param fileName used in error messages.
     */
    static Result<PlyHeader> parse(BufferedFile& file, const std::string& fileName);
};

} // namespace stylos::core::io
