// XXH64 (libxxhash) golden digests: the shared fixtures and the committed .poct, recorded when the
// hand-written XXH64 and libxxhash were compared on them and agreed (commit 8918b5c,
// Hash64LibraryTest): whole files, a misaligned slice, and every tail length 0..64.
#include "stylos/core/util/Hash64.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

namespace fs = std::filesystem;
using stylos::core::Hash64;
using stylos::core::xxh64;

namespace {

struct Golden {
    const char* file;         ///< under ../shared/data
    std::uint64_t whole;      ///< XXH64 of every byte, seed 0
    std::uint64_t misaligned; ///< XXH64 of bytes [7, size - 5), seed 0
};

constexpr Golden SharedFiles[] = {
    {"formats/autzen_trim.las", 0xFA44C7840CE31C94ull, 0xC80EE42DCCE05BDCull},
    {"formats/autzen_trim.laz", 0x12148396E022ACC5ull, 0x15624769A43863E4ull},
    {"formats/bun000_ascii_rangegrid.ply", 0xE59934D3A9E1E557ull, 0x405544636BFFC584ull},
    {"formats/bunnyDouble.e57", 0x47076C9693516F50ull, 0x492C02413B98C832ull},
    {"formats/cgal_kitten.xyz", 0x15EDD6A253BDD791ull, 0x1E7072FC43A3B553ull},
    {"formats/e57/A4.e57", 0x2E7DF7CCEBB3E903ull, 0x6B764C4D0EBC9E2Aull},
    {"formats/e57/A_B.e57", 0x37F4834E6718C327ull, 0x1B14DEDD87B82C96ull},
    {"formats/e57/ColourRepresentation.e57", 0x94CE8165A82F528Aull, 0xA07C1BE3308383C4ull},
    {"formats/e57/ColouredCubeFloat.e57", 0x0C4264527C63BDA4ull, 0x3F17394D5175ADCAull},
    {"formats/e57/ZeroPoints.e57", 0xC49F3CEB65C5EAC2ull, 0xA899A0F66678D3A8ull},
    {"formats/e57/invalid/InvalidCVHeader.e57", 0x903E4F832DF74B98ull, 0x946B6BA36006A28Full},
    {"formats/e57/invalid/bad-crc.e57", 0xD3F8F9AB401A2FE3ull, 0x294C8DCE9871DCD9ull},
    {"formats/e57/invalid/empty.e57", 0x1C3F4EB6D6A59191ull, 0xAC2F17839C46E108ull},
    {"formats/invalid/cube-ply-1.0_ascii-comment_renamed_to_remark-invalid.ply", 0x2B058EE7E6108E8Eull, 0x4E02C0C2960AF36Full},
    {"formats/invalid/cube-ply-1.0_binary-comment_renamed_to_remark-invalid.ply", 0x10D61B86CDFC5114ull, 0x4AF1A9509F1822BBull},
    {"formats/minimal-las-1.2-unmodified-valid.las", 0x05B69EB06AF37520ull, 0xB36CAAE55B23581Cull},
    {"formats/minimal-ply-1.0_ascii-unmodified-unknown.ply", 0x659ECB6D16733989ull, 0x1E13902AFD33E0BDull},
    {"formats/minimal-ply-1.0_binary-unmodified-unknown.ply", 0xEFCCBFFAB5CE06E5ull, 0xA237BB608F0AF02Full},
    {"formats/mvk-thin.las", 0x44E1BA95BEF87545ull, 0xC1BB53BF7C9F7CDCull},
    {"formats/pdal_test.pts", 0x486DA28B05C7913Dull, 0xCE324191C9EF0E4Eull},
    {"formats/ptx/1.2-with-color.ptx", 0x6056B86E4F8D4AF9ull, 0x13901907C106E0E3ull},
    {"formats/ptx/multiple-and-transform.ptx", 0x08ADF48288D53B24ull, 0x0FFBEF69CD932EBBull},
    {"scans/happy_buddha_1.1M.ply", 0xD3FE2354633A6DC5ull, 0xB5D2474A745B953Cull},
    {"scans/igea_134k.ply", 0x6072E674F4159D8Aull, 0x83E6158CC383B47Bull},
    {"scans/lion_takanawa_342k.ply", 0x280BD4AE07E16F05ull, 0xB59D2F9DA39ED776ull},
};

/** XXH64 (seed 0) of bytes [1, 1 + n) of scans/igea_134k.ply for n = 0..64: every tail case. */
constexpr std::array<std::uint64_t, 65> IgeaTails = {
    0xEF46DB3751D8E999ull, 0xF88DBA187615C755ull, 0x265A7A9445CC81D7ull, 0x302EE79FA13791E6ull,
    0x2A8393240757F98Full, 0x064BE438F684E39Cull, 0x12080CB4889EED4Dull, 0x778E43EA9E76822Full,
    0xC6AFBB7FD9267FDEull, 0xC1842C531D854EC5ull, 0x534E311DD3EE5DA4ull, 0xA0BAFEA1AC371D1Aull,
    0xAA06E1F8886AF8D8ull, 0x288F0626CF765DE6ull, 0xC2A8DD62BBC1CADAull, 0xA5975B40F2ABA63Dull,
    0x9FD06708D490615Dull, 0x8E1E1D7284E30402ull, 0x08B26718AD551736ull, 0xC54B49BEF0791D2Aull,
    0xC49BC8940E856940ull, 0xAEDC3EF09CA43E6Aull, 0xF429A67EB1B1407Cull, 0xCEE54D40EA4415E1ull,
    0x602C5D0930F87AFCull, 0xF2CE36859416B71Full, 0x1ABC0379D2CA2E61ull, 0xB38ADD67DA89AF5Bull,
    0x4569FF33829D1E45ull, 0xEEA7BE03CBC2BC73ull, 0x3876608B2CAF7DD1ull, 0x5458DD679A0A175Eull,
    0x92744DA4146AF8A8ull, 0x24BA2BD7BD3D1D87ull, 0xF557AEE84D5827D8ull, 0xC13C0D5F2A3E943Full,
    0x9FD7FDFE166C9915ull, 0x20B4FAE5647285B1ull, 0x070F0BDA6AEFE081ull, 0x03A858A93DCCF2DBull,
    0xC0DB991ED17BF4E0ull, 0x1EA0280B2AED814Dull, 0x3D8EDD79A7B2AD6Cull, 0xD61BC3E25352E435ull,
    0xBAE1259D4E74EE18ull, 0x5A5D121225E0722Aull, 0xDDBCCE3177FED5E1ull, 0x846A4E2453A21674ull,
    0xA662FCCC5A4BA884ull, 0x9EC124EDD549EC82ull, 0xFEA2E3BA6EABFB54ull, 0x258D2824EE41FBADull,
    0x4EA28ED235FCD1A4ull, 0x7630C523CB855889ull, 0x73DB5C9186D14276ull, 0x968EA8C97B8E86F0ull,
    0x004846075751B7EBull, 0xF43C3039BCDE0D1Bull, 0xED76BA42F19B71B3ull, 0xC25E6528EFA86AF2ull,
    0xD2A761805403D174ull, 0x605DCC0E0A55DF09ull, 0xEAD61E13C9DA2FCFull, 0x32328DE3CAF21ED2ull,
    0xB9D8F9EDA7DAA944ull,
};

std::uint64_t misalignedSlice(const std::vector<char>& bytes)
{
    const std::size_t n = bytes.size();
    return xxh64(bytes.data() + std::min<std::size_t>(7, n), n > 12 ? n - 12 : 0);
}

/** Hashed in pieces of random sizes, as the .poct writer's section streams do. */
std::uint64_t inPieces(const std::vector<char>& bytes, std::mt19937_64& rng)
{
    Hash64 h;
    for (std::size_t at = 0; at < bytes.size();) {
        const std::size_t piece = std::min<std::size_t>(bytes.size() - at, rng() % 100000);
        h.update(bytes.data() + at, piece);
        at += piece;
    }
    EXPECT_EQ(h.length(), bytes.size());
    return h.digest();
}

} // namespace

TEST(Hash64Fixture, SharedFilesKeepTheirDigests)
{
    SKIP_WITHOUT_SHARED_DATA();
    std::mt19937_64 rng(5);
    for (const Golden& g : SharedFiles) {
        const fs::path path = stylos::test::sharedData() / g.file;
        ASSERT_TRUE(fs::exists(path)) << path;
        const std::vector<char> bytes = stylos::test::readBytes(path);
        EXPECT_EQ(xxh64(bytes.data(), bytes.size()), g.whole) << g.file;
        EXPECT_EQ(misalignedSlice(bytes), g.misaligned) << g.file;
        EXPECT_EQ(inPieces(bytes, rng), g.whole) << g.file;
    }
}

TEST(Hash64Fixture, EveryTailLengthFromAMisalignedStart)
{
    SKIP_WITHOUT_SHARED_DATA();
    const std::vector<char> igea = stylos::test::readBytes(stylos::test::sharedData() / "scans/igea_134k.ply");
    ASSERT_GT(igea.size(), 65u);
    for (std::size_t n = 0; n <= 64; ++n) {
        EXPECT_EQ(xxh64(igea.data() + 1, n), IgeaTails[n]) << n;
        Hash64 h;
        h.update(igea.data() + 1, n / 2);
        h.update(igea.data() + 1 + n / 2, n - n / 2);
        EXPECT_EQ(h.digest(), IgeaTails[n]) << n;
    }
}

TEST(Hash64Fixture, CommittedOctreeKeepsItsDigest)
{
    // Needs no shared data: tests/data/fragment-v1.poct is in the repository.
    const std::vector<char> bytes = stylos::test::readBytes(fs::path(STYLOS_TEST_DATA) / "fragment-v1.poct");
    ASSERT_EQ(bytes.size(), 7548u);
    EXPECT_EQ(xxh64(bytes.data(), bytes.size()), 0x8EFC16F493E08EECull);
    EXPECT_EQ(misalignedSlice(bytes), 0x2EFBFDB849CBDF1Dull);
}
