// XXH64 (libxxhash behind our API) against published test vectors, incremental hashing in arbitrary
// pieces and copies (its speed: BM_Xxh64, tests/benchmarks/FileOpenBenchmark.cpp). Golden digests of real files:
// Hash64FixtureTest.cpp.
#include "stylos/core/util/Hash64.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

using stylos::core::Hash64;
using stylos::core::xxh64;

namespace {

std::uint64_t ofString(const std::string& s, std::uint64_t seed = 0)
{
    return xxh64(s.data(), s.size(), seed);
}

} // namespace

TEST(Hash64, PublishedVectors)
{
    // Vectors published with xxHash and its ports (python-xxhash, LLVM's xxhashTest.cpp, ClickHouse).
    EXPECT_EQ(ofString(""), 0xEF46DB3751D8E999ull);
    EXPECT_EQ(xxh64(nullptr, 0), 0xEF46DB3751D8E999ull);
    EXPECT_EQ(ofString("a"), 0xD24EC4F1A98C6E5Bull);
    EXPECT_EQ(ofString("a"), 15154266338359012955ull);
    EXPECT_EQ(ofString("ab"), 7347350983217793633ull);
    EXPECT_EQ(ofString("abc"), 0x44BC2CF5AD770999ull);
    EXPECT_EQ(ofString("foo"), 0x33BF00A859C4BA3Full);
    EXPECT_EQ(ofString("bar"), 0x48A37C90AD27A659ull);
    EXPECT_EQ(ofString("xxhash"), 0x32DD38952C4BC720ull);
    EXPECT_EQ(ofString("ABC"), 0xE66AE7354FCFEE98ull);
    // 31 bytes: no stripe, tail of 8 + 8 + 8 + 4 + 3.
    EXPECT_EQ(ofString("abcdefghijklmnopqrstuvwxyz12345"), 0x467605901B01D6F6ull);
    // 36 bytes: one 32-byte stripe, then a 4-byte tail.
    EXPECT_EQ(ofString("0123456789abcdefghijklmnopqrstuvwxyz"), 0x69196C1B3AF0BFF9ull);
}

TEST(Hash64, PublishedVectorsWithSeed)
{
    EXPECT_EQ(ofString("", 668718853), 0x04E830582A31A119ull);
    EXPECT_EQ(ofString("a", 191961062), 0x6E05BA2887C97977ull);
    EXPECT_EQ(ofString("abcdefghijklmnopqrstuvwxyz12345", 877380273), 0x37B562EC5715E132ull);
    EXPECT_EQ(ofString("", 0x1234567890ABCDEFull), 0xA2F5C44D0F46C872ull);
    EXPECT_EQ(ofString("0"), 0x633457081244AFECull);
    EXPECT_EQ(ofString("0", 0x1234567890ABCDEFull), 0xF47EBF7F5CB6795Bull);
    EXPECT_EQ(ofString("0123"), 0x4C33072B45647DCBull);
    EXPECT_EQ(ofString("0123", 0x1234567890ABCDEFull), 0xE19FFF0227E3B861ull);
}

TEST(Hash64, IncrementalEqualsOneShotForAnySplit)
{
    std::mt19937_64 rng(11);
    std::vector<std::uint8_t> data(1000);
    for (auto& b : data) b = static_cast<std::uint8_t>(rng());
    for (std::size_t size : {0u, 1u, 3u, 4u, 7u, 8u, 31u, 32u, 33u, 63u, 64u, 65u, 100u, 1000u}) {
        const std::uint64_t expected = xxh64(data.data(), size, 42);
        for (int trial = 0; trial < 20; ++trial) {
            Hash64 h(42);
            std::size_t at = 0;
            while (at < size) {
                const std::size_t piece = std::min<std::size_t>(size - at, rng() % 40);
                h.update(data.data() + at, piece);
                at += piece;
            }
            EXPECT_EQ(h.digest(), expected) << size;
            EXPECT_EQ(h.length(), size);
        }
    }
    // digest() does not end the stream.
    Hash64 h;
    h.update("ab", 2);
    EXPECT_EQ(h.digest(), ofString("ab"));
    h.update("c", 1);
    EXPECT_EQ(h.digest(), ofString("abc"));
}

TEST(Hash64, CopiesHashOnIndependently)
{
    Hash64 a(7);
    a.update("abc", 3);
    Hash64 b = a;
    b.update("def", 3);
    EXPECT_EQ(a.digest(), ofString("abc", 7));
    EXPECT_EQ(b.digest(), ofString("abcdef", 7));
    EXPECT_EQ(b.length(), 6u);
    a = b;
    a.update("g", 1);
    EXPECT_EQ(a.digest(), ofString("abcdefg", 7));
    EXPECT_EQ(b.digest(), ofString("abcdef", 7));
    const Hash64 moved = std::move(a);
    EXPECT_EQ(moved.digest(), ofString("abcdefg", 7));
    EXPECT_EQ(moved.length(), 7u);
}

TEST(Hash64, EveryByteMatters)
{
    std::vector<std::uint8_t> data(257, 0x5A);
    const std::uint64_t base = xxh64(data.data(), data.size());
    for (std::size_t i = 0; i < data.size(); ++i) {
        data[i] ^= 0x01;
        EXPECT_NE(xxh64(data.data(), data.size()), base) << i;
        data[i] ^= 0x01;
    }
    EXPECT_NE(xxh64(data.data(), data.size() - 1), base);
}
