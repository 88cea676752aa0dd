// LasReader: every point format 0–10 in every version 1.0–1.4 written by a small writer below, with
// exact read-back; extra bytes, VLRs, 64-bit counts, colour depth; every error path; real fixtures.
#include "stylos/core/io/LasReader.h"
#include "stylos/core/io/PointFileFormat.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace fs = std::filesystem;
using namespace stylos::core;
using namespace stylos::core::io;

namespace {

static_assert(std::endian::native == std::endian::little, "the test writer assumes a little-endian host");

struct LasPoint {
    std::int32_t x = 0, y = 0, z = 0;
    std::uint16_t intensity = 0;
    std::uint8_t returnNumber = 1, numberOfReturns = 1, classification = 0;
    std::int16_t scanAngle = 0; ///< degrees (formats 0–5) or 0.006° units (6–10)
    std::uint8_t userData = 0;
    std::uint16_t pointSourceId = 0;
    double gpsTime = 0;
    std::uint16_t red = 0, green = 0, blue = 0, nir = 0;
};

struct LasSpec {
    unsigned minor = 2;
    unsigned format = 0;
    std::size_t extraBytes = 0;     ///< after the standard record
    std::size_t vlrs = 0;           ///< each 54 + 10 bytes
    std::size_t headerPadding = 0;  ///< user data between the header and the VLRs
    bool count64 = false;           ///< 1.4: legacy count 0, the 64-bit count set
    std::array<double, 3> scale{0.001, 0.01, 0.5};
    std::array<double, 3> offset{1000.0, -2000.0, 5.0};
};

constexpr std::uint16_t kStandardLength[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

template <typename T>
void put(std::vector<char>& b, std::size_t at, T v) { std::memcpy(b.data() + at, &v, sizeof v); }

double world(std::int32_t v, const LasSpec& s, int axis) { return double(v) * s.scale[axis] + s.offset[axis]; }

std::vector<char> makeLas(const LasSpec& s, const std::vector<LasPoint>& points)
{
    const std::size_t header = LasHeader::minimumHeaderSize(s.minor) + s.headerPadding;
    const std::size_t dataOffset = header + s.vlrs * 64;
    const std::size_t length = kStandardLength[s.format] + s.extraBytes;
    std::vector<char> b(dataOffset + points.size() * length, char(0xCD));
    std::memset(b.data(), 0, header);
    std::memcpy(b.data(), "LASF", 4);
    b[24] = 1; b[25] = char(s.minor); b[104] = char(s.format);
    put(b, 94, std::uint16_t(header)); put(b, 96, std::uint32_t(dataOffset)); put(b, 100, std::uint32_t(s.vlrs));
    put(b, 105, std::uint16_t(length)); put(b, 107, s.count64 ? 0u : std::uint32_t(points.size()));
    if (s.minor >= 4) put<std::uint64_t>(b, 247, points.size());
    std::array<double, 6> bounds{1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
    for (const auto& p : points)
        for (int a = 0; a < 3; ++a) {
            const double v = world(a == 0 ? p.x : a == 1 ? p.y : p.z, s, a);
            bounds[a] = std::min(bounds[a], v);
            bounds[3 + a] = std::max(bounds[3 + a], v);
        }
    for (int a = 0; a < 3; ++a) {
        put(b, 131 + 8 * a, s.scale[a]); put(b, 155 + 8 * a, s.offset[a]);
        put(b, 179 + 16 * a, bounds[3 + a]); put(b, 187 + 16 * a, bounds[a]); // max then min
    }
    for (std::size_t at = header; at < dataOffset; at += 64) { // VLR: 54-byte header + 10 bytes
        std::memset(b.data() + at, 'v', 64); put(b, at + 20, std::uint16_t(1234)); put(b, at + 22, std::uint16_t(10));
    }
    const bool ext = s.format >= 6;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const LasPoint& p = points[i];
        const std::size_t at = dataOffset + i * length;
        std::memset(b.data() + at, 0xAB, kStandardLength[s.format]); // wave packets stay 0xAB
        put(b, at, p.x); put(b, at + 4, p.y); put(b, at + 8, p.z); put(b, at + 12, p.intensity);
        if (!ext) {
            b[at + 14] = char(p.returnNumber | p.numberOfReturns << 3 | 0x40); // scan direction flag set
            b[at + 15] = char(p.classification | 0x80);                        // withheld flag set
            b[at + 16] = char(std::int8_t(p.scanAngle));
            b[at + 17] = char(p.userData);
            put(b, at + 18, p.pointSourceId);
            if (s.format == 1 || s.format >= 3) put(b, at + 20, p.gpsTime);
        } else {
            b[at + 14] = char(p.returnNumber | p.numberOfReturns << 4);
            b[at + 15] = char(0xF7); // flags, channel, direction, edge
            b[at + 16] = char(p.classification);
            b[at + 17] = char(p.userData);
            put(b, at + 18, p.scanAngle);
            put(b, at + 20, p.pointSourceId);
            put(b, at + 22, p.gpsTime);
        }
        const int rgb = s.format == 2 ? 20 : (s.format == 3 || s.format == 5) ? 28
                      : (s.format == 7 || s.format == 8 || s.format == 10) ? 30 : -1;
        if (rgb >= 0) { put(b, at + rgb, p.red); put(b, at + rgb + 2, p.green); put(b, at + rgb + 4, p.blue); }
        if (s.format == 8 || s.format == 10) put(b, at + 36, p.nir);
    }
    return b;
}

std::vector<LasPoint> samplePoints(unsigned format)
{
    const bool ext = format >= 6;
    LasPoint a{-5, 7, 2147483647, 65535, ext ? std::uint8_t(15) : std::uint8_t(7), ext ? std::uint8_t(15) : std::uint8_t(7),
               ext ? std::uint8_t(200) : std::uint8_t(31), ext ? std::int16_t(-15000) : std::int16_t(-90), 255, 65535,
               123456.789, 0x1234, 0xFFFF, 0x0100, 0xBEEF};
    LasPoint b{1000000, -2147483647 - 1, 0, 0, 1, 2, 2, ext ? std::int16_t(2500) : std::int16_t(15), 0, 0, -1.5,
               0, 0x00FF, 0x8000, 0};
    LasPoint c{0, 0, -3, 4242, 0, 0, 0, 0, 17, 9, 0.0, 0xFF00, 0x0300, 0x0200, 65535};
    return {a, b, c};
}

Result<std::unique_ptr<PointReader>> openBytes(const stylos::test::TempDir& dir, const std::vector<char>& bytes,
                                               const std::string& name = "cloud.las")
{
    stylos::test::writeBytes(dir / name, bytes);
    return LasReader::open(dir / name);
}

/** Reads the whole file in batches of @p batchSize into one batch. */
PointBatch readAll(PointReader& reader, std::size_t batchSize = 65536)
{
    PointBatch all, batch;
    all.scalars.resize(reader.header().schema.scalarNames.size());
    for (;;) {
        auto n = reader.read(batch, batchSize);
        EXPECT_TRUE(n.ok()) << (n.ok() ? "" : n.error().message);
        if (!n.ok() || *n == 0) break;
        all.positions.insert(all.positions.end(), batch.positions.begin(), batch.positions.end());
        all.colors.insert(all.colors.end(), batch.colors.begin(), batch.colors.end());
        for (std::size_t c = 0; c < batch.scalars.size(); ++c)
            all.scalars[c].insert(all.scalars[c].end(), batch.scalars[c].begin(), batch.scalars[c].end());
    }
    return all;
}

double column(const PointReader& r, const PointBatch& b, const std::string& name, std::size_t i)
{
    const auto& names = r.header().schema.scalarNames;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) ADD_FAILURE() << "no column " << name;
    return it == names.end() ? NAN : b.scalars[std::size_t(it - names.begin())][i];
}

} // namespace

TEST(LasReader, ReadsEveryPointFormatInEveryVersion)
{
    stylos::test::TempDir dir;
    for (unsigned minor = 0; minor <= 4; ++minor)
        for (unsigned format = 0; format <= 10; ++format) {
            SCOPED_TRACE("LAS 1." + std::to_string(minor) + " format " + std::to_string(format));
            LasSpec spec;
            spec.minor = minor;
            spec.format = format;
            spec.extraBytes = (minor + format) % 4 * 3; // extra bytes after the standard record
            spec.vlrs = minor % 3;
            spec.headerPadding = format % 2 * 13;      // user data after the header
            spec.count64 = minor == 4 && format % 2 == 0; // 1.4: legacy count 0, 64-bit count set
            const auto points = samplePoints(format);
            auto reader = openBytes(dir, makeLas(spec, points));
            ASSERT_TRUE(reader.ok()) << reader.error().message;
            PointReader& r = **reader;
            const LasHeader& las = dynamic_cast<const LasReader&>(r).lasHeader();
            EXPECT_EQ(las.recordLength, kStandardLength[format] + spec.extraBytes);
            EXPECT_EQ(las.offsetToPointData, las.headerSize + 64 * spec.vlrs);
            EXPECT_EQ(las.vlrCount, spec.vlrs);
            const bool ext = format >= 6, rgb = format == 2 || format == 3 || format == 5 || format == 7 ||
                                               format == 8 || format == 10;
            const bool gps = format != 0 && format != 2, nir = format == 8 || format == 10;
            EXPECT_EQ(r.header().format, "las-1." + std::to_string(minor));
            EXPECT_EQ(r.header().declaredPoints, 3u);
            EXPECT_EQ(r.header().schema.hasColors, rgb);
            EXPECT_FALSE(r.header().schema.hasNormals);
            std::vector<std::string> names{"intensity", "return_number", "number_of_returns", "classification",
                                           "scan_angle", "user_data", "point_source_id"};
            if (gps) names.push_back("gps_time");
            if (nir) names.push_back("nir");
            EXPECT_EQ(r.header().schema.scalarNames, names);
            ASSERT_TRUE(r.header().declaredBounds.has_value());
            const std::array<double, 6> bounds{world(-5, spec, 0), world(-2147483647 - 1, spec, 1), world(-3, spec, 2),
                                               world(1000000, spec, 0), world(7, spec, 1), world(2147483647, spec, 2)};
            EXPECT_EQ(*r.header().declaredBounds, bounds);

            const PointBatch b = readAll(r);
            ASSERT_EQ(b.size(), 3u);
            EXPECT_EQ(r.pointsRead(), 3u);
            EXPECT_EQ(r.bytesConsumed(), r.fileBytes());
            for (std::size_t i = 0; i < 3; ++i) {
                const LasPoint& p = points[i];
                EXPECT_EQ(b.positions[3 * i + 0], world(p.x, spec, 0));
                EXPECT_EQ(b.positions[3 * i + 1], world(p.y, spec, 1));
                EXPECT_EQ(b.positions[3 * i + 2], world(p.z, spec, 2));
                EXPECT_EQ(column(r, b, "intensity", i), p.intensity);
                EXPECT_EQ(column(r, b, "return_number", i), p.returnNumber);
                EXPECT_EQ(column(r, b, "number_of_returns", i), p.numberOfReturns);
                EXPECT_EQ(column(r, b, "classification", i), p.classification);
                EXPECT_DOUBLE_EQ(column(r, b, "scan_angle", i), ext ? p.scanAngle * 0.006 : p.scanAngle);
                EXPECT_EQ(column(r, b, "user_data", i), p.userData);
                EXPECT_EQ(column(r, b, "point_source_id", i), p.pointSourceId);
                if (gps) { EXPECT_EQ(column(r, b, "gps_time", i), p.gpsTime); }
                if (nir) { EXPECT_EQ(column(r, b, "nir", i), p.nir); }
                if (rgb) {
                    ASSERT_EQ(b.colors.size(), 9u);
                    EXPECT_EQ(b.colors[3 * i + 0], p.red >> 8);
                    EXPECT_EQ(b.colors[3 * i + 1], p.green >> 8);
                    EXPECT_EQ(b.colors[3 * i + 2], p.blue >> 8);
                } else {
                    EXPECT_TRUE(b.colors.empty());
                }
            }
            EXPECT_NEAR(column(r, b, "scan_angle", 0), -90.0, 1e-12); // rank -90° or -15000 × 0.006°
        }
}

TEST(LasReader, BatchesSplitTheFileAndEndWithZero)
{
    stylos::test::TempDir dir;
    LasSpec spec;
    spec.format = 1;
    spec.extraBytes = 3; // 31-byte records straddle every buffer boundary
    std::vector<LasPoint> points(150000);
    for (std::size_t i = 0; i < points.size(); ++i) {
        points[i].x = std::int32_t(i);
        points[i].y = -std::int32_t(i);
        points[i].intensity = std::uint16_t(i * 7);
        points[i].gpsTime = double(i) * 0.25;
    }
    auto reader = openBytes(dir, makeLas(spec, points));
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    PointBatch batch;
    std::size_t total = 0;
    for (;;) {
        auto n = (*reader)->read(batch, 40000);
        ASSERT_TRUE(n.ok()) << n.error().message;
        if (*n == 0) break;
        ASSERT_EQ(*n, std::min<std::size_t>(40000, points.size() - total));
        for (std::size_t i = 0; i < *n; ++i) {
            const std::size_t k = total + i;
            ASSERT_EQ(batch.positions[3 * i], world(std::int32_t(k), spec, 0));
            ASSERT_EQ(batch.positions[3 * i + 1], world(-std::int32_t(k), spec, 1));
            ASSERT_EQ(batch.scalars[0][i], std::uint16_t(k * 7));
            ASSERT_EQ(batch.scalars[7][i], double(k) * 0.25);
        }
        total += *n;
    }
    EXPECT_EQ(total, points.size());
    EXPECT_EQ((*reader)->pointsRead(), points.size());
    EXPECT_EQ((*reader)->bytesConsumed(), (*reader)->fileBytes());
    auto again = (*reader)->read(batch, 10);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(*again, 0u);
    EXPECT_TRUE(batch.empty());
}

TEST(LasReader, EightBitColoursPassUnchanged)
{
    stylos::test::TempDir dir;
    LasSpec spec;
    spec.format = 2;
    std::vector<LasPoint> points(100000);
    for (std::size_t i = 0; i < points.size(); ++i) {
        points[i].red = std::uint16_t(i % 256);
        points[i].green = 255;
        points[i].blue = 7;
    }
    points[4000].red = 1000; // between two sampling windows: judged 8-bit, clamped
    auto reader = openBytes(dir, makeLas(spec, points));
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    EXPECT_TRUE(dynamic_cast<const LasReader&>(**reader).colorsStored8Bit());
    const PointBatch b = readAll(**reader);
    ASSERT_EQ(b.size(), points.size());
    for (std::size_t i : {std::size_t(0), std::size_t(1), std::size_t(200), std::size_t(99999)}) {
        EXPECT_EQ(b.colors[3 * i], i % 256);
        EXPECT_EQ(b.colors[3 * i + 1], 255);
        EXPECT_EQ(b.colors[3 * i + 2], 7);
    }
    EXPECT_EQ(b.colors[3 * 4000], 255);

    points[4000].red = 0;
    points.back().blue = 256; // the last window ends the data: the file is 16-bit
    auto sixteen = openBytes(dir, makeLas(spec, points), "sixteen.las");
    ASSERT_TRUE(sixteen.ok()) << sixteen.error().message;
    EXPECT_FALSE(dynamic_cast<const LasReader&>(**sixteen).colorsStored8Bit());
    const PointBatch c = readAll(**sixteen);
    EXPECT_EQ(c.colors[3 * 200 + 1], 0);
    EXPECT_EQ(c.colors[3 * 99999 + 2], 1);
}

TEST(LasReader, SkipsPointsWhosePositionOverflows)
{
    stylos::test::TempDir dir;
    LasSpec spec;
    spec.scale = {1e300, 1.0, 1.0};
    spec.offset = {0.0, 0.0, 0.0};
    std::vector<LasPoint> points(3);
    points[0].x = 1;
    points[1].x = 2000000000; // 2e309: infinite
    points[2].x = -1;
    points[2].intensity = 77;
    auto reader = openBytes(dir, makeLas(spec, points));
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    PointBatch b;
    auto n = (*reader)->read(b, 2);
    ASSERT_TRUE(n.ok());
    ASSERT_EQ(*n, 2u);
    EXPECT_EQ(b.positions[0], 1e300);
    EXPECT_EQ(b.positions[3], -1e300);
    EXPECT_EQ(b.scalars[0][1], 77);
    EXPECT_EQ((*reader)->pointsSkipped(), 1u);
    EXPECT_EQ((*reader)->read(b, 2).value(), 0u);
}

TEST(LasReader, RefusesBadHeadersWithPreciseErrors)
{
    using Bytes = std::vector<char>;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    struct BadCase { const char* name; ErrorCode code; const char* where; const char* contains; void (*patch)(Bytes&); };
    const BadCase cases[] = {
        {"signature", ErrorCode::Malformed, "byte 0", "LASF", [](Bytes& b) { b[3] = 'X'; }},
        {"short-header", ErrorCode::Truncated, "byte 200", "header", [](Bytes& b) { b.resize(200); }},
        {"short-14-header", ErrorCode::Truncated, "byte 300", "375", [](Bytes& b) { b[25] = 4; b.resize(300); }},
        {"version-2", ErrorCode::Unsupported, "byte 24", "2.0", [](Bytes& b) { b[24] = 2; b[25] = 0; }},
        {"version-15", ErrorCode::Unsupported, "byte 24", "1.5", [](Bytes& b) { b[25] = 5; }},
        {"format-11", ErrorCode::Unsupported, "byte 104", "format 11", [](Bytes& b) { b[104] = 11; }},
        {"laz", ErrorCode::Unsupported, "byte 104", "LAZ", [](Bytes& b) { b[104] = char(0x83); }},
        {"record-short", ErrorCode::Malformed, "byte 105", "shorter", [](Bytes& b) { put<std::uint16_t>(b, 105, 19); }},
        {"offset-beyond", ErrorCode::Truncated, "byte 96", "beyond", [](Bytes& b) { put<std::uint32_t>(b, 96, 99999); }},
        {"offset-in-header", ErrorCode::Malformed, "byte 94", "overlaps", [](Bytes& b) { put<std::uint32_t>(b, 96, 100); }},
        {"header-size-small", ErrorCode::Malformed, "byte 94", "impossible", [](Bytes& b) { put<std::uint16_t>(b, 94, 100); }},
        {"header-size-huge", ErrorCode::Malformed, "byte 94", "overlaps", [](Bytes& b) { put<std::uint16_t>(b, 94, 60000); }},
        {"data-short", ErrorCode::Truncated, "byte 227", "200 bytes from here, but the file has only 195",
         [](Bytes& b) { b.resize(b.size() - 5); }},
        {"count-huge", ErrorCode::Truncated, "byte 227", "4294967295 points", [](Bytes& b) { put(b, 107, ~0u); }},
        {"scale-nan", ErrorCode::Malformed, "byte 139", "Y scale factor NaN", [](Bytes& b) { put(b, 139, nan); }},
        {"scale-zero", ErrorCode::Malformed, "byte 131", "X scale factor 0", [](Bytes& b) { put(b, 131, 0.0); }},
        {"offset-inf", ErrorCode::Malformed, "byte 171", "Z offset", [](Bytes& b) { put(b, 171, inf); }},
    };
    stylos::test::TempDir dir;
    for (const BadCase& c : cases) {
        SCOPED_TRACE(c.name);
        auto bytes = makeLas(LasSpec{}, std::vector<LasPoint>(10));
        c.patch(bytes);
        const std::string name = std::string(c.name) + ".las";
        auto reader = openBytes(dir, bytes, name);
        ASSERT_FALSE(reader.ok());
        const std::string& m = reader.error().message;
        EXPECT_EQ(reader.error().code, c.code) << m;
        EXPECT_EQ(m.rfind((dir / name).string() + ": " + c.where + ": ", 0), 0u) << m;
        EXPECT_NE(m.find(c.contains), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

TEST(LasReader, RefusesDisagreeingCountsEmptyAndMissingFiles)
{
    stylos::test::TempDir dir;
    LasSpec spec;
    spec.minor = 4;
    auto bytes = makeLas(spec, std::vector<LasPoint>(3));
    put<std::uint64_t>(bytes, 247, 2);
    auto reader = openBytes(dir, bytes);
    ASSERT_FALSE(reader.ok());
    EXPECT_EQ(reader.error().code, ErrorCode::Malformed);
    EXPECT_NE(reader.error().message.find("byte 247: the 64-bit point count 2 disagrees"), std::string::npos);

    auto empty = openBytes(dir, {}, "empty.las");
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().code, ErrorCode::Empty);
    auto missing = LasReader::open(dir / "missing.las");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
}

TEST(LasReader, FileShrinkingWhileReadIsTruncatedNotACrash)
{
    stylos::test::TempDir dir;
    auto reader = openBytes(dir, makeLas(LasSpec{}, std::vector<LasPoint>(200000))); // 4 MB
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    fs::resize_file(dir / "cloud.las", 2000000);
    PointBatch b;
    for (;;) {
        auto n = (*reader)->read(b, 65536);
        if (!n.ok()) {
            EXPECT_EQ(n.error().code, ErrorCode::Truncated);
            EXPECT_NE(n.error().message.find("cloud.las: byte 2000000: the file ends inside"), std::string::npos)
                << n.error().message;
            return;
        }
        ASSERT_NE(*n, 0u) << "the shrunken file was read to the end without an error";
    }
}

TEST(LasReader, ReadsRealFixtures)
{
    SKIP_WITHOUT_SHARED_DATA();
    const fs::path dir = stylos::test::sharedData() / "formats";
    struct Fixture { const char* name; std::uint64_t points; bool colors; };
    for (const Fixture& f : {Fixture{"autzen_trim.las", 110000, true}, Fixture{"mvk-thin.las", 6280, false},
                             Fixture{"minimal-las-1.2-unmodified-valid.las", 1, false}}) {
        SCOPED_TRACE(f.name);
        auto reader = openPointReader(dir / f.name);
        ASSERT_TRUE(reader.ok()) << reader.error().message;
        const PointFileHeader& h = (*reader)->header();
        EXPECT_EQ(h.format, "las-1.2");
        EXPECT_EQ(h.declaredPoints, f.points);
        EXPECT_EQ(h.schema.hasColors, f.colors);
        ASSERT_TRUE(h.declaredBounds.has_value());
        const auto& bounds = *h.declaredBounds;
        const PointBatch b = readAll(**reader);
        ASSERT_EQ(b.size(), f.points);
        EXPECT_EQ((*reader)->pointsSkipped(), 0u);
        for (std::size_t i = 0; i < b.size(); ++i)
            for (std::size_t a = 0; a < 3; ++a) {
                ASSERT_GE(b.positions[3 * i + a], bounds[a] - 1e-6) << "point " << i;
                ASSERT_LE(b.positions[3 * i + a], bounds[3 + a] + 1e-6) << "point " << i;
            }
    }
    // First autzen point, read with Python's struct: colours stored 8-bit (all ≤ 236).
    auto autzen = LasReader::open(dir / "autzen_trim.las");
    ASSERT_TRUE(autzen.ok());
    PointBatch b;
    ASSERT_TRUE((*autzen)->read(b, 1).ok());
    EXPECT_EQ(b.positions[0], 63717798 * 0.01);
    EXPECT_EQ(b.positions[1], 84939395 * 0.01);
    EXPECT_EQ(b.positions[2], 41119 * 0.01);
    EXPECT_EQ((std::vector<std::uint8_t>(b.colors.begin(), b.colors.end())), (std::vector<std::uint8_t>{84, 102, 93}));
    EXPECT_EQ((std::vector<double>{b.scalars[0][0], b.scalars[1][0], b.scalars[2][0], b.scalars[3][0],
                                   b.scalars[4][0], b.scalars[5][0], b.scalars[6][0]}),
              (std::vector<double>{4, 1, 1, 1, -17, 128, 7326}));

    for (auto* open : {+[](const fs::path& p) { return openPointReader(p); },
                       +[](const fs::path& p) { return LasReader::open(p); }}) {
        auto laz = open(dir / "autzen_trim.laz");
        ASSERT_FALSE(laz.ok());
        EXPECT_EQ(laz.error().code, ErrorCode::Unsupported);
        EXPECT_NE(laz.error().message.find("autzen_trim.laz"), std::string::npos);
    }
}

TEST(LasReader, ExtraBytesDescriptorsGiveNamedScaledColumns)
{
    // Two descriptors: 3 undocumented bytes (type 0, their count in the options), then a signed 16-bit "temp" with
    // scale 0.1 and offset 20 (options bits 3 and 4); a third, a deprecated array type, ends the list.
    std::vector<char> d(3 * 192, 0);
    d[2] = 0, d[3] = 3;
    char* t = d.data() + 192;
    t[2] = 4, t[3] = 0x18;
    std::memcpy(t + 4, "temp (C)", 8); // a name made fit for a column: "temp__C_"
    const double scale = 0.1, offset = 20.0;
    std::memcpy(t + 112, &scale, 8);
    std::memcpy(t + 136, &offset, 8);
    d[2 * 192 + 2] = 11;
    const auto fields = stylos::core::io::lasExtraBytesFields(d.data(), d.size(), 30, 40);
    ASSERT_EQ(fields.size(), 1u);
    EXPECT_EQ(fields[0].name, "temp__C_");
    EXPECT_EQ(fields[0].kind, stylos::core::io::LasScalarField::Kind::I16);
    EXPECT_EQ(fields[0].offset, 33);
    EXPECT_EQ(fields[0].scale, 0.1);
    EXPECT_EQ(fields[0].add, 20.0);
    // A field past the record's end is left out.
    EXPECT_TRUE(stylos::core::io::lasExtraBytesFields(d.data(), d.size(), 30, 34).empty());
}

TEST(LasReader, ExtraBytesColumnsAreNamedOnceAndNeverAsANormal)
{
    // Format 0 with 3 extra bytes, described as unsigned bytes "nx", "a" and "a" in an Extra Bytes VLR: the columns
    // come after the standard ones as nx_2 (a normal estimated later takes "nx"), a and a_2, each byte as written.
    LasSpec spec;
    std::vector<char> bytes = makeLas([&] { spec.extraBytes = 3; return spec; }(), std::vector<LasPoint>(4));
    const std::size_t header = LasHeader::minimumHeaderSize(spec.minor);
    std::vector<char> vlr(54 + 3 * 192, 0);
    std::memcpy(vlr.data() + 2, "LASF_Spec", 9);
    put(vlr, 18, std::uint16_t(4));
    put(vlr, 20, std::uint16_t(3 * 192));
    const char* names[3] = {"nx", "a", "a"};
    for (int k = 0; k < 3; ++k) {
        char* d = vlr.data() + 54 + 192 * k;
        d[2] = 1; // unsigned char
        std::memcpy(d + 4, names[k], std::strlen(names[k]));
    }
    bytes.insert(bytes.begin() + std::ptrdiff_t(header), vlr.begin(), vlr.end());
    put(bytes, 96, std::uint32_t(header + vlr.size()));
    put(bytes, 100, std::uint32_t(1));
    const std::size_t first = header + vlr.size();
    const std::size_t length = kStandardLength[0] + 3;
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t k = 0; k < 3; ++k) bytes[first + i * length + kStandardLength[0] + k] = char(10 * k + i);
    stylos::test::TempDir dir;
    auto reader = openBytes(dir, bytes);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    const auto& names_ = (*reader)->header().schema.scalarNames;
    ASSERT_GE(names_.size(), 3u);
    EXPECT_EQ(std::vector<std::string>(names_.end() - 3, names_.end()), (std::vector<std::string>{"nx_2", "a", "a_2"}));
    const PointBatch all = readAll(**reader);
    ASSERT_EQ(all.size(), 4u);
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(all.scalars[names_.size() - 3 + k][i], double(10 * k + i)) << k << "," << i;
}
