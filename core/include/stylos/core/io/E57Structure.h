#pragma once
/** @file
 * @brief What an E57 file says about itself: the 48-byte file header (ASTM E2807 §8) and, from the
 *        XML section, every `/data3D` scan — name, guid, pose, the compressed vector of its points
 *        (section offset, record count, prototype fields in bytestream order) and the intensity and
 *        colour limits. Pure parsing, no I/O; thread-safe.
 */
#include "stylos/core/io/PointReader.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stylos::core::io {

/** @brief The file header, from the first 48 bytes (little-endian). */
struct E57FileHeader {
    static constexpr std::size_t Bytes = 48;
    std::uint32_t versionMajor = 0, versionMinor = 0;
    std::uint64_t physicalLength = 0;
    std::uint64_t xmlOffset = 0;      ///< physical
    std::uint64_t xmlLength = 0;      ///< logical bytes
    std::uint64_t pageSize = 0;

    /**
     * @brief Parses and checks the header against the file size: signature "ASTM-E57", major version 1,
     *        page size 1024, physical length equal to the file size (Truncated when the file is shorter),
     *        an XML section inside the file. Errors name @p file and the field.
     */
    static Result<E57FileHeader> parse(const char* bytes, std::uint64_t fileSize, const std::string& file);
};

/** @brief One field of a compressed vector's prototype, decoded with the bitpack codec. */
struct E57Field {
    enum class Type { Float, ScaledInteger, Integer };
    std::string name;                 ///< "cartesianX", "las:pointSourceId", "a/b" for nested structures
    Type type = Type::Float;
    bool singlePrecision = false;     ///< Float: 4 bytes, else 8
    std::int64_t minimum = 0, maximum = 0; ///< Integer, ScaledInteger: the raw integer range
    double scale = 1.0, offset = 0.0;      ///< ScaledInteger: value = raw × scale + offset
    double floatMinimum = 0, floatMaximum = 0; ///< Float: the stated range (±DBL_MAX when absent)

    /** Bits per record in the bytestream: 32/64 for Float, the width of maximum − minimum otherwise (0 when equal). */
    unsigned bits() const;
    /** The range of the decoded value (for normalising intensity and colour when limits are absent). */
    double valueMinimum() const;
    double valueMaximum() const;
};

/** @brief A scan (`/data3D/N`) and where its points are. */
struct E57Scan {
    ScanInfo info;                        ///< name, guid, declared records, pose
    std::uint64_t sectionOffset = 0;      ///< physical offset of the compressed vector's section header
    std::uint64_t recordCount = 0;
    std::vector<E57Field> fields;         ///< prototype fields, in bytestream order
    std::optional<std::array<double, 2>> intensityLimits;
    std::optional<std::array<double, 6>> colorLimits; ///< red min, max, green min, max, blue min, max

    /** Index of the field named @p name in fields, or -1. */
    int field(const std::string& name) const;
};

/**
 * @brief Parses the XML section (@p size bytes) into its scans. Errors (Malformed, naming @p file and
 *        @p position — "XML section at byte N" — and the element): XML that is not well formed, no
 *        e57Root, a scan without a CompressedVector `points`, a prototype field of another type than
 *        Float, ScaledInteger or Integer, a minimum above its maximum, a zero quaternion. A file with no
 *        scans gives an empty list (the reader reports it).
 */
Result<std::vector<E57Scan>> parseE57Xml(const char* xml, std::size_t size, const std::string& file,
                                         const std::string& position);

} // namespace stylos::core::io
