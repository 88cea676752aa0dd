#pragma once
/** @file
 * @brief The LAS 1.0–1.4 public header block and the layout of point data formats 0–10 (ASPRS LAS
 *        1.4 R15), as far as reading uncompressed points needs them. Pure functions over bytes: no I/O,
 *        thread-safe.
 *
 *        LasHeader::parse() validates everything that can be checked before the first point, so a
 *        reader that opened successfully never meets a malformed or short file while decoding
 *        (unless the file changes underneath it). Failures, each "FILE: byte N: problem":
 *        - Malformed: no "LASF" signature; header size field smaller than the version's header or
 *          overlapping the point data; record length shorter than the point format's; a scale factor
 *          NaN, infinite or zero; a coordinate offset NaN or infinite; 1.4 point counts that disagree.
 *        - Truncated: file shorter than its header; offset to point data beyond the end of the file;
 *          fewer bytes of point data than count × record length.
 *        - Unsupported: version other than 1.0–1.4; point data format above 10; LAZ (format byte with
 *          the compression bit 0x80 or 0x40 set).
 *        The point format is accepted whatever the version (a 1.2 file with format 6 is read): the
 *        record layouts are fixed, so there is no ambiguity.
 */
#include "stylos/core/util/Result.h"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace stylos::core::io {

/** @brief Loads a little-endian @p T (integer or IEEE double) from unaligned bytes, on any host. */
template <typename T>
inline T loadLittleEndian(const char* bytes)
{
    T value;
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(&value, bytes, sizeof(T));
    } else {
        char swapped[sizeof(T)];
        for (std::size_t i = 0; i < sizeof(T); ++i) swapped[i] = bytes[sizeof(T) - 1 - i];
        std::memcpy(&value, swapped, sizeof(T));
    }
    return value;
}

/** @brief The public header fields a reader needs; positions are in the file's world units. */
struct LasHeader {
    std::uint8_t versionMajor = 1;
    std::uint8_t versionMinor = 2;
    std::uint16_t headerSize = 0;        ///< bytes, at least 227 (1.0–1.2), 235 (1.3), 375 (1.4)
    std::uint32_t offsetToPointData = 0; ///< byte offset of the first point record (after the VLRs)
    std::uint32_t vlrCount = 0;          ///< variable length records, skipped by the reader
    std::uint8_t pointFormat = 0;        ///< 0–10
    std::uint16_t recordLength = 0;      ///< bytes per point record, ≥ the format's standard size
    std::uint64_t pointCount = 0;        ///< legacy 32-bit count, or the 1.4 64-bit count when that is 0
    std::array<double, 3> scale{};       ///< world = integer × scale + offset, per axis
    std::array<double, 3> offset{};
    /** {minx, miny, minz, maxx, maxy, maxz}; absent when not finite or min > max in the file. */
    std::optional<std::array<double, 6>> bounds;

    /** Smallest possible header for @p versionMinor (LAS 1.x): 227, 235 or 375 bytes. */
    static std::uint16_t minimumHeaderSize(unsigned versionMinor);

    /**
     * @brief Parses and validates the header.
     * @param bytes the first @p n bytes of the file (n ≥ 375, or the whole file when shorter).
     * @param fileSize the file's size in bytes, to check that the announced point data are there.
     * @param file the file name used in error messages.
     */
    static Result<LasHeader> parse(const char* bytes, std::size_t n, std::uint64_t fileSize,
                                   const std::string& file);

    /** "las-1.2" etc. */
    std::string formatName() const;
};

/** @brief Where the fixed fields sit in a point record of one format (byte offsets in the record). */
struct LasPointLayout {
    unsigned format = 0;
    std::uint16_t standardLength = 0; ///< 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 for 0–10
    bool extended = false;            ///< formats 6–10: 4-bit return numbers, 16-bit scan angle
    int gpsTime = -1;                 ///< offset of the GPS time (double), or -1
    int rgb = -1;                     ///< offset of red, green, blue (uint16 each), or -1
    int nir = -1;                     ///< offset of near infrared (uint16), or -1
    // Wave packet descriptors (formats 4, 5, 9, 10) are not decoded; extra bytes are (lasExtraBytesFields).

    /** The layout of @p format, or nothing for a format above 10. */
    static std::optional<LasPointLayout> forFormat(unsigned format);
};

/** @brief How one field of a point record becomes one double scalar column. */
struct LasScalarField {
    enum class Kind : std::uint8_t {
        U8,       ///< unsigned byte as is
        U16,      ///< unsigned 16-bit as is
        Bits,     ///< (byte >> shift) & mask
        Angle8,   ///< signed 8-bit scan angle rank, already in degrees (formats 0–5)
        Angle16,  ///< signed 16-bit scan angle in units of 0.006 degree (formats 6–10)
        F64,      ///< double as is (GPS time)
        // Extra bytes (LAS 1.4 data types 1–10), then × scale + offset:
        I8, I16, U32, I32, U64, I64, F32,
    };
    std::string name;
    Kind kind = Kind::U8;
    std::uint16_t offset = 0;
    std::uint8_t shift = 0;
    std::uint8_t mask = 0xFF;
    double scale = 1.0;  ///< extra bytes: value × scale + offset (1 and 0 unless the descriptor says)
    double add = 0.0;
};

/**
 * @brief The extra bytes of each point record that the Extra Bytes VLR (user "LASF_Spec", record 4) describes:
 *        @p descriptors is that VLR's payload (192 bytes a field), the fields laid out from @p firstOffset (the
 *        format's standard record length) in order. A field of a documented type (1–10: integers, float, double;
 *        one value, not the deprecated arrays) becomes a scalar column named as the descriptor names it, with its
 *        scale and offset applied when its options say so; an undocumented one (type 0, its byte count in the
 *        options) only moves the offset on. Fields past @p recordLength are left out.
 */
std::vector<LasScalarField> lasExtraBytesFields(const char* descriptors, std::size_t bytes, std::size_t firstOffset,
                                                std::size_t recordLength);

/**
 * @brief The scalar columns a LAS point of @p layout yields, in schema order: intensity,
 *        return_number, number_of_returns, classification (the 5-bit class for formats 0–5, the full
 *        byte for 6–10; flag bits are dropped), scan_angle (degrees), user_data, point_source_id, then
 *        gps_time and nir when the format has them.
 */
std::vector<LasScalarField> lasScalarFields(const LasPointLayout& layout);

} // namespace stylos::core::io
