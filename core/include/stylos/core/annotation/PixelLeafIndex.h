#pragma once
/** @file
 * @brief Both directions between a développée's pixels and the leaves of the octree it was made of: each
 *        leaf's pixel (as leafPixels() gives it, LabelRaster.h) and, for each pixel, its leaves (a CSR index:
 *        offsets per pixel into one array of leaf indices, ascending within a pixel). Built once per
 *        développée, in O(leaves + pixels); then painting a set of pixels finds its leaves, and a change of
 *        some leaves' labels finds the pixels to redraw, without touching the rest of the image.
 *
 * The pixel's shown label (majorityLabel) is the one labelRasterFromLeaves() gives: the most frequent label of
 * its leaves, 0 counting as a label, a tie going to the smaller id; 0 for a pixel without leaves. Nearest
 * neighbour only: no id is ever blended.
 * Memory: 4 bytes per leaf twice and 4 bytes per pixel. Limits: fewer than 2³² leaves and pixels (asserted).
 * Thread-safety: a value; const members are reentrant.
 */
#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::annotation {

class PixelLeafIndex {
public:
    PixelLeafIndex() = default;
    /** @brief From leafPixels() (one pixel index per leaf, −1 off the image) on a @p width × @p height grid;
     *         pixels outside the grid are asserted. */
    static PixelLeafIndex build(std::span<const std::int64_t> leafPixels, int width, int height);

    int width() const { return m_width; }
    int height() const { return m_height; }
    std::size_t pixelCount() const { return std::size_t(m_width) * std::size_t(m_height); }
    std::size_t leafCount() const { return m_leafPixel.size(); }
    /** @brief How many leaves land on some pixel. */
    std::size_t mappedLeafCount() const { return m_leaves.size(); }

    /** @brief The pixel of @p leaf (row · width + column), −1 when off the image or out of range. */
    std::int64_t pixelOf(std::uint32_t leaf) const { return leaf < m_leafPixel.size() ? m_leafPixel[leaf] : -1; }
    /** @brief The leaves of pixel @p pixel (< pixelCount(), asserted), ascending. */
    std::span<const std::uint32_t> leavesAt(std::uint32_t pixel) const;
    /** @brief The leaves of every pixel in @p pixels (any order; duplicates allowed): ascending, unique. */
    std::vector<std::uint32_t> leavesOf(std::span<const std::uint32_t> pixels) const;
    /** @brief The pixels of @p leaves (any order): ascending, unique, leaves off the image left out. */
    std::vector<std::uint32_t> pixelsOf(std::span<const std::uint32_t> leaves) const;

    /** @brief The label pixel @p pixel shows for per-leaf @p labels (leafCount() of them, asserted). */
    std::uint8_t majorityLabel(std::uint32_t pixel, std::span<const std::uint8_t> labels) const;
    /** @brief majorityLabel() of every pixel, row-major. */
    std::vector<std::uint8_t> majorityLabels(std::span<const std::uint8_t> labels) const;

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<std::int32_t> m_leafPixel; ///< per leaf; −1 off the image
    std::vector<std::uint32_t> m_offsets;  ///< pixelCount() + 1
    std::vector<std::uint32_t> m_leaves;   ///< leaves grouped by pixel
};

} // namespace stylos::core::annotation
