#pragma once
// Internal to the skydome: the field as the horizon bands read it, and the transposes between layouts.
#include "HorizonBand.h"
#include "stylos/core/shading/HeightField.h"

#include <vector>

namespace stylos::core::shading::detail {

/**
 * Fills @p out (pixelCount floats) with the field's heights, Empty pixels as NaN, row-major (for the
 * row-major rasters: a step is a row) or transposed (for the column-major ones: a step is a column, a
 * row of the copy), so that the 16 pixels of a step are contiguous; returns where the bands read it.
 * In parallel, in cache-sized tiles.
 */
BandSource copyField(float* out, const HeightField& field, bool transposed, unsigned threads);

/**
 * Sizes @p buffer to @p count zeros, asking the kernel (Linux) for huge pages first: a band touches a
 * new row, so a new 4 KiB page, at every step, and a TLB miss costs about as much as the cache miss.
 */
void assignZeros(std::vector<float>& buffer, std::size_t count);

/** out[r · width + c] = transposed[c · height + r] for every pixel, in parallel. */
void transposeBack(float* out, const float* transposed, int width, int height, unsigned threads);

} // namespace stylos::core::shading::detail
