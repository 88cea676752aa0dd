// Image writer: every format written then read back with OpenImageIO (exact samples, alpha from
// coverage, float heights, resolution and text metadata), the refused combinations, and atomicity.
#include "stylos/core/image/ImageWriter.h"

#include "TestSupport.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::image;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

/** 4 × 2: row 0 = 0, 0.5, 1, 0.25; row 1 = 0.75, uncovered 0.7, -0.5 (clamped), NaN (→ 0). */
shading::ShadedImage sampleShading(double pixelSize = 0.0005)
{
    shading::ShadedImage image;
    image.width = 4;
    image.height = 2;
    image.pixelSize = pixelSize;
    image.values = {0.0f, 0.5f, 1.0f, 0.25f, 0.75f, 0.7f, -0.5f, std::numeric_limits<float>::quiet_NaN()};
    image.coverage = {1, 1, 1, 1, 1, 0, 1, 1};
    return image;
}

/** 3 × 2 heights: measured, filled and empty pixels. */
shading::HeightField sampleHeights()
{
    auto field = shading::HeightField::create(3, 2, 0.0005).value();
    field.setMeasured(0, 0, -0.00123f);
    field.setMeasured(1, 0, 0.0456f);
    field.setFilled(2, 0, 1.0e-7f);
    field.setMeasured(0, 1, 12.5f);
    // (1, 1) and (2, 1) stay Empty
    return field;
}

struct ReadBack {
    OIIO::ImageSpec spec;
    std::vector<double> samples; ///< interleaved, converted to double from the requested type
};

/** Reads @p path as @p type without OIIO's alpha premultiplication; samples as raw integers or floats. */
ReadBack readBack(const fs::path& path, OIIO::TypeDesc type)
{
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path.string(), &config);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return {};
    ReadBack r{in->spec(), {}};
    const std::size_t count = std::size_t(r.spec.width) * r.spec.height * r.spec.nchannels;
    r.samples.resize(count);
    if (type == OIIO::TypeDesc::UINT8) {
        std::vector<std::uint8_t> raw(count);
        EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, type, raw.data()));
        r.samples.assign(raw.begin(), raw.end());
    } else if (type == OIIO::TypeDesc::UINT16) {
        std::vector<std::uint16_t> raw(count);
        EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, type, raw.data()));
        r.samples.assign(raw.begin(), raw.end());
    } else {
        std::vector<float> raw(count);
        EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, raw.data()));
        r.samples.assign(raw.begin(), raw.end());
    }
    return r;
}

/** A string attribute as std::string (readable test failures); "" when absent. */
std::string text(const OIIO::ImageSpec& spec, const char* name)
{
    return std::string(spec.get_string_attribute(name));
}

/** The resolution read back, converted to pixels per cm (NaN when absent or in an unknown unit). */
double pixelsPerCm(const OIIO::ImageSpec& spec)
{
    const float x = spec.get_float_attribute("XResolution", 0.0f);
    const std::string unit = text(spec, "ResolutionUnit");
    if (x <= 0.0f) return std::nan("");
    if (unit == "cm") return x;
    if (unit == "in" || unit == "inch") return x / 2.54;
    if (unit == "m") return x / 100.0;
    return std::nan("");
}

/** The pHYs chunk of a PNG: {x, y, unit} (all 0 when absent). */
std::vector<std::uint32_t> pngPhys(const fs::path& path)
{
    const auto bytes = stylos::test::readBytes(path);
    auto be32 = [&](std::size_t at) {
        return (std::uint32_t(std::uint8_t(bytes[at])) << 24) | (std::uint32_t(std::uint8_t(bytes[at + 1])) << 16)
               | (std::uint32_t(std::uint8_t(bytes[at + 2])) << 8) | std::uint32_t(std::uint8_t(bytes[at + 3]));
    };
    for (std::size_t at = 8; at + 8 <= bytes.size();) { // chunks: length, type, data, CRC
        const std::uint32_t length = be32(at);
        if (std::string(&bytes[at + 4], 4) == "pHYs" && length == 9)
            return {be32(at + 8), be32(at + 12), std::uint32_t(std::uint8_t(bytes[at + 16]))};
        at += 12 + length;
    }
    return {0, 0, 0};
}

std::vector<std::string> folderEntries(const fs::path& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/** Asks to cancel once the writer has reported any progress (after its first group of rows). */
class CancelAfterFirstUpdate final : public ProgressSink {
public:
    void update(double fraction) override { m_updates.push_back(fraction); }
    bool isCancelRequested() const override { return !m_updates.empty(); }
    std::vector<double> m_updates;
};

} // namespace

TEST(ImageWriter, Png8BitRoundsToNearestWithCoverageAsAlpha)
{
    TempDir dir;
    const auto path = dir / "shade.png";
    ASSERT_TRUE(writeShadedImage(sampleShading(), path).ok());
    const auto r = readBack(path, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(r.spec.format, OIIO::TypeDesc::UINT8); // the .png default
    ASSERT_EQ(r.spec.nchannels, 2);
    EXPECT_EQ(r.spec.alpha_channel, 1);
    // 0.5 · 255 = 127.5 → 128; 0.25 · 255 = 63.75 → 64; 0.75 · 255 = 191.25 → 191.
    const std::vector<double> expected = {0, 255, 128, 255, 255, 255, 64, 255, 191, 255, 0, 0, 0, 255, 0, 255};
    EXPECT_EQ(r.samples, expected);
}

TEST(ImageWriter, SixteenBitPngAndTiffRoundToNearest)
{
    TempDir dir;
    // 0.5 · 65535 = 32767.5 → 32768; 0.25 · 65535 = 16383.75 → 16384; 0.75 · 65535 = 49151.25 → 49151.
    const std::vector<double> expected = {0,     65535, 32768, 65535, 65535, 65535, 16384, 65535,
                                          49151, 65535, 0,     0,     0,     65535, 0,     65535};
    ImageWriteOptions sixteen;
    sixteen.format = SampleFormat::UInt16;
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "shade.png", sixteen).ok());
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "shade.tif").ok()); // .tif default: 16-bit
    for (const char* name : {"shade.png", "shade.tif"}) {
        const auto r = readBack(dir / name, OIIO::TypeDesc::UINT16);
        EXPECT_EQ(r.spec.format, OIIO::TypeDesc::UINT16) << name;
        EXPECT_EQ(r.samples, expected) << name;
    }
}

TEST(ImageWriter, EightBitAndFloatTiffShadings)
{
    TempDir dir;
    ImageWriteOptions options;
    options.format = SampleFormat::UInt8;
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "shade8.TIFF", options).ok()); // extension case ignored
    auto r = readBack(dir / "shade8.TIFF", OIIO::TypeDesc::UINT8);
    EXPECT_EQ(r.spec.format, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(r.samples[2], 128.0);
    EXPECT_EQ(r.samples[6], 64.0);

    options.format = SampleFormat::Float32;
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "shadef.tif", options).ok());
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "shade.exr").ok()); // .exr default: float
    for (const char* name : {"shadef.tif", "shade.exr"}) {
        r = readBack(dir / name, OIIO::TypeDesc::FLOAT);
        EXPECT_EQ(r.spec.format, OIIO::TypeDesc::FLOAT) << name;
        const std::vector<double> expected = {0, 1, 0.5, 1, 1, 1, 0.25, 1, 0.75, 1, 0, 0, 0, 1, 0, 1};
        EXPECT_EQ(r.samples, expected) << name;
    }
}

TEST(ImageWriter, HeightsAreExactFloatsWithAlphaOnNonEmptyPixels)
{
    TempDir dir;
    const auto field = sampleHeights();
    for (const char* name : {"h.tif", "h.exr"}) {
        ASSERT_TRUE(writeHeightImage(field, dir / name).ok()) << name;
        const auto r = readBack(dir / name, OIIO::TypeDesc::FLOAT);
        EXPECT_EQ(r.spec.format, OIIO::TypeDesc::FLOAT) << name;
        ASSERT_EQ(r.spec.nchannels, 2);
        EXPECT_EQ(r.spec.channelnames[0], "Y");
        EXPECT_EQ(r.spec.channelnames[1], "A");
        const std::vector<double> expected = {-0.00123f, 1, 0.0456f, 1, 1.0e-7f, 1, 12.5f, 1, 0, 0, 0, 0};
        EXPECT_EQ(r.samples, expected) << name;
        EXPECT_EQ(text(r.spec, "ImageDescription"), "stylos:content=height_m\nstylos:pixel_size_m=0.0005");
    }
}

TEST(ImageWriter, ResolutionGivesThePixelSize)
{
    TempDir dir;
    for (const double pixelSize : {0.0005, 0.0003, 0.002}) {
        const double expected = 0.01 / pixelSize; // pixels per cm
        const auto image = sampleShading(pixelSize);
        ASSERT_TRUE(writeShadedImage(image, dir / "r.png").ok());
        ASSERT_TRUE(writeShadedImage(image, dir / "r.tif").ok());
        ASSERT_TRUE(writeShadedImage(image, dir / "r.exr").ok());
        // PNG: whole pixels per metre in pHYs (unit 1 = metre), e.g. 3333 for 0.3 mm.
        const auto phys = pngPhys(dir / "r.png");
        const std::uint32_t perMetre = std::uint32_t(std::lround(1.0 / pixelSize));
        EXPECT_EQ(phys, (std::vector<std::uint32_t>{perMetre, perMetre, 1})) << pixelSize;
        EXPECT_NEAR(pixelsPerCm(readBack(dir / "r.png", OIIO::TypeDesc::UINT8).spec), expected, expected * 2e-4);
        const auto tiff = readBack(dir / "r.tif", OIIO::TypeDesc::UINT16).spec;
        EXPECT_EQ(text(tiff, "ResolutionUnit"), "cm");
        EXPECT_NEAR(tiff.get_float_attribute("YResolution"), expected, expected * 1e-6);
        EXPECT_NEAR(pixelsPerCm(tiff), expected, expected * 1e-6) << pixelSize;
        EXPECT_NEAR(pixelsPerCm(readBack(dir / "r.exr", OIIO::TypeDesc::FLOAT).spec), expected, expected * 1e-6)
            << pixelSize;
    }
}

TEST(ImageWriter, TextMetadataReadsBackInEveryFormat)
{
    TempDir dir;
    ImageWriteOptions options;
    options.metadata["stylos:shading"] = "skydome";
    options.metadata["delphi:drum"] = "Dancers Column, drum 2 — Δελφοί";
    const std::string description = "delphi:drum=Dancers Column, drum 2 — Δελφοί\nstylos:content=shading\n"
                                    "stylos:pixel_size_m=0.0005\nstylos:shading=skydome";
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "m.png", options).ok());
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "m.tif", options).ok());
    ASSERT_TRUE(writeShadedImage(sampleShading(), dir / "m.exr", options).ok());
    for (const char* name : {"m.png", "m.tif", "m.exr"}) {
        const auto spec = readBack(dir / name, OIIO::TypeDesc::FLOAT).spec;
        EXPECT_EQ(text(spec, "ImageDescription"), description) << name;
        EXPECT_EQ(text(spec, "Software"), "Stylos") << name;
    }
    for (const char* name : {"m.png", "m.exr"}) { // separate text attributes (TIFF keeps only the description)
        const auto spec = readBack(dir / name, OIIO::TypeDesc::FLOAT).spec;
        EXPECT_EQ(text(spec, "stylos:pixel_size_m"), "0.0005") << name;
        EXPECT_EQ(text(spec, "stylos:content"), "shading") << name;
        EXPECT_EQ(text(spec, "stylos:shading"), "skydome") << name;
        EXPECT_EQ(text(spec, "delphi:drum"), "Dancers Column, drum 2 — Δελφοί") << name;
    }
}

TEST(ImageWriter, PixelSizeTextReadsBackToTheSameDouble)
{
    TempDir dir;
    const double pixelSize = 0.1 + 0.2; // 0.30000000000000004: needs all 17 digits
    ASSERT_TRUE(writeShadedImage(sampleShading(pixelSize), dir / "p.exr").ok());
    const auto value = text(readBack(dir / "p.exr", OIIO::TypeDesc::FLOAT).spec, "stylos:pixel_size_m");
    EXPECT_EQ(value, "0.30000000000000004");
    EXPECT_EQ(std::stod(value), pixelSize);
}

TEST(ImageWriter, RefusesUnsupportedExtensionsAndSampleFormats)
{
    TempDir dir;
    ImageWriteOptions floatFormat, eightBit, sixteenBit;
    floatFormat.format = SampleFormat::Float32;
    eightBit.format = SampleFormat::UInt8;
    sixteenBit.format = SampleFormat::UInt16;
    const auto shading = sampleShading();
    const auto heights = sampleHeights();
    struct Case {
        Status status;
        fs::path path;
    };
    const std::vector<Case> cases = {
        {writeShadedImage(shading, dir / "a.jpg"), dir / "a.jpg"},
        {writeShadedImage(shading, dir / "noextension"), dir / "noextension"},
        {writeShadedImage(shading, dir / "f.png", floatFormat), dir / "f.png"},
        {writeShadedImage(shading, dir / "e8.exr", eightBit), dir / "e8.exr"},
        {writeShadedImage(shading, dir / "e16.exr", sixteenBit), dir / "e16.exr"},
        {writeHeightImage(heights, dir / "h.png"), dir / "h.png"},
        {writeHeightImage(heights, dir / "h16.tif", sixteenBit), dir / "h16.tif"},
        {writeHeightImage(heights, dir / "h.jpg"), dir / "h.jpg"},
    };
    for (const auto& c : cases) {
        ASSERT_FALSE(c.status.ok()) << c.path;
        EXPECT_EQ(c.status.error().code, ErrorCode::InvalidArgument) << c.path;
        EXPECT_NE(c.status.error().message.find(c.path.string()), std::string::npos) << c.status.error().message;
    }
    EXPECT_NE(cases[2].status.error().message.find("PNG cannot hold 32-bit float"), std::string::npos);
    EXPECT_TRUE(folderEntries(dir.path()).empty());
}

TEST(ImageWriter, RefusesBadGeometryAndMetadata)
{
    TempDir dir;
    const auto path = dir / "x.png";
    auto empty = sampleShading();
    empty.width = 0;
    empty.values.clear();
    empty.coverage.clear();
    EXPECT_EQ(writeShadedImage(empty, path).error().code, ErrorCode::InvalidArgument);
    for (const double pixelSize : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
        EXPECT_EQ(writeShadedImage(sampleShading(pixelSize), path).error().code, ErrorCode::InvalidArgument) << pixelSize;
    const std::vector<std::pair<std::string, std::string>> badEntries = {
        {"shading", "no namespace"},         {":x", "empty namespace"},          {"stylos:", "empty name"},
        {"oiio:ColorSpace", "steers OIIO"},  {"png:compressionLevel", "9"},  {"tiff:RowsPerStrip", "1"},
        {"openexr:lineOrder", "decreasingY"}, {"stylos:pixel_size_m", "1"},  {"stylos:content", "x"},
        {"stylos:with space", "x"},          {"stylos:x", "two\nlines"},     {"stylos:" + std::string(80, 'k'), "x"},
    };
    for (const auto& [key, value] : badEntries) {
        ImageWriteOptions options;
        options.metadata[key] = value;
        const auto status = writeShadedImage(sampleShading(), path, options);
        ASSERT_FALSE(status.ok()) << key;
        EXPECT_EQ(status.error().code, ErrorCode::InvalidArgument) << key;
        EXPECT_NE(status.error().message.find(path.string()), std::string::npos);
    }
    EXPECT_TRUE(folderEntries(dir.path()).empty());
}

TEST(ImageWriter, MissingFolderFailsAndLeavesNothing)
{
    TempDir dir;
    auto status = writeShadedImage(sampleShading(), dir / "missing" / "x.png");
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(status.error().message.find((dir / "missing" / "x.png").string()), std::string::npos);
    EXPECT_NE(status.error().message.find("does not exist"), std::string::npos) << status.error().message;

    stylos::test::writeText(dir / "plain", "a file, not a folder");
    status = writeHeightImage(sampleHeights(), dir / "plain" / "x.exr");
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"plain"});
}

TEST(ImageWriter, UnwritableFolderFailsAndLeavesNothing)
{
    if (geteuid() == 0) GTEST_SKIP() << "running as root: folder permissions are not enforced";
    TempDir dir;
    const auto locked = dir / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    const auto status = writeShadedImage(sampleShading(), locked / "x.tif");
    fs::permissions(locked, fs::perms::owner_all);
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(status.error().message.find((locked / "x.tif").string()), std::string::npos);
    EXPECT_NE(status.error().message.find("Permission denied"), std::string::npos) << status.error().message;
    EXPECT_TRUE(folderEntries(locked).empty());
}

TEST(ImageWriter, ExistingFileIsReplacedOnlyOnSuccess)
{
    TempDir dir;
    const auto path = dir / "out.png";
    stylos::test::writeText(path, "previous contents");
    auto big = sampleShading();
    big.width = 16;
    big.height = 300; // several groups of 64 rows: the cancel lands in the middle of the file
    big.values.assign(16 * 300, 0.5f);
    big.coverage.assign(16 * 300, 1);

    ImageWriteOptions floatPng;
    floatPng.format = SampleFormat::Float32;
    EXPECT_EQ(writeShadedImage(big, path, floatPng).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(stylos::test::readBytes(path).size(), std::string("previous contents").size());

    CancelAfterFirstUpdate cancel;
    ImageWriteOptions cancelling;
    cancelling.progress = &cancel;
    const auto status = writeShadedImage(big, path, cancelling);
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::Cancelled);
    EXPECT_NE(status.error().message.find("row 64"), std::string::npos) << status.error().message;
    EXPECT_EQ(cancel.m_updates, std::vector<double>{64.0 / 300.0});
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"out.png"}); // no temporary left
    EXPECT_EQ(stylos::test::readBytes(path).size(), std::string("previous contents").size());

    SilentProgress silent;
    ImageWriteOptions reporting;
    reporting.progress = &silent;
    ASSERT_TRUE(writeShadedImage(big, path, reporting).ok());
    EXPECT_EQ(silent.last(), 1.0);
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"out.png"});
    const auto r = readBack(path, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(r.spec.height, 300);
    EXPECT_EQ(r.samples[2 * 16 * 299], 128.0);
}

TEST(ImageWriter, TargetThatIsAFolderIsRefused)
{
    TempDir dir;
    fs::create_directory(dir / "taken.tif");
    stylos::test::writeText(dir / "taken.tif" / "inside", "x");
    const auto status = writeShadedImage(sampleShading(), dir / "taken.tif");
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(status.error().message.find("is a folder"), std::string::npos) << status.error().message;
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"taken.tif"});
    EXPECT_EQ(folderEntries(dir / "taken.tif"), std::vector<std::string>{"inside"});
}

// Timing, not run by default: --gtest_also_run_disabled_tests --gtest_filter='*Timing*'.
TEST(ImageWriter, DISABLED_Timing4096)
{
    TempDir dir(stylos::test::fastTempBase());
    const int side = 4096;
    shading::ShadedImage image;
    image.width = image.height = side;
    image.pixelSize = 0.0005;
    image.values.resize(std::size_t(side) * side);
    image.coverage.assign(std::size_t(side) * side, 1);
    std::uint32_t noise = 12345;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) { // a smooth relief plus a little noise, like a skydome shading
            noise = noise * 1664525u + 1013904223u;
            const double v = 0.5 + 0.3 * std::sin(x * 0.02) * std::cos(y * 0.015) + 0.05 * ((noise >> 8) / 16777216.0 - 0.5);
            image.values[std::size_t(y) * side + x] = float(v);
            if ((x - 3000) * (x - 3000) + (y - 1000) * (y - 1000) < 400 * 400) image.coverage[std::size_t(y) * side + x] = 0;
        }
    auto field = shading::HeightField::create(side, side, 0.0005).value();
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) field.setMeasured(x, y, float(0.002 * std::sin(x * 0.02) * std::cos(y * 0.015)));
    auto time = [&](const char* label, auto&& write, const char* name) {
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpuStart = std::clock();
        ASSERT_TRUE(write(dir / name).ok());
        const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%-22s wall %6.3f s  cpu %6.3f s  %5.1f MB\n", label, seconds, cpu, double(fs::file_size(dir / name)) / 1e6);
    };
    ImageWriteOptions sixteen;
    sixteen.format = SampleFormat::UInt16;
    time("PNG 8-bit shading", [&](const fs::path& p) { return writeShadedImage(image, p); }, "s8.png");
    time("PNG 16-bit shading", [&](const fs::path& p) { return writeShadedImage(image, p, sixteen); }, "s16.png");
    time("TIFF 16-bit shading", [&](const fs::path& p) { return writeShadedImage(image, p); }, "s16.tif");
    time("TIFF float heights", [&](const fs::path& p) { return writeHeightImage(field, p); }, "h.tif");
    time("EXR float heights", [&](const fs::path& p) { return writeHeightImage(field, p); }, "h.exr");
}
