#pragma once
/** @file
 * @brief The output of every shading: one float per pixel in [0, 1] and a coverage flag, laid out like
 *        the HeightField it came from (row-major, row 0 at the top).
 *
 * Pixels whose height field pixel is Empty have coverage 0 and value 0: an exporter writes them
 * transparent (alpha = coverage). Units: values are dimensionless (grey level, cosine or fraction of
 * the sky); pixelSize is metres. Thread-safety: a value type.
 */
#include <cstddef>
#include <cstdint>
#include <vector>

namespace stylos::core::shading {

/** @brief A grey image in [0, 1] with a per-pixel coverage flag (1 = has a value, 0 = transparent). */
struct ShadedImage {
    int width = 0;
    int height = 0;
    double pixelSize = 1.0;          ///< metres, as the source field
    std::vector<float> values;       ///< width × height, row-major, in [0, 1]; 0 where coverage is 0
    std::vector<std::uint8_t> coverage; ///< width × height, 1 where the source pixel had a height

    float value(int column, int row) const { return values[std::size_t(row) * std::size_t(width) + std::size_t(column)]; }
    bool covered(int column, int row) const
    {
        return coverage[std::size_t(row) * std::size_t(width) + std::size_t(column)] != 0;
    }
};

} // namespace stylos::core::shading
