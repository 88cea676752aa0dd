#include "HorizonSources.h"

#include "ParallelChunks.h"
#include "stylos/core/util/HugePages.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace stylos::core::shading::detail {
namespace {

/** Side of the square tiles of the copies: 64 × 64 floats. */
constexpr int kTile = 64;

/** Calls f(r, c) for every pixel of the grid tile by tile, rows of tiles shared among the threads. */
template <typename F>
void forEachTiled(int width, int height, unsigned threads, const F& f)
{
    const std::size_t rows = std::size_t((height + kTile - 1) / kTile);
    parallelChunks(rows, 1, threads, nullptr, [&](std::size_t tileRow, std::size_t, unsigned) {
        const int r0 = int(tileRow) * kTile, r1 = std::min(height, r0 + kTile);
        for (int c0 = 0; c0 < width; c0 += kTile) {
            const int c1 = std::min(width, c0 + kTile);
            for (int r = r0; r < r1; ++r)
                for (int c = c0; c < c1; ++c) f(r, c);
        }
    });
}

} // namespace

void assignZeros(std::vector<float>& buffer, std::size_t count)
{
    buffer.clear();
    buffer.reserve(count);
    adviseHugePages(buffer.data(), count * sizeof(float)); // before the first touch
    buffer.resize(count, 0.0f);
}

void transposeBack(float* out, const float* transposed, int width, int height, unsigned threads)
{
    const std::size_t w = std::size_t(width), h = std::size_t(height);
    forEachTiled(width, height, threads, [&](int r, int c) {
        out[std::size_t(r) * w + std::size_t(c)] = transposed[std::size_t(c) * h + std::size_t(r)];
    });
}

BandSource copyField(float* out, const HeightField& field, bool transposed, unsigned threads)
{
    const float* heights = field.heights().data();
    const PixelState* states = field.states().data();
    const std::size_t w = std::size_t(field.width()), h = std::size_t(field.height());
    forEachTiled(field.width(), field.height(), threads, [&](int r, int c) {
        const std::size_t i = std::size_t(r) * w + std::size_t(c);
        const float value = states[i] == PixelState::Empty ? std::numeric_limits<float>::quiet_NaN() : heights[i];
        out[transposed ? std::size_t(c) * h + std::size_t(r) : i] = value;
    });
    return BandSource{out, transposed ? h : w};
}

} // namespace stylos::core::shading::detail
