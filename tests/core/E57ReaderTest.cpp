// E57Reader: the shared fixtures (counts, first points decoded by hand from a hexdump of the first data
// packet, bounds equal to the files' own cartesianBounds, the invalid files' messages), and files made by
// a small writer below: a pose applied, spherical coordinates, invalid states skipped and counted,
// bit-packed integers straddling packets, index and empty packets, one scan chosen, a damaged page named.
#include "stylos/core/io/E57PagedFile.h"
#include "stylos/core/io/E57Reader.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointFileSummary.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>

namespace fs = std::filesystem;
using namespace stylos::core;
using namespace stylos::core::io;
using stylos::test::TempDir;

namespace {

static_assert(std::endian::native == std::endian::little, "the test writer assumes a little-endian host");

fs::path fixture(const std::string& name) { return stylos::test::sharedData() / "formats" / name; }

PointBatch readAll(const fs::path& path, const ReadOptions& options = {}, std::size_t batch = 3)
{
    auto reader = openPointReader(path, options);
    EXPECT_TRUE(reader) << (reader ? "" : reader.error().message);
    if (!reader) return {};
    auto all = stylos::test::readAllPoints(**reader, batch);
    EXPECT_TRUE(all) << (all ? "" : all.error().message);
    return all ? all.value() : PointBatch{};
}

std::string openError(const fs::path& path, ErrorCode expected)
{
    auto reader = openPointReader(path);
    if (reader) {
        PointBatch batch;
        for (;;) {
            auto got = (*reader)->read(batch, 1000);
            if (!got) {
                EXPECT_EQ(int(got.error().code), int(expected)) << got.error().message;
                return got.error().message;
            }
            if (*got == 0) break;
        }
        ADD_FAILURE() << path << " was read without an error";
        return {};
    }
    EXPECT_EQ(int(reader.error().code), int(expected)) << reader.error().message;
    return reader.error().message;
}

// ---- a small E57 writer: logical bytes, then 1024-byte pages with their big-endian CRC-32C ----

struct Field {
    std::string xml;                 ///< the prototype element
    std::vector<unsigned char> bits; ///< the whole bytestream
};

template <typename T>
void putLe(std::vector<unsigned char>& b, T v)
{
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    b.insert(b.end(), p, p + sizeof v);
}

/** Packs (value − minimum) in @p width bits from the least significant bit, as the bitpack codec does. */
std::vector<unsigned char> packBits(const std::vector<std::int64_t>& values, std::int64_t minimum, unsigned width)
{
    std::vector<unsigned char> out((values.size() * width + 7) / 8, 0);
    std::uint64_t bit = 0;
    for (std::int64_t v : values)
        for (unsigned k = 0; k < width; ++k, ++bit)
            if ((std::uint64_t(v - minimum) >> k) & 1u) out[bit / 8] |= static_cast<unsigned char>(1u << (bit % 8));
    return out;
}

template <typename T>
Field floatField(const std::string& name, const std::vector<double>& values)
{
    Field f;
    f.xml = "<" + name + " type=\"Float\"" + (sizeof(T) == 4 ? " precision=\"single\"" : "") + "/>";
    for (double v : values) putLe(f.bits, T(v));
    return f;
}

Field integerField(const std::string& name, std::int64_t min, std::int64_t max, unsigned width,
                   const std::vector<std::int64_t>& values, const std::string& scale = "")
{
    Field f;
    f.xml = "<" + name + " type=\"" + (scale.empty() ? "Integer" : "ScaledInteger") + "\" minimum=\"" +
            std::to_string(min) + "\" maximum=\"" + std::to_string(max) + "\"" +
            (scale.empty() ? "" : " scale=\"" + scale + "\"") + "/>";
    f.bits = packBits(values, min, width);
    return f;
}

struct Scan {
    std::string extraXml; ///< name, pose, limits
    std::uint64_t records = 0;
    std::vector<Field> fields;
    std::size_t packets = 2; ///< each bytestream is cut into this many packets at different byte positions
};

std::uint64_t physical(std::uint64_t logical) { return logical / 1020 * 1024 + logical % 1020; }

std::vector<char> makeE57(const std::vector<Scan>& scans)
{
    std::vector<unsigned char> log(48, 0);
    std::vector<std::uint64_t> sections;
    for (const Scan& s : scans) {
        while (log.size() % 4) log.push_back(0);
        const std::size_t start = log.size();
        sections.push_back(physical(start));
        log.resize(start + 32, 0);
        std::vector<unsigned char> body;
        // An empty packet and an index packet first: both must be skipped.
        body.insert(body.end(), {2, 0, 3, 0});
        body.insert(body.end(), {0, 0, 15, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
        for (std::size_t p = 0; p < s.packets; ++p) {
            std::vector<unsigned char> packet = {1, 0, 0, 0};
            putLe(packet, std::uint16_t(s.fields.size()));
            std::vector<std::pair<std::size_t, std::size_t>> cuts;
            for (std::size_t f = 0; f < s.fields.size(); ++f) {
                const std::size_t n = s.fields[f].bits.size();
                // Field f's cut points shift with f, so the streams run out of step.
                auto cut = [&](std::size_t k) { return k == 0 ? 0 : k == s.packets ? n : std::min(n, n * k / s.packets + f % 3); };
                cuts.emplace_back(cut(p), cut(p + 1));
                putLe(packet, std::uint16_t(cuts.back().second - cuts.back().first));
            }
            for (std::size_t f = 0; f < s.fields.size(); ++f)
                packet.insert(packet.end(), s.fields[f].bits.begin() + cuts[f].first, s.fields[f].bits.begin() + cuts[f].second);
            while (packet.size() % 4) packet.push_back(0);
            const auto lengthMinus1 = std::uint16_t(packet.size() - 1);
            std::memcpy(packet.data() + 2, &lengthMinus1, 2);
            body.insert(body.end(), packet.begin(), packet.end());
        }
        log.insert(log.end(), body.begin(), body.end());
        std::vector<unsigned char> header = {1, 0, 0, 0, 0, 0, 0, 0};
        putLe(header, std::uint64_t(log.size() - start));
        putLe(header, physical(start + 32));
        putLe(header, std::uint64_t(0));
        std::memcpy(log.data() + start, header.data(), 32);
    }
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<e57Root type=\"Structure\" "
                      "xmlns=\"http://www.astm.org/COMMIT/E57/2010-e57-v1.0\">\n<data3D type=\"Vector\">\n";
    for (std::size_t i = 0; i < scans.size(); ++i) {
        xml += "<vectorChild type=\"Structure\">" + scans[i].extraXml + "<points type=\"CompressedVector\" fileOffset=\"" +
               std::to_string(sections[i]) + "\" recordCount=\"" + std::to_string(scans[i].records) +
               "\"><prototype type=\"Structure\">";
        for (const Field& f : scans[i].fields) xml += f.xml;
        xml += "</prototype><codecs type=\"Vector\"/></points></vectorChild>\n";
    }
    xml += "</data3D>\n</e57Root>\n";
    const std::uint64_t xmlLogical = log.size();
    log.insert(log.end(), xml.begin(), xml.end());
    const std::size_t pages = (log.size() + 1019) / 1020;
    log.resize(pages * 1020, 0);
    std::memcpy(log.data(), "ASTM-E57", 8);
    std::vector<unsigned char> h;
    putLe(h, std::uint32_t(1));
    putLe(h, std::uint32_t(0));
    putLe(h, std::uint64_t(pages * 1024));
    putLe(h, physical(xmlLogical));
    putLe(h, std::uint64_t(xml.size()));
    putLe(h, std::uint64_t(1024));
    std::memcpy(log.data() + 8, h.data(), h.size());
    std::vector<char> file;
    for (std::size_t p = 0; p < pages; ++p) {
        const unsigned char* page = log.data() + p * 1020;
        file.insert(file.end(), page, page + 1020);
        const std::uint32_t crc = crc32c(page, 1020);
        for (int k = 3; k >= 0; --k) file.push_back(static_cast<char>((crc >> (8 * k)) & 0xFF));
    }
    return file;
}

/** Scan 0: cartesian (double x, single y, scaled-integer z in 11 bits), an invalid state, intensity and
 *  colour, rotated 90° about z and moved by (10, 20, 30). Scan 1: spherical, no pose, no colour. */
std::vector<Scan> twoScans()
{
    const double h = std::sqrt(0.5);
    Scan a;
    a.extraXml = "<name type=\"String\"><![CDATA[posed]]></name><guid type=\"String\"><![CDATA[{A}]]></guid>"
                 "<pose type=\"Structure\"><rotation type=\"Structure\"><w type=\"Float\">" + std::to_string(h) +
                 "</w><x type=\"Float\"/><y type=\"Float\"/><z type=\"Float\">" + std::to_string(h) +
                 "</z></rotation><translation type=\"Structure\"><x type=\"Float\">10</x><y type=\"Float\">20</y>"
                 "<z type=\"Float\">30</z></translation></pose>"
                 "<intensityLimits type=\"Structure\"><intensityMinimum type=\"Integer\">0</intensityMinimum>"
                 "<intensityMaximum type=\"Integer\">1000</intensityMaximum></intensityLimits>";
    a.records = 5;
    a.fields = {floatField<double>("cartesianX", {1, 2, 3, 4, 5}),
                floatField<float>("cartesianY", {0.5, 0, -1, 7, 9}),
                integerField("cartesianZ", -1024, 1023, 11, {-1024, 0, 1023, 5, 6}, "0.5"),
                integerField("cartesianInvalidState", 0, 2, 2, {0, 2, 0, 1, 0}),
                integerField("intensity", 0, 1000, 10, {0, 1000, 250, 3, 500}),
                integerField("colorRed", 0, 255, 8, {255, 0, 10, 0, 1}),
                integerField("colorGreen", 0, 255, 8, {0, 0, 20, 0, 2}),
                integerField("colorBlue", 0, 255, 8, {0, 0, 30, 0, 3}),
                integerField("rowIndex", 0, 100000, 17, {7, 8, 9, 10, 11})};
    a.packets = 3;
    Scan b;
    b.extraXml = "<name type=\"String\"><![CDATA[round]]></name>";
    b.records = 2;
    b.fields = {floatField<double>("sphericalRange", {2, 4}),
                floatField<double>("sphericalAzimuth", {std::numbers::pi / 2, 0}),
                floatField<double>("sphericalElevation", {0, std::numbers::pi / 6}),
                integerField("intensity", 0, 1000, 10, {100, 900})};
    return {a, b};
}

} // namespace

TEST(E57Reader, Crc32cOfTheCheckString)
{
    EXPECT_EQ(crc32c("123456789", 9), 0xE3069283u); // the CRC-32C check value
    EXPECT_EQ(crc32c("", 0), 0u);
    EXPECT_EQ(E57PagedFile::advance(1000, 20), 1024u);
    EXPECT_EQ(E57PagedFile::advance(1000, 30), 1034u);
    EXPECT_EQ(E57PagedFile::toLogical(2048 + 5), 2040u + 5);
}

TEST(E57Reader, GeneratedScansWithPoseSphericalAndInvalidStates)
{
    TempDir dir;
    stylos::test::writeBytes(dir / "two.e57", makeE57(twoScans()));
    auto reader = openPointReader(dir / "two.e57");
    ASSERT_TRUE(reader) << reader.error().message;
    EXPECT_EQ((*reader)->header().format, "e57-1.0");
    EXPECT_EQ((*reader)->header().declaredPoints, 7u);
    // Scan 1 has no colour: only the attributes common to both are kept.
    EXPECT_FALSE((*reader)->header().schema.hasColors);
    // Two scans read: each point also carries its scan's number.
    EXPECT_EQ((*reader)->header().schema.scalarNames, (std::vector<std::string>{"intensity", "scan_index"}));
    ASSERT_EQ((*reader)->scans().size(), 2u);
    EXPECT_EQ((*reader)->scans()[0].name, "posed");
    EXPECT_EQ((*reader)->scans()[0].guid, "{A}");
    EXPECT_EQ((*reader)->scans()[1].points, 2u);

    auto all = stylos::test::readAllPoints(**reader, 2);
    ASSERT_TRUE(all) << all.error().message;
    EXPECT_EQ((*reader)->pointsMissing(), 2u); // states 2 and 1
    // Kept records of scan 0: 0, 2, 4 → (x, y, z) = (1, .5, -512), (3, -1, 511.5), (5, 9, 3); then
    // R (90° about z): (x, y, z) → (−y, x, z); + (10, 20, 30).
    const std::vector<double> expected = {10 - 0.5, 20 + 1, 30 - 512, 10 + 1, 20 + 3, 30 + 511.5, 10 - 9, 20 + 5, 30 + 3,
                                          // scan 1: r 2 at azimuth 90°, r 4 at elevation 30°
                                          0, 2, 0, 4 * std::sqrt(3.0) / 2, 0, 2};
    ASSERT_EQ(all->positions.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(all->positions[i], expected[i], 1e-12) << i;
    const std::vector<double> intensity = {0, 0.25, 0.5, 0.1, 0.9};
    ASSERT_EQ(all->scalars.size(), 2u);
    for (std::size_t i = 0; i < intensity.size(); ++i) EXPECT_DOUBLE_EQ(all->scalars[0][i], intensity[i]) << i;
    EXPECT_EQ(all->scalars[1], (std::vector<double>{0, 0, 0, 1, 1}));
}

TEST(E57Reader, OneScanKeepsItsColours)
{
    TempDir dir;
    stylos::test::writeBytes(dir / "two.e57", makeE57(twoScans()));
    ReadOptions first;
    first.scan = 0;
    const PointBatch a = readAll(dir / "two.e57", first);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(a.colors, (std::vector<std::uint8_t>{255, 0, 0, 10, 20, 30, 1, 2, 3}));
    ReadOptions second;
    second.scan = 1;
    const PointBatch b = readAll(dir / "two.e57", second);
    ASSERT_EQ(b.size(), 2u);
    EXPECT_NEAR(b.positions[1], 2.0, 1e-12);
    ASSERT_EQ(b.scalars.size(), 1u); // intensity only: one scan read has no scan column
    EXPECT_EQ(b.scalars[0], (std::vector<double>{0.1, 0.9}));
    ReadOptions none;
    none.scan = 2;
    auto missing = openPointReader(dir / "two.e57", none);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(missing.error().message.find("scan 2 does not exist: the file has 2 scan(s)"), std::string::npos)
        << missing.error().message;
}

TEST(E57Reader, DamagedPagesAndCutFilesAreNamed)
{
    TempDir dir;
    auto bytes = makeE57(twoScans());
    ASSERT_GE(bytes.size(), 2048u);
    auto damaged = bytes;
    damaged[1024 + 500] ^= 0x40; // a payload byte of page 1
    stylos::test::writeBytes(dir / "damaged.e57", damaged);
    const std::string message = openError(dir / "damaged.e57", ErrorCode::Malformed);
    EXPECT_EQ(message.rfind((dir / "damaged.e57").string() + ": page 1 (byte 1024): checksum mismatch", 0), 0u) << message;

    stylos::test::writeBytes(dir / "cut.e57", std::vector<char>(bytes.begin(), bytes.end() - 1024));
    const std::string cut = openError(dir / "cut.e57", ErrorCode::Truncated);
    EXPECT_NE(cut.find("was cut short"), std::string::npos) << cut;

    stylos::test::writeBytes(dir / "tiny.e57", std::vector<char>(bytes.begin(), bytes.begin() + 100));
    openError(dir / "tiny.e57", ErrorCode::Truncated);
}

TEST(E57Reader, FewerPacketsThanRecordsIsAnError)
{
    auto scans = twoScans();
    scans[1].records = 3; // the bytestreams hold two
    TempDir dir;
    stylos::test::writeBytes(dir / "short.e57", makeE57(scans));
    const std::string message = openError(dir / "short.e57", ErrorCode::Malformed);
    EXPECT_NE(message.find("scan 1 (\"round\"): the compressed vector ends"), std::string::npos) << message;
}

// ---- the shared fixtures ----

TEST(E57Reader, BunnyDoubleCountBoundsAndFirstPoint)
{
    SKIP_WITHOUT_SHARED_DATA();
    auto summary = summarizePointFile(fixture("bunnyDouble.e57"));
    ASSERT_TRUE(summary) << summary.error().message;
    EXPECT_EQ(summary->format, "e57-1.0");
    EXPECT_EQ(summary->points, 30571u);
    EXPECT_EQ(summary->declaredPoints, 30571u);
    EXPECT_EQ(summary->missing, 0u);
    EXPECT_TRUE(summary->attributes.empty());
    // The file's own cartesianBounds.
    EXPECT_EQ(*summary->min, (std::array<double, 3>{-9.4688999999999995e-002, 4.0010999999999998e-002, -6.1872999999999997e-002}));
    EXPECT_EQ(*summary->max, (std::array<double, 3>{6.1008999999999994e-002, 1.8732099999999999e-001, 5.8798999999999997e-002}));
    ASSERT_EQ(summary->scans.size(), 1u);
    EXPECT_EQ(summary->scans[0].name, "bunny");
    EXPECT_EQ(summary->scans[0].guid, "{9CA24C38-C93E-40E8-A366-F49977C7E3EB}");
    EXPECT_FALSE(summary->scans[0].quaternion);

    const PointBatch all = readAll(fixture("bunnyDouble.e57"), {}, 4096);
    ASSERT_EQ(all.size(), 30571u);
    // The first doubles of the first packet's three bytestreams.
    EXPECT_EQ(all.positions[0], -0.07063);
    EXPECT_EQ(all.positions[1], 0.04015);
    EXPECT_EQ(all.positions[2], 0.0012259999999999999);
    EXPECT_EQ(all.positions[3], -0.070891);
}

TEST(E57Reader, SmallFixturesCountsAndFirstPoints)
{
    SKIP_WITHOUT_SHARED_DATA();
    {
        const PointBatch a4 = readAll(fixture("e57/A4.e57"));
        ASSERT_EQ(a4.size(), 4u);
        EXPECT_EQ(a4.positions[0], double(-44.30009841918945f));
        EXPECT_EQ(a4.positions[1], double(-1.132099986076355f));
        EXPECT_EQ(a4.positions[2], double(0.3357999920845032f));
        EXPECT_EQ(a4.colors, (std::vector<std::uint8_t>{0, 255, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0}));
        ASSERT_EQ(a4.scalars.size(), 1u);
        EXPECT_EQ(a4.scalars[0], (std::vector<double>{0, 0, 0, 0}));
    }
    {
        const PointBatch cube = readAll(fixture("e57/ColouredCubeFloat.e57"), {}, 1000);
        ASSERT_EQ(cube.size(), 7680u);
        EXPECT_EQ(cube.positions[0], -0.5);
        EXPECT_EQ(cube.positions[1], double(-0.4990559220314026f));
        EXPECT_EQ(cube.positions[2], double(0.07136291265487671f));
        EXPECT_EQ((std::vector<std::uint8_t>(cube.colors.begin(), cube.colors.begin() + 3)),
                  (std::vector<std::uint8_t>{0, 0, 255}));
    }
    {
        // ScaledInteger coordinates in 10 bits (−500..500, scale 0.001); 16-bit colours without colorLimits.
        const PointBatch las = readAll(fixture("e57/ColourRepresentation.e57"), {}, 64);
        ASSERT_EQ(las.size(), 153u);
        EXPECT_DOUBLE_EQ(las.positions[0], -0.5);
        EXPECT_DOUBLE_EQ(las.positions[1], -15 * 1.00000000000000002e-03);
        EXPECT_DOUBLE_EQ(las.positions[2], -432 * 1.00000000000000002e-03);
        EXPECT_DOUBLE_EQ(las.positions[3], -0.5);
        EXPECT_DOUBLE_EQ(las.positions[4], 169 * 1.00000000000000002e-03);
        EXPECT_EQ((std::vector<std::uint8_t>(las.colors.begin(), las.colors.begin() + 3)),
                  (std::vector<std::uint8_t>{0, 0, 254})); // 65280 of 0..65535
    }
    {
        auto zero = summarizePointFile(fixture("e57/ZeroPoints.e57"));
        ASSERT_TRUE(zero) << zero.error().message;
        EXPECT_EQ(zero->points, 0u);
        EXPECT_EQ(zero->declaredPoints, 0u);
        EXPECT_FALSE(zero->min);
    }
}

TEST(E57Reader, TwoScansGiveTheUnionOrOne)
{
    SKIP_WITHOUT_SHARED_DATA();
    auto both = summarizePointFile(fixture("e57/A_B.e57"));
    ASSERT_TRUE(both) << both.error().message;
    EXPECT_EQ(both->points, 6u);
    ASSERT_EQ(both->scans.size(), 2u);
    EXPECT_EQ(both->scans[0].name, "B2 - Cloud");
    EXPECT_EQ(both->scans[0].points, 2u);
    EXPECT_EQ(both->scans[1].name, "A4 - Cloud");
    EXPECT_EQ(both->scans[1].points, 4u);
    // Union of the two scans' cartesianBounds (no pose in the file: identity).
    EXPECT_DOUBLE_EQ((*both->min)[0], double(-4.49522018e+001f));
    EXPECT_DOUBLE_EQ((*both->max)[0], double(-4.26394997e+001f));
    EXPECT_DOUBLE_EQ((*both->min)[1], double(-1.34930003f));
    EXPECT_DOUBLE_EQ((*both->max)[1], double(2.05780005f));
    ReadOptions second;
    second.scan = 1;
    auto a4 = summarizePointFile(fixture("e57/A_B.e57"), second);
    ASSERT_TRUE(a4) << a4.error().message;
    EXPECT_EQ(a4->points, 4u);
    EXPECT_EQ(a4->declaredPoints, 4u);
    EXPECT_DOUBLE_EQ((*a4->max)[0], double(-4.43000984e+001f));
}

TEST(E57Reader, InvalidFixturesAreRefusedWithTheirProblem)
{
    SKIP_WITHOUT_SHARED_DATA();
    const fs::path crc = fixture("e57/invalid/bad-crc.e57");
    EXPECT_EQ(openError(crc, ErrorCode::Malformed),
              crc.string() + ": page 0 (byte 0): checksum mismatch (stored 0x1392E413, computed 0x360E223D): the page is damaged");
    const fs::path empty = fixture("e57/invalid/empty.e57");
    EXPECT_EQ(openError(empty, ErrorCode::Empty), empty.string() + ": the file holds no scan (its /data3D list is empty): no points");
    const fs::path cv = fixture("e57/invalid/InvalidCVHeader.e57");
    EXPECT_EQ(openError(cv, ErrorCode::Malformed),
              cv.string() + ": byte 48: scan 0: invalid compressed-vector section header: section id 182, expected 1");
}
