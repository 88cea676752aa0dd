// Every fixture truncated and corrupted at many offsets: each read either succeeds or fails with a
// one-line error that names the file and the position; never a crash, never a hang. Files with a
// fixed size implied by their header (binary PLY, LAS) must always fail when truncated.
#include "TestSupport.h"

#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/io/PointFileFormat.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace stylos::core;
using namespace stylos::core::io;
namespace fs = std::filesystem;
using stylos::test::TempDir;

namespace {

struct Outcome {
    bool ok = false;
    Error error{ErrorCode::Malformed, {}};
    std::uint64_t points = 0;
};

Outcome readEverything(const fs::path& path)
{
    Outcome out;
    auto reader = openPointReader(path);
    if (!reader) {
        out.error = reader.error();
        return out;
    }
    PointBatch batch;
    for (;;) {
        auto got = (*reader)->read(batch, 4096);
        if (!got) {
            out.error = got.error();
            return out;
        }
        if (*got == 0) break;
        for (double v : batch.positions)
            if (!std::isfinite(v)) {
                out.error = Error{ErrorCode::Malformed, "a non-finite coordinate was passed on"};
                return out;
            }
        out.points += *got;
    }
    out.ok = true;
    return out;
}

void expectCleanFailure(const Outcome& o, const fs::path& path, const std::string& what)
{
    static const std::set<ErrorCode> allowed = {ErrorCode::Malformed, ErrorCode::Truncated, ErrorCode::Empty,
                                                ErrorCode::UnknownFormat, ErrorCode::Unsupported};
    EXPECT_TRUE(allowed.count(o.error.code)) << what << ": " << o.error.message;
    EXPECT_EQ(o.error.message.rfind(path.string() + ": ", 0), 0u) << what << ": " << o.error.message;
    EXPECT_EQ(o.error.message.find('\n'), std::string::npos) << what << ": " << o.error.message;
    EXPECT_GT(o.error.message.size(), path.string().size() + 10) << what << ": " << o.error.message;
}

/** Offsets to cut or corrupt at: every few bytes in the first 512 (every 16 for files over 1 MB, which
 *  cost more to rewrite), then spread over the file. */
std::vector<std::size_t> offsetsFor(std::size_t size)
{
    const bool large = size > (1u << 20);
    std::vector<std::size_t> offsets;
    for (std::size_t o = 0; o < std::min<std::size_t>(size, 512); o += large ? 16 : 3) offsets.push_back(o);
    const int spread = large ? 12 : 40;
    for (int k = 1; k < spread; ++k) offsets.push_back(size * k / spread);
    offsets.push_back(size - 1);
    return offsets;
}

bool sizeFixedByHeader(const fs::path& original)
{
    const auto format = detectPointFormat(original);
    if (format == PointFormat::Las || format == PointFormat::E57) return true;
    if (format != PointFormat::Ply) return false;
    auto reader = openPointReader(original);
    return reader && (*reader)->header().format != "ply-ascii";
}

void tortureFile(const fs::path& original)
{
    SCOPED_TRACE(original.string());
    const Outcome baseline = readEverything(original);
    ASSERT_TRUE(baseline.ok) << baseline.error.message;
    const auto bytes = stylos::test::readBytes(original);
    const bool strict = sizeFixedByHeader(original);
    TempDir dir(stylos::test::fastTempBase());
    const fs::path cut = dir / ("cut" + original.extension().string());
    std::mt19937 rng(42);

    for (std::size_t offset : offsetsFor(bytes.size())) {
        if (offset >= bytes.size()) continue;
        stylos::test::writeBytes(cut, std::vector<char>(bytes.begin(), bytes.begin() + offset));
        const Outcome o = readEverything(cut);
        const std::string what = "truncated at " + std::to_string(offset);
        if (o.ok) {
            EXPECT_FALSE(strict) << what << " was accepted";
            EXPECT_LE(o.points, baseline.points) << what;
        } else {
            expectCleanFailure(o, cut, what);
        }

        const std::vector<char> patterns =
            bytes.size() > (1u << 20) ? std::vector<char>{'\xff', '9'} : std::vector<char>{'\xff', '\0', '9', '\n', '-'};
        for (const char pattern : patterns) {
            auto corrupt = bytes;
            const std::size_t len = std::min<std::size_t>(8, bytes.size() - offset);
            for (std::size_t i = 0; i < len; ++i) corrupt[offset + i] = pattern == '9' ? char('0' + rng() % 10) : pattern;
            stylos::test::writeBytes(cut, corrupt);
            const Outcome c = readEverything(cut);
            if (!c.ok) expectCleanFailure(c, cut, "corrupted at " + std::to_string(offset));
        }
    }
}

} // namespace

TEST(BadInput, GeneratedFixturesSurviveTruncationAndCorruption)
{
    TempDir dir;
    PointSchema schema{true, true, {"intensity"}};
    PointBatch batch;
    batch.reset(schema, 50);
    for (int i = 0; i < 50; ++i) {
        batch.positions.insert(batch.positions.end(), {i * 0.1, 1000.0 + i, -i * 0.5});
        batch.normals.insert(batch.normals.end(), {0.f, 0.f, 1.f});
        batch.colors.insert(batch.colors.end(), {std::uint8_t(i), 2, 3});
        batch.scalars[0].push_back(i);
    }
    for (auto positionType : {PlyScalarType::Float64, PlyScalarType::Float32}) {
        PlyWriterOptions options;
        options.positionType = positionType;
        auto w = PlyWriter::create(dir / "fixture.ply", schema, options);
        ASSERT_TRUE(w);
        ASSERT_TRUE(w->write(batch));
        ASSERT_TRUE(w->finish());
        tortureFile(dir / "fixture.ply");
    }
    std::string xyz = "# x y z nx ny nz\n";
    for (int i = 0; i < 50; ++i) xyz += std::to_string(i * 0.1) + " " + std::to_string(i) + " 3.5 0 0 1\n";
    stylos::test::writeText(dir / "fixture.xyz", xyz);
    tortureFile(dir / "fixture.xyz");
    std::string pts = "50\n";
    for (int i = 0; i < 50; ++i) pts += std::to_string(i * 0.1) + " " + std::to_string(i) + " 3.5 -1000 10 20 30\n";
    stylos::test::writeText(dir / "fixture.pts", pts);
    tortureFile(dir / "fixture.pts");
    std::string obj = "# cube\n";
    for (int i = 0; i < 20; ++i) obj += "v " + std::to_string(i) + " 1 2\nvn 0 0 1\n";
    obj += "f 1 2 3\n";
    stylos::test::writeText(dir / "fixture.obj", obj);
    tortureFile(dir / "fixture.obj");
}

TEST(BadInput, SharedFixturesSurviveTruncationAndCorruption)
{
    SKIP_WITHOUT_SHARED_DATA();
    for (const char* folder : {"formats", "formats/e57", "formats/ptx", "scans"})
        for (const auto& entry : fs::directory_iterator(stylos::test::sharedData() / folder)) {
            if (!entry.is_regular_file()) continue;
            const auto format = detectPointFormat(entry.path());
            if (format == PointFormat::Laz) continue; // refused whole, see CliInfo
            tortureFile(entry.path());
        }
}
