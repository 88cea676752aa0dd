#include "HorizonSources.h"

#include "ParallelChunks.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace stylos::core::shading::detail {
namespace {

/** Side of the square tiles of the transposes: 64 × 64 floats, 16 KiB a side of the copy. */
constexpr int kTile = 64;

/** Calls f(r, c) for every pixel of the grid, tile by tile, the tiles' rows of tiles shared among threads. */
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

/** out[c · height + r] = f(r · width + c) for the width × height grid. */
template <typename F>
void transposeInto(float* out, int width, int height, unsigned threads, const F& f)
{
    const std::size_t w = std::size_t(width), h = std::size_t(height);
    forEachTiled(width, height, threads, [&](int r, int c) {
        out[std::size_t(c) * h + std::size_t(r)] = f(std::size_t(r) * w + std::size_t(c));
    });
}

} // namespace

void addTransposed(float* sum, const float* transposed, int width, int height, unsigned threads)
{
    const std::size_t w = std::size_t(width), h = std::size_t(height);
    forEachTiled(width, height, threads, [&](int r, int c) {
        sum[std::size_t(r) * w + std::size_t(c)] += transposed[std::size_t(c) * h + std::size_t(r)];
    });
}

HorizonSources::HorizonSources(const HeightField& field, bool transposed, unsigned threads) : m_field(field)
{
    if (!transposed) return;
    m_transposed.resize(field.pixelCount());
    const float* heights = field.heights().data();
    const PixelState* states = field.states().data();
    transposeInto(m_transposed.data(), field.width(), field.height(), threads, [&](std::size_t i) {
        return states[i] == PixelState::Empty ? std::numeric_limits<float>::quiet_NaN() : heights[i];
    });
}

BandSource HorizonSources::source(const DirectionRaster& raster) const
{
    if (!raster.columnMajor())
        return BandSource{m_field.heights().data(), reinterpret_cast<const std::uint8_t*>(m_field.states().data()),
                          std::size_t(m_field.width())};
    assert(m_transposed.size() == m_field.pixelCount() && "HorizonSources::source(): no transposed copy");
    return BandSource{m_transposed.data(), nullptr, std::size_t(m_field.height())};
}

} // namespace stylos::core::shading::detail
