// NormalEncoder must give encodeNormal()'s code bit for bit: the builders depend on it for their output
// to equal the reference's.
#include "stylos/core/octree/NormalEncoder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace stylos::core::octree;

namespace {

void expectSame(const NormalEncoder& e, float x, float y, float z)
{
    ASSERT_EQ(e(x, y, z), encodeNormal(e.kind(), x, y, z)) << x << " " << y << " " << z;
}

} // namespace

TEST(NormalEncoder, EqualsEncodeNormalOnEveryCodesDirectionAndItsMultiples)
{
    for (NormalCodeKind kind : {NormalCodeKind::Octahedral16, NormalCodeKind::Paper15}) {
        const NormalEncoder e(kind);
        const auto* table = normalDecodeTable(kind);
        for (std::size_t c = 0; c < normalCodeCount(kind); ++c) {
            const auto& d = table[c];
            expectSame(e, d[0], d[1], d[2]);
            expectSame(e, d[0] * 3.0f + 0.25f, d[1] * 3.0f, d[2] * 3.0f - 0.125f);
        }
    }
}

TEST(NormalEncoder, EqualsEncodeNormalOnRandomAndDegenerateVectors)
{
    const NormalEncoder e(NormalCodeKind::Octahedral16);
    std::mt19937_64 random(5);
    std::normal_distribution<float> gauss;
    std::uniform_int_distribution<int> small(-3, 3);
    for (int i = 0; i < 300000; ++i) {
        expectSame(e, gauss(random), gauss(random), gauss(random));
        // Grid-aligned and axis-aligned directions, where ties and folds happen.
        expectSame(e, float(small(random)), float(small(random)), float(small(random)));
    }
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (float v : {0.0f, -0.0f, 1e-38f, 1e-45f, 3e38f, inf, -inf, nan}) {
        expectSame(e, v, 0, 0);
        expectSame(e, 0, v, -0.0f);
        expectSame(e, v, v, v);
        expectSame(e, -v, 1, v);
    }
}

TEST(NormalEncoder, BatchEncodingEqualsEncodeNormal)
{
    // Random unit and non-unit normals, every code's direction, and special values mixed in, in an odd
    // count (the last one alone).
    std::mt19937_64 random(9);
    std::normal_distribution<float> gauss;
    std::vector<std::array<float, 3>> normals;
    for (int i = 0; i < 200001; ++i) normals.push_back({gauss(random), gauss(random), gauss(random)});
    const auto* table = normalDecodeTable(NormalCodeKind::Octahedral16);
    for (std::size_t c = 0; c < normalCodeCount(NormalCodeKind::Octahedral16); ++c) normals.push_back(table[c]);
    const float inf = std::numeric_limits<float>::infinity();
    for (std::size_t i : {std::size_t(0), std::size_t(7), std::size_t(1000), std::size_t(50001)}) {
        normals[i] = {0, 0, 0};
        normals[i + 2] = {inf, 1, 0};
        normals[i + 3] = {std::numeric_limits<float>::quiet_NaN(), 0, 1};
        normals[i + 5] = {-0.0f, 0, -1e-40f};
    }
    for (NormalCodeKind kind : {NormalCodeKind::Octahedral16, NormalCodeKind::Paper15}) {
        const NormalEncoder e(kind);
        std::vector<std::uint16_t> codes(normals.size());
        e.encode(normals, codes);
        for (std::size_t i = 0; i < normals.size(); ++i)
            ASSERT_EQ(codes[i], encodeNormal(kind, normals[i][0], normals[i][1], normals[i][2])) << i;
    }
}
