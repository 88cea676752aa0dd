// Pixel ↔ leaf index of a développée (CSR), and the label each pixel shows.
#include "stylos/core/annotation/PixelLeafIndex.h"

#include <algorithm>
#include <cstdlib>
#include <array>
#include <cassert>
#include <limits>

namespace stylos::core::annotation {

PixelLeafIndex PixelLeafIndex::build(std::span<const std::int64_t> leafPixels, int width, int height)
{
    assert(width >= 0 && height >= 0 && "PixelLeafIndex::build(): negative size");
    PixelLeafIndex index;
    index.m_width = width;
    index.m_height = height;
    const std::size_t pixels = index.pixelCount();
    assert(pixels < std::numeric_limits<std::uint32_t>::max() &&
           leafPixels.size() < std::numeric_limits<std::uint32_t>::max() && "PixelLeafIndex::build(): too large");
    index.m_leafPixel.resize(leafPixels.size());
    index.m_offsets.assign(pixels + 1, 0);
    for (std::size_t leaf = 0; leaf < leafPixels.size(); ++leaf) {
        const std::int64_t p = leafPixels[leaf];
        assert(p < std::int64_t(pixels) && "PixelLeafIndex::build(): pixel outside the grid");
        index.m_leafPixel[leaf] = p < 0 ? -1 : std::int32_t(p);
        if (p >= 0) ++index.m_offsets[std::size_t(p) + 1];
    }
    for (std::size_t p = 0; p < pixels; ++p) index.m_offsets[p + 1] += index.m_offsets[p];
    index.m_leaves.resize(index.m_offsets[pixels]);
    std::vector<std::uint32_t> cursor(index.m_offsets.begin(), index.m_offsets.end() - 1);
    for (std::size_t leaf = 0; leaf < leafPixels.size(); ++leaf) // ascending leaves: ascending within a pixel
        if (const std::int32_t p = index.m_leafPixel[leaf]; p >= 0) index.m_leaves[cursor[std::size_t(p)]++] = std::uint32_t(leaf);
    return index;
}

std::span<const std::uint32_t> PixelLeafIndex::leavesAt(std::uint32_t pixel) const
{
    assert(pixel < pixelCount() && "PixelLeafIndex::leavesAt(): pixel outside the grid");
    return std::span<const std::uint32_t>(m_leaves).subspan(m_offsets[pixel], m_offsets[pixel + 1] - m_offsets[pixel]);
}

std::vector<std::uint32_t> PixelLeafIndex::leavesOf(std::span<const std::uint32_t> pixels) const
{
    std::vector<std::uint32_t> out;
    for (std::uint32_t p : pixels)
        if (p < pixelCount()) {
            const auto leaves = leavesAt(p);
            out.insert(out.end(), leaves.begin(), leaves.end());
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<std::uint32_t> PixelLeafIndex::pixelsOf(std::span<const std::uint32_t> leaves) const
{
    std::vector<std::uint32_t> out;
    out.reserve(leaves.size());
    for (std::uint32_t leaf : leaves)
        if (const std::int64_t p = pixelOf(leaf); p >= 0) out.push_back(std::uint32_t(p));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    if (m_borrowerOffsets.empty() || out.empty()) return out;
    const std::size_t owners = out.size();
    for (std::size_t k = 0; k < owners; ++k) // and the pixels they lend their leaves to
        out.insert(out.end(), m_borrowers.begin() + m_borrowerOffsets[out[k]],
                   m_borrowers.begin() + m_borrowerOffsets[out[k] + 1]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

void PixelLeafIndex::lendLeaves(std::span<const shading::PixelState> states)
{
    assert(states.size() == pixelCount() && "PixelLeafIndex::lendLeaves(): one state per pixel");
    const std::size_t pixels = pixelCount();
    m_lender.assign(pixels, -1);
    std::vector<std::uint8_t> steps(pixels, 0);
    std::vector<std::uint32_t> queue;
    for (std::size_t p = 0; p < pixels; ++p)
        if (m_offsets[p + 1] != m_offsets[p]) {
            m_lender[p] = std::int32_t(p);
            queue.push_back(std::uint32_t(p));
        }
    constexpr int kSteps[8][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint32_t p = queue[head];
        if (steps[p] >= kMaxLendSteps) continue;
        const int c = int(p % std::uint32_t(m_width)), r = int(p / std::uint32_t(m_width));
        for (const auto& d : kSteps) {
            const int nc = c + d[0], nr = r + d[1];
            if (nc < 0 || nr < 0 || nc >= m_width || nr >= m_height) continue;
            const std::size_t n = std::size_t(nr) * std::size_t(m_width) + std::size_t(nc);
            if (m_lender[n] >= 0 || states[n] == shading::PixelState::Empty) continue;
            m_lender[n] = m_lender[p];
            steps[n] = std::uint8_t(steps[p] + 1);
            queue.push_back(std::uint32_t(n));
        }
    }
    // Each lender's borrowers (CSR), so that a change of its leaves redraws them without a search.
    m_borrowerOffsets.assign(pixels + 1, 0);
    for (std::size_t p = 0; p < pixels; ++p)
        if (m_lender[p] >= 0 && std::size_t(m_lender[p]) != p) ++m_borrowerOffsets[std::size_t(m_lender[p]) + 1];
    for (std::size_t p = 0; p < pixels; ++p) m_borrowerOffsets[p + 1] += m_borrowerOffsets[p];
    m_borrowers.resize(m_borrowerOffsets[pixels]);
    std::vector<std::uint32_t> cursor(m_borrowerOffsets.begin(), m_borrowerOffsets.end() - 1);
    for (std::size_t p = 0; p < pixels; ++p)
        if (m_lender[p] >= 0 && std::size_t(m_lender[p]) != p) m_borrowers[cursor[std::size_t(m_lender[p])]++] = std::uint32_t(p);
}

std::int64_t PixelLeafIndex::shownPixel(std::uint32_t pixel) const
{
    assert(pixel < pixelCount() && "PixelLeafIndex::shownPixel(): pixel outside the grid");
    if (m_offsets[pixel + 1] != m_offsets[pixel]) return pixel;
    return m_lender.empty() ? -1 : m_lender[pixel];
}

std::uint8_t PixelLeafIndex::majorityLabel(std::uint32_t pixel, std::span<const std::uint8_t> labels) const
{
    assert(labels.size() == m_leafPixel.size() && "PixelLeafIndex::majorityLabel(): one label per leaf");
    const std::int64_t shown = shownPixel(pixel);
    if (shown < 0) return 0;
    const auto leaves = leavesAt(std::uint32_t(shown));
    if (leaves.size() > 16) { // many (a bed face seen edge-on): a table
        std::array<std::uint32_t, 256> counts{};
        for (std::uint32_t leaf : leaves) ++counts[labels[leaf]];
        return std::uint8_t(std::max_element(counts.begin(), counts.end()) - counts.begin()); // first max: smaller id
    }
    // Few leaves per pixel: count by scanning (no 256-entry table to clear).
    std::uint8_t best = labels[leaves[0]];
    std::size_t bestCount = 0;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const std::uint8_t label = labels[leaves[i]];
        std::size_t n = 0;
        for (std::uint32_t leaf : leaves) n += labels[leaf] == label;
        if (n > bestCount || (n == bestCount && label < best)) {
            best = label;
            bestCount = n;
        }
    }
    return best;
}

std::vector<std::uint8_t> PixelLeafIndex::majorityLabels(std::span<const std::uint8_t> labels) const
{
    std::vector<std::uint8_t> out(pixelCount(), 0);
    for (std::size_t p = 0; p < out.size(); ++p)
        if (shownPixel(std::uint32_t(p)) >= 0) out[p] = majorityLabel(std::uint32_t(p), labels);
    return out;
}

} // namespace stylos::core::annotation
