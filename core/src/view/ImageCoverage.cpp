#include "stylos/core/view/ImageCoverage.h"

#include <algorithm>
#include <cassert>

namespace stylos::core::view {

namespace {

/** One separable pass of a square max (dilate) or min (erode) filter of half-width @p r along x or y. */
CoverageMask filterPass(const CoverageMask& in, int w, int h, int r, bool dilate, bool alongX)
{
    CoverageMask out(in.size());
    const std::uint8_t outside = dilate ? 0 : 1;
    const int n = alongX ? w : h, lines = alongX ? h : w;
    for (int line = 0; line < lines; ++line)
        for (int i = 0; i < n; ++i) {
            std::uint8_t v = dilate ? 0 : 1;
            for (int k = i - r; k <= i + r; ++k) {
                std::uint8_t s = outside;
                if (k >= 0 && k < n) s = in[alongX ? std::size_t(line) * w + k : std::size_t(k) * w + line];
                v = dilate ? std::max(v, s) : std::min(v, s);
            }
            out[alongX ? std::size_t(line) * w + i : std::size_t(i) * w + line] = v;
        }
    return out;
}

} // namespace

CoverageMask closeMask(const CoverageMask& mask, int width, int height, int radius)
{
    assert(mask.size() == std::size_t(width) * std::size_t(height) && "closeMask(): mask is not width × height");
    const CoverageMask dilated = filterPass(filterPass(mask, width, height, radius, true, true), width, height, radius, true, false);
    return filterPass(filterPass(dilated, width, height, radius, false, true), width, height, radius, false, false);
}

CoverageMask enclosedBackground(const CoverageMask& covered, const CoverageMask& silhouette, int width, int height)
{
    assert(covered.size() == std::size_t(width) * std::size_t(height) && silhouette.size() == covered.size() &&
           "enclosedBackground(): masks are not width × height");
    CoverageMask out(covered.size(), 0), seen(covered.size(), 0);
    std::vector<std::size_t> stack, region;
    const std::size_t w = std::size_t(width);
    for (std::size_t s = 0; s < covered.size(); ++s) {
        if (covered[s] || seen[s]) continue;
        bool open = false;
        region.clear();
        stack.push_back(s);
        seen[s] = 1;
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            region.push_back(i);
            const std::size_t x = i % w, y = i / w;
            if (!silhouette[i] || x == 0 || y == 0 || x + 1 == w || y + 1 == std::size_t(height)) open = true;
            auto visit = [&](std::size_t j) {
                if (!covered[j] && !seen[j]) {
                    seen[j] = 1;
                    stack.push_back(j);
                }
            };
            if (x > 0) visit(i - 1);
            if (x + 1 < w) visit(i + 1);
            if (y > 0) visit(i - w);
            if (y + 1 < std::size_t(height)) visit(i + w);
        }
        if (!open)
            for (const std::size_t i : region) out[i] = 1;
    }
    return out;
}

CoverageCounts measureCoverage(const CoverageMask& covered, int width, int height, int radius, std::vector<HoleKind>* kinds)
{
    const CoverageMask silhouette = closeMask(covered, width, height, radius);
    const CoverageMask enclosed = enclosedBackground(covered, silhouette, width, height);
    CoverageCounts c;
    if (kinds) kinds->assign(covered.size(), HoleKind::None);
    for (std::size_t i = 0; i < covered.size(); ++i) {
        c.covered += covered[i];
        c.silhouette += silhouette[i];
        if (!silhouette[i] || covered[i]) continue;
        ++c.holes;
        (enclosed[i] ? c.through : c.edge) += 1;
        if (kinds) (*kinds)[i] = enclosed[i] ? HoleKind::Through : HoleKind::Edge;
    }
    return c;
}

} // namespace stylos::core::view
