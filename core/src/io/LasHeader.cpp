#include "stylos/core/io/LasHeader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

namespace stylos::core::io {

namespace {

// Byte offsets in the public header block (LAS 1.4 R15, table 3; the same for 1.0–1.3 up to 227).
constexpr std::size_t kVersionMajor = 24;
constexpr std::size_t kHeaderSize = 94;
constexpr std::size_t kOffsetToPointData = 96;
constexpr std::size_t kVlrCount = 100;
constexpr std::size_t kPointFormat = 104;
constexpr std::size_t kRecordLength = 105;
constexpr std::size_t kLegacyPointCount = 107;
constexpr std::size_t kScale = 131;
constexpr std::size_t kOffset = 155;
constexpr std::size_t kMaxX = 179; // then minX, maxY, minY, maxZ, minZ
constexpr std::size_t kPointCount64 = 247; // LAS 1.4 only

std::string at(std::size_t byte) { return "byte " + std::to_string(byte); }

std::string formatDouble(double v)
{
    if (std::isnan(v)) return "NaN";
    if (std::isinf(v)) return v > 0 ? "+infinity" : "-infinity";
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

} // namespace

std::uint16_t LasHeader::minimumHeaderSize(unsigned versionMinor)
{
    if (versionMinor >= 4) return 375;
    if (versionMinor == 3) return 235;
    return 227;
}

std::string LasHeader::formatName() const
{
    return "las-" + std::to_string(versionMajor) + "." + std::to_string(versionMinor);
}

Result<LasHeader> LasHeader::parse(const char* bytes, std::size_t n, std::uint64_t fileSize,
                                   const std::string& file)
{
    auto error = [&](ErrorCode code, std::size_t byte, const std::string& problem) {
        return Error::at(code, file, at(byte), problem);
    };
    const std::size_t have = static_cast<std::size_t>(std::min<std::uint64_t>(n, fileSize));
    if (have < 4 || std::memcmp(bytes, "LASF", 4) != 0)
        return error(ErrorCode::Malformed, 0, "not a LAS file: it does not start with the signature \"LASF\"");
    if (have < 227)
        return error(ErrorCode::Truncated, have,
                     "the file ends after " + std::to_string(have) +
                         " bytes, inside the LAS public header (at least 227 bytes)");

    LasHeader h;
    h.versionMajor = static_cast<std::uint8_t>(bytes[kVersionMajor]);
    h.versionMinor = static_cast<std::uint8_t>(bytes[kVersionMajor + 1]);
    if (h.versionMajor != 1 || h.versionMinor > 4)
        return error(ErrorCode::Unsupported, kVersionMajor,
                     "LAS version " + std::to_string(h.versionMajor) + "." + std::to_string(h.versionMinor) +
                         " is not supported (Stylos reads LAS 1.0 to 1.4)");
    const std::uint16_t minimum = minimumHeaderSize(h.versionMinor);
    if (have < minimum)
        return error(ErrorCode::Truncated, have,
                     "the file ends after " + std::to_string(have) + " bytes, inside the LAS " +
                         std::to_string(h.versionMajor) + "." + std::to_string(h.versionMinor) + " header (" +
                         std::to_string(minimum) + " bytes)");

    h.headerSize = loadLittleEndian<std::uint16_t>(bytes + kHeaderSize);
    h.offsetToPointData = loadLittleEndian<std::uint32_t>(bytes + kOffsetToPointData);
    h.vlrCount = loadLittleEndian<std::uint32_t>(bytes + kVlrCount);
    const auto formatByte = static_cast<std::uint8_t>(bytes[kPointFormat]);
    h.recordLength = loadLittleEndian<std::uint16_t>(bytes + kRecordLength);

    if (h.headerSize < minimum)
        return error(ErrorCode::Malformed, kHeaderSize,
                     "header size " + std::to_string(h.headerSize) + " is impossible: a LAS 1." +
                         std::to_string(h.versionMinor) + " header has at least " + std::to_string(minimum) +
                         " bytes");
    if (h.offsetToPointData > fileSize)
        return error(ErrorCode::Truncated, kOffsetToPointData,
                     "the offset to point data (" + std::to_string(h.offsetToPointData) +
                         ") is beyond the end of the file (" + std::to_string(fileSize) + " bytes)");
    if (h.headerSize > h.offsetToPointData)
        return error(ErrorCode::Malformed, kHeaderSize,
                     "header size " + std::to_string(h.headerSize) + " overlaps the point data, which start at byte " +
                         std::to_string(h.offsetToPointData));

    if (formatByte & 0xC0)
        return error(ErrorCode::Unsupported, kPointFormat,
                     "this is a LAZ (compressed LAS) file: point format byte " + std::to_string(formatByte) +
                         " has the compression bit set; decompress it first, e.g. `laszip -i IN.laz -o OUT.las`");
    const auto layout = LasPointLayout::forFormat(formatByte);
    if (!layout)
        return error(ErrorCode::Unsupported, kPointFormat,
                     "point data format " + std::to_string(formatByte) +
                         " is not supported (LAS defines formats 0 to 10)");
    h.pointFormat = formatByte;
    if (h.recordLength < layout->standardLength)
        return error(ErrorCode::Malformed, kRecordLength,
                     "point record length " + std::to_string(h.recordLength) + " is shorter than the " +
                         std::to_string(layout->standardLength) + " bytes of point format " +
                         std::to_string(formatByte));

    h.pointCount = loadLittleEndian<std::uint32_t>(bytes + kLegacyPointCount);
    if (h.versionMinor >= 4) {
        const auto count64 = loadLittleEndian<std::uint64_t>(bytes + kPointCount64);
        if (h.pointCount == 0) {
            h.pointCount = count64;
        } else if (count64 != 0 && count64 != h.pointCount) {
            return error(ErrorCode::Malformed, kPointCount64,
                         "the 64-bit point count " + std::to_string(count64) +
                             " disagrees with the legacy point count " + std::to_string(h.pointCount) +
                             " at byte " + std::to_string(kLegacyPointCount));
        }
    }

    static const char* const axes[3] = {"X", "Y", "Z"};
    for (std::size_t i = 0; i < 3; ++i) {
        h.scale[i] = loadLittleEndian<double>(bytes + kScale + 8 * i);
        h.offset[i] = loadLittleEndian<double>(bytes + kOffset + 8 * i);
        if (!std::isfinite(h.scale[i]) || h.scale[i] == 0.0)
            return error(ErrorCode::Malformed, kScale + 8 * i,
                         std::string(axes[i]) + " scale factor " + formatDouble(h.scale[i]) +
                             " is invalid (it must be finite and non-zero)");
        if (!std::isfinite(h.offset[i]))
            return error(ErrorCode::Malformed, kOffset + 8 * i,
                         std::string(axes[i]) + " offset " + formatDouble(h.offset[i]) + " is not finite");
    }

    // Stored as maxX, minX, maxY, minY, maxZ, minZ.
    std::array<double, 6> b{};
    bool boundsOk = true;
    for (std::size_t i = 0; i < 3; ++i) {
        b[3 + i] = loadLittleEndian<double>(bytes + kMaxX + 16 * i);
        b[i] = loadLittleEndian<double>(bytes + kMaxX + 16 * i + 8);
        boundsOk = boundsOk && std::isfinite(b[i]) && std::isfinite(b[3 + i]) && b[i] <= b[3 + i];
    }
    if (boundsOk) h.bounds = b;

    // Sizes are fixed, so a short file is detected here rather than in the middle of the data.
    const std::uint64_t available = fileSize - h.offsetToPointData;
    const std::uint64_t maxCount = available / h.recordLength;
    if (h.pointCount > maxCount) {
        std::string expected = std::to_string(h.pointCount) + " points × " + std::to_string(h.recordLength) +
                               " bytes";
        if (h.pointCount <= std::numeric_limits<std::uint64_t>::max() / h.recordLength)
            expected += " = " + std::to_string(h.pointCount * h.recordLength) + " bytes";
        return error(ErrorCode::Truncated, h.offsetToPointData,
                     "point data truncated: the header announces " + expected + " from here, but the file has only " +
                         std::to_string(available) + " bytes left (" + std::to_string(maxCount) +
                         " complete points)");
    }
    return h;
}

std::optional<LasPointLayout> LasPointLayout::forFormat(unsigned format)
{
    static constexpr std::uint16_t lengths[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
    if (format > 10) return std::nullopt;
    LasPointLayout l;
    l.format = format;
    l.standardLength = lengths[format];
    l.extended = format >= 6;
    if (!l.extended) {
        const bool hasGps = format == 1 || format == 3 || format == 4 || format == 5;
        if (hasGps) l.gpsTime = 20;
        if (format == 2) l.rgb = 20;
        if (format == 3 || format == 5) l.rgb = 28;
    } else {
        l.gpsTime = 22;
        if (format == 7 || format == 8 || format == 10) l.rgb = 30;
        if (format == 8 || format == 10) l.nir = 36;
    }
    return l;
}

std::vector<LasScalarField> lasExtraBytesFields(const char* descriptors, std::size_t bytes, std::size_t firstOffset,
                                                std::size_t recordLength)
{
    using K = LasScalarField::Kind;
    struct Type {
        K kind;
        std::size_t size;
    };
    static constexpr Type kTypes[11] = {{K::U8, 0},  {K::U8, 1},  {K::I8, 1},  {K::U16, 2}, {K::I16, 2}, {K::U32, 4},
                                        {K::I32, 4}, {K::U64, 8}, {K::I64, 8}, {K::F32, 4}, {K::F64, 8}};
    constexpr std::size_t kDescriptor = 192;
    std::vector<LasScalarField> fields;
    std::size_t offset = firstOffset;
    for (std::size_t at = 0; at + kDescriptor <= bytes; at += kDescriptor) {
        const char* d = descriptors + at;
        const auto type = std::uint8_t(d[2]);
        const auto options = std::uint8_t(d[3]);
        std::size_t size = 0;
        if (type == 0) size = options; // undocumented bytes: their count in the options
        else if (type <= 10) size = kTypes[type].size;
        else break;                    // the deprecated arrays (11–30) and unknown types: stop reading fields
        if (size == 0 || offset + size > recordLength) break;
        if (type != 0) {
            LasScalarField f;
            const char* name = d + 4;
            // A column name as every writer takes it: letters, digits and '_' ("Original cloud index" →
            // "Original_cloud_index"); none: extra_N.
            for (const char* c = name; c < name + 32 && *c != '\0'; ++c)
                f.name += std::isalnum(static_cast<unsigned char>(*c)) && static_cast<unsigned char>(*c) < 128 ? *c : '_';
            if (f.name.empty()) f.name = "extra_" + std::to_string(fields.size());
            f.kind = kTypes[type].kind;
            f.offset = std::uint16_t(offset);
            if (options & 0x08) f.scale = loadLittleEndian<double>(d + 4 + 32 + 4 + 24 * 3);
            if (options & 0x10) f.add = loadLittleEndian<double>(d + 4 + 32 + 4 + 24 * 4);
            if (!std::isfinite(f.scale) || f.scale == 0.0) f.scale = 1.0;
            if (!std::isfinite(f.add)) f.add = 0.0;
            fields.push_back(std::move(f));
        }
        offset += size;
    }
    return fields;
}

std::vector<LasScalarField> lasScalarFields(const LasPointLayout& layout)
{
    using K = LasScalarField::Kind;
    std::vector<LasScalarField> f;
    f.push_back({"intensity", K::U16, 12, 0, 0xFF});
    if (!layout.extended) {
        f.push_back({"return_number", K::Bits, 14, 0, 0x07});
        f.push_back({"number_of_returns", K::Bits, 14, 3, 0x07});
        f.push_back({"classification", K::Bits, 15, 0, 0x1F});
        f.push_back({"scan_angle", K::Angle8, 16, 0, 0xFF});
        f.push_back({"user_data", K::U8, 17, 0, 0xFF});
        f.push_back({"point_source_id", K::U16, 18, 0, 0xFF});
    } else {
        f.push_back({"return_number", K::Bits, 14, 0, 0x0F});
        f.push_back({"number_of_returns", K::Bits, 14, 4, 0x0F});
        f.push_back({"classification", K::U8, 16, 0, 0xFF});
        f.push_back({"scan_angle", K::Angle16, 18, 0, 0xFF});
        f.push_back({"user_data", K::U8, 17, 0, 0xFF});
        f.push_back({"point_source_id", K::U16, 20, 0, 0xFF});
    }
    if (layout.gpsTime >= 0)
        f.push_back({"gps_time", K::F64, static_cast<std::uint8_t>(layout.gpsTime), 0, 0xFF});
    if (layout.nir >= 0) f.push_back({"nir", K::U16, static_cast<std::uint8_t>(layout.nir), 0, 0xFF});
    return f;
}

} // namespace stylos::core::io
