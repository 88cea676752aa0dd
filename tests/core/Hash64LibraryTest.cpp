// Before replacing the hand-written XXH64 by Debian's libxxhash: both give the same digests on every
// shared fixture (whole files, slices of 0..64 bytes at misaligned starts, long misaligned slices,
// several seeds), on random buffers of every length up to 1 KiB, and in incremental use.
// Prints the digests that the golden test keeps once the hand-written code is gone.
#include "stylos/core/util/Hash64.h"

#include "TestSupport.h"

#include <gtest/gtest.h>
#include <xxhash.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

namespace fs = std::filesystem;
using stylos::core::Hash64;
using stylos::core::xxh64;

namespace {

constexpr std::uint64_t Seeds[] = {0, 1, 0x9E3779B97F4A7C15ull};

std::vector<fs::path> fixtureFiles()
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(stylos::test::sharedData()))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    files.push_back(fs::path(STYLOS_TEST_DATA) / "fragment-v1.poct");
    return files;
}

std::uint64_t libraryStreaming(const std::uint8_t* p, std::size_t n, std::uint64_t seed, std::mt19937_64& rng)
{
    XXH64_state_t* state = XXH64_createState();
    XXH64_reset(state, seed);
    for (std::size_t at = 0; at < n;) {
        const std::size_t piece = std::min<std::size_t>(n - at, rng() % 100000);
        XXH64_update(state, p + at, piece);
        at += piece;
    }
    const std::uint64_t h = XXH64_digest(state);
    XXH64_freeState(state);
    return h;
}

} // namespace

TEST(Hash64Library, SameDigestsOnSharedFixtures)
{
    SKIP_WITHOUT_SHARED_DATA();
    std::mt19937_64 rng(7);
    std::size_t compared = 0;
    for (const fs::path& file : fixtureFiles()) {
        const std::vector<char> chars = stylos::test::readBytes(file);
        const auto* p = reinterpret_cast<const std::uint8_t*>(chars.data());
        const std::size_t n = chars.size();
        const std::string name = file.filename() == "fragment-v1.poct"
                                     ? file.filename().string()
                                     : fs::relative(file, stylos::test::sharedData()).string();
        for (std::uint64_t seed : Seeds) {
            ASSERT_EQ(xxh64(p, n, seed), XXH64(p, n, seed)) << name;
            Hash64 mine(seed);
            for (std::size_t at = 0; at < n;) {
                const std::size_t piece = std::min<std::size_t>(n - at, rng() % 100000);
                mine.update(p + at, piece);
                at += piece;
            }
            ASSERT_EQ(mine.digest(), libraryStreaming(p, n, seed, rng)) << name;
            for (std::size_t start : {0u, 1u, 3u, 5u, 7u, 13u})
                for (std::size_t len = 0; len <= 64 && start + len <= n; ++len, ++compared)
                    ASSERT_EQ(xxh64(p + start, len, seed), XXH64(p + start, len, seed)) << name << " " << start;
            for (std::size_t start : {1u, 3u, 7u, 31u, 33u})
                if (start < n) {
                    ASSERT_EQ(xxh64(p + start, n - start, seed), XXH64(p + start, n - start, seed)) << name;
                }
        }
        // The values the golden test keeps: the whole file, and a misaligned slice that drops 5 bytes at the end.
        const std::size_t sliceLength = n > 12 ? n - 12 : 0;
        std::printf("        {\"%s\", 0x%016llXull, 0x%016llXull},\n", name.c_str(),
                    static_cast<unsigned long long>(xxh64(p, n)),
                    static_cast<unsigned long long>(xxh64(p + std::min<std::size_t>(7, n), sliceLength)));
        ++compared;
    }
    EXPECT_GT(compared, 1000u);
    // Every length 0..64 from byte 1 of the Igea scan (the tail cases of XXH64), seed 0.
    const std::vector<char> igea = stylos::test::readBytes(stylos::test::sharedData() / "scans/igea_134k.ply");
    for (std::size_t len = 0; len <= 64; ++len)
        std::printf("0x%016llXull,%s", static_cast<unsigned long long>(xxh64(igea.data() + 1, len)),
                    len % 4 == 3 ? "\n" : " ");
    std::printf("\n");
}

TEST(Hash64Library, SameDigestsOnRandomBuffersOfEveryLength)
{
    std::mt19937_64 rng(3);
    std::vector<std::uint8_t> data(1024 + 8);
    for (auto& b : data) b = static_cast<std::uint8_t>(rng());
    for (std::size_t len = 0; len <= 1024; ++len)
        for (std::size_t start : {0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u})
            for (std::uint64_t seed : Seeds) {
                ASSERT_EQ(xxh64(data.data() + start, len, seed), XXH64(data.data() + start, len, seed)) << len;
                Hash64 mine(seed);
                mine.update(data.data() + start, len / 3);
                mine.update(data.data() + start + len / 3, len - len / 3);
                ASSERT_EQ(mine.digest(), XXH64(data.data() + start, len, seed)) << len;
            }
}
