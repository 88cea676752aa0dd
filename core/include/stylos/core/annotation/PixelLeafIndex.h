#pragma once
/** @file
 * @brief Both directions between a développée's pixels and the leaves of the octree it was made of: each
 *        leaf's pixel (as leafPixels() gives it, LabelRaster.h) and, for each pixel, its leaves (a CSR index:
 *        offsets per pixel into one array of leaf indices, ascending within a pixel). Built once per
 *        développée, in O(leaves + pixels); then painting a set of pixels finds its leaves, and a change of
 *        some leaves' labels finds the pixels to redraw, without touching the rest of the image.
 *
 * The pixel's shown label (majorityLabel) is the one labelRasterFromLeaves() gives: the most frequent label of
 * its leaves, 0 counting as a label, a tie going to the smaller id; 0 for a pixel without leaves — unless
 * lendLeaves() gave it a lender: a pixel with a height but no leaf (filled from its neighbours, or a gap of the
 * leaves' grid) then shows the label of the nearest pixel with leaves, as its height came from its neighbours;
 * without it such pixels showed as unpainted specks inside every painted region. Painting (leavesAt, leavesOf)
 * still takes a pixel's own leaves only. Nearest neighbour only: no id is ever blended.
 * Memory: 4 bytes per leaf twice and 4 bytes per pixel (12 once leaves are lent, and 4 per borrower). Limits: fewer than 2³² leaves and pixels (asserted).
 * Thread-safety: a value; const members are reentrant.
 */
#include "stylos/core/shading/HeightField.h"

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
    /** @brief The pixels of @p leaves (any order) and the pixels they lend them to: ascending, unique, leaves off the
     *         image left out. */
    std::vector<std::uint32_t> pixelsOf(std::span<const std::uint32_t> leaves) const;

    /**
     * @brief Gives each pixel without leaves but with a height in @p states (row-major, pixelCount() of them, asserted;
     *        Measured or Filled) the pixel with leaves nearest to it, through pixels with a height (8-connected steps, at
     *        most kMaxLendSteps; a tie goes to the one met first in a breadth-first search seeded in pixel order:
     *        deterministic). majorityLabel() then shows that pixel's label there, and pixelsOf() includes the borrowers.
     */
    void lendLeaves(std::span<const shading::PixelState> states);
    /** Steps a pixel's leaves are lent at most: as deep as filling reaches (a 256-pixel hole: 8 steps; gaps inside
     *  the footprint, shading::fillFootprintGaps, up to its closing radius, 64 pixels). */
    static constexpr int kMaxLendSteps = 64;
    /** @brief The pixel whose leaves @p pixel shows: itself, its lender, or −1 (no leaf near it). */
    std::int64_t shownPixel(std::uint32_t pixel) const;

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
    std::vector<std::int32_t> m_lender;    ///< per pixel without leaves, once lent: the pixel it shows, or −1
    std::vector<std::uint32_t> m_borrowerOffsets; ///< once lent: pixelCount() + 1, into m_borrowers
    std::vector<std::uint32_t> m_borrowers;       ///< the pixels each pixel lends its leaves to, grouped by lender
};

} // namespace stylos::core::annotation
