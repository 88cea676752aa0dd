// The pixel ↔ leaf index of an assembly's développée: one windowed PixelLeafIndex per piece, on the pixels it shows.
#include "stylos/core/annotation/AssemblyLeafIndex.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace stylos::core::annotation {

Result<std::vector<std::int64_t>> posedLeafPixels(const octree::PackedOctree& octree, const Eigen::Isometry3d& pose,
                                                  const unroll::UnrollMap& map, ProgressSink* progress,
                                                  double visibleDepth)
{
    constexpr double kMinFacing = 0.3; // |n · outward| of a leaf the développée shows: within 72° of facing it
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    std::vector<std::int64_t> pixels(leaves, -1);
    const bool hide = std::isfinite(visibleDepth);
    std::vector<float> heights(hide ? leaves : 0);
    std::vector<float> top(hide ? std::size_t(map.width()) * std::size_t(map.height()) : 0,
                           -std::numeric_limits<float>::infinity());
    bool cancelled = false;
    octree.forEachCell(octree.depth(), [&](const octree::CellView& cell) {
        const Eigen::Vector3d centre = pose * Eigen::Vector3d(cell.centre[0], cell.centre[1], cell.centre[2]);
        if (const auto hit = map.pixelOf(centre)) {
            const double c = std::floor(hit->column), r = std::floor(hit->row);
            if (c >= 0 && r >= 0 && c < map.width() && r < map.height()) {
                const std::int64_t pixel = std::int64_t(r) * map.width() + std::int64_t(c);
                pixels[cell.index] = pixel;
                if (hide) {
                    // Edge-on to the développée's view (a fracture or bed face: its normal within 17° of the
                    // surface's plane): not what the pixel shows, whatever its height.
                    const Eigen::Vector3d out = (map.worldAtPixel(hit->column, hit->row, hit->h + 1e-3) -
                                                 map.worldAtPixel(hit->column, hit->row, hit->h)).normalized();
                    const Eigen::Vector3d n = pose.linear() * Eigen::Vector3d(cell.normal[0], cell.normal[1], cell.normal[2]);
                    heights[cell.index] = float(hit->h);
                    if (std::abs(n.dot(out)) < kMinFacing) pixels[cell.index] = -1;
                    else top[std::size_t(pixel)] = std::max(top[std::size_t(pixel)], float(hit->h));
                }
            }
        }
        if (progress && (cell.index & 0xFFFF) == 0) {
            progress->update(double(cell.index) / double(std::max<std::uint64_t>(leaves, 1)));
            if (progress->isCancelRequested()) return !(cancelled = true);
        }
        return true;
    });
    if (cancelled) return Error::at(ErrorCode::Cancelled, octree.path().string(), {}, "cancelled");
    if (hide) {
        // Under the surface the pixel shows (a fragment's inner break face): below its own top by more than the depth,
        // or below its neighbours' top (2 pixels around) by more than twice it — a pixel that no outer leaf of a sparse scan lands in
        // has only the inner face's leaves, which its own top would keep (shown as unpainted specks in a painted
        // region); twice the depth keeps a flute's wall beside its fillet.
        constexpr int kNear = 2; // a 5 × 5 window: a gap of the outer surface's leaves up to 3 pixels wide
        const int width = map.width(), height = map.height();
        // The window's maximum as two passes (along rows, then along columns): 10 reads a pixel instead of 25.
        const auto at = [width](int r, int c) { return std::size_t(r) * std::size_t(width) + std::size_t(c); };
        std::vector<float> across(top.size(), -std::numeric_limits<float>::infinity());
        for (int r = 0; r < height; ++r)
            for (int c = 0; c < width; ++c) {
                float highest = -std::numeric_limits<float>::infinity();
                for (int dc = std::max(-kNear, -c); dc <= kNear && c + dc < width; ++dc) highest = std::max(highest, top[at(r, c + dc)]);
                across[at(r, c)] = highest;
            }
        std::vector<float> near(top.size(), -std::numeric_limits<float>::infinity());
        for (int r = 0; r < height; ++r)
            for (int c = 0; c < width; ++c) {
                float highest = -std::numeric_limits<float>::infinity();
                for (int dr = std::max(-kNear, -r); dr <= kNear && r + dr < height; ++dr) highest = std::max(highest, across[at(r + dr, c)]);
                near[at(r, c)] = highest;
            }
        for (std::size_t leaf = 0; leaf < pixels.size(); ++leaf) {
            if (pixels[leaf] < 0) continue;
            const std::size_t p = std::size_t(pixels[leaf]);
            const double h = heights[leaf];
            if (h < double(top[p]) - visibleDepth || h < double(near[p]) - 2.0 * visibleDepth) pixels[leaf] = -1;
        }
    }
    return pixels;
}

AssemblyLeafIndex AssemblyLeafIndex::build(int width, int height, std::shared_ptr<const std::vector<std::uint64_t>> pieceAt,
                                           std::vector<PieceLeaves> pieces, std::span<const shading::PixelState> states)
{
    assert(pieceAt && pieceAt->size() == std::size_t(width) * std::size_t(height) &&
           "AssemblyLeafIndex::build(): pieceAt is not width × height");
    assert((states.empty() || states.size() == pieceAt->size()) && "AssemblyLeafIndex::build(): states are not width × height");
    const bool lend = !states.empty();
    AssemblyLeafIndex out;
    out.m_width = width;
    out.m_height = height;
    out.m_pieceAt = std::move(pieceAt);
    const auto& at = *out.m_pieceAt;
    // Lending: each piece's window spans every pixel it shows with a height, so that its borrowers are in it — found
    // for all pieces in one pass over the image (runs of one piece along a row: one lookup a run).
    struct Span {
        int left = std::numeric_limits<int>::max(), top = std::numeric_limits<int>::max(), right = -1, bottom = -1;
    };
    std::unordered_map<std::uint64_t, Span> shownSpans;
    if (lend) {
        for (const PieceLeaves& p : pieces) shownSpans[p.id];
        Span* span = nullptr;
        std::uint64_t spanId = 0;
        for (int r = 0; r < height; ++r)
            for (int c = 0; c < width; ++c) {
                const std::size_t pixel = std::size_t(r) * std::size_t(width) + std::size_t(c);
                if (states[pixel] == shading::PixelState::Empty) continue;
                if (!span || at[pixel] != spanId) {
                    const auto it = shownSpans.find(at[pixel]);
                    span = it == shownSpans.end() ? nullptr : &it->second;
                    spanId = at[pixel];
                    if (!span) continue;
                }
                span->left = std::min(span->left, c), span->right = std::max(span->right, c);
                span->top = std::min(span->top, r), span->bottom = std::max(span->bottom, r);
            }
    }
    for (PieceLeaves& p : pieces) {
        assert(!out.find(p.id) && "AssemblyLeafIndex::build(): two pieces of one id");
        // Keep the leaves on the pixels this piece shows; their bounding window.
        int left = width, top = height, right = -1, bottom = -1;
        for (std::int64_t& pixel : p.pixels) {
            if (pixel < 0) continue;
            assert(std::size_t(pixel) < at.size() && "AssemblyLeafIndex::build(): pixel outside the image");
            if (at[std::size_t(pixel)] != p.id) {
                pixel = -1; // hidden under another piece
                continue;
            }
            const int c = int(pixel % width), r = int(pixel / width);
            left = std::min(left, c), right = std::max(right, c), top = std::min(top, r), bottom = std::max(bottom, r);
        }
        const auto shows = [&](std::size_t pixel) { return at[pixel] == p.id && states[pixel] != shading::PixelState::Empty; };
        if (lend && right >= 0) {
            const Span& s = shownSpans[p.id];
            if (s.right >= 0)
                left = std::min(left, s.left), right = std::max(right, s.right), top = std::min(top, s.top),
                bottom = std::max(bottom, s.bottom);
        }
        Piece piece;
        piece.id = p.id;
        piece.pose = p.pose;
        piece.source = std::move(p.source);
        if (right < 0) { // shows nowhere
            piece.index = PixelLeafIndex::build(p.pixels, 0, 0);
        } else {
            piece.left = left;
            piece.top = top;
            const int w = right - left + 1;
            for (std::int64_t& pixel : p.pixels)
                if (pixel >= 0) pixel = (pixel / width - top) * w + (pixel % width - left);
            piece.index = PixelLeafIndex::build(p.pixels, w, bottom - top + 1);
            if (lend) {
                // Only through this piece's own pixels: another piece's, or the drum's under a fragment, are Empty here.
                std::vector<shading::PixelState> window(piece.index.pixelCount(), shading::PixelState::Empty);
                for (int r = top; r <= bottom; ++r)
                    for (int c = left; c <= right; ++c) {
                        const std::size_t pixel = std::size_t(r) * std::size_t(width) + std::size_t(c);
                        if (shows(pixel)) window[std::size_t(r - top) * std::size_t(w) + std::size_t(c - left)] = states[pixel];
                    }
                piece.index.lendLeaves(window);
            }
        }
        std::vector<std::int64_t>().swap(p.pixels); // peak memory: one piece's pixels at a time
        out.m_pieces.push_back(std::move(piece));
    }
    return out;
}

const AssemblyLeafIndex::Piece* AssemblyLeafIndex::find(std::uint64_t id) const
{
    const auto it = std::find_if(m_pieces.begin(), m_pieces.end(), [id](const Piece& p) { return p.id == id; });
    return it == m_pieces.end() ? nullptr : &*it;
}

std::uint64_t AssemblyLeafIndex::shownAt(std::uint32_t pixel) const
{
    return m_pieceAt && pixel < m_pieceAt->size() ? (*m_pieceAt)[pixel] : 0;
}

std::int64_t AssemblyLeafIndex::localPixel(const Piece& piece, std::uint32_t pixel) const
{
    if (m_width <= 0) return -1;
    const int c = int(pixel % std::uint32_t(m_width)) - piece.left, r = int(pixel / std::uint32_t(m_width)) - piece.top;
    if (c < 0 || r < 0 || c >= piece.index.width() || r >= piece.index.height()) return -1;
    return std::int64_t(r) * piece.index.width() + c;
}

std::int64_t AssemblyLeafIndex::shownPixel(std::uint32_t pixel) const
{
    const Piece* piece = find(shownAt(pixel));
    if (!piece) return -1;
    const std::int64_t local = localPixel(*piece, pixel);
    const std::int64_t shown = local < 0 ? -1 : piece->index.shownPixel(std::uint32_t(local));
    if (shown < 0) return -1;
    const int w = piece->index.width();
    return std::int64_t(piece->top + int(shown) / w) * m_width + piece->left + int(shown) % w;
}

std::vector<std::pair<std::uint64_t, std::vector<std::uint32_t>>>
AssemblyLeafIndex::split(std::span<const std::uint32_t> pixels) const
{
    std::vector<std::pair<std::uint64_t, std::vector<std::uint32_t>>> out;
    for (const Piece& piece : m_pieces) {
        std::vector<std::uint32_t> mine;
        for (std::uint32_t p : pixels)
            if (m_pieceAt && p < m_pieceAt->size() && (*m_pieceAt)[p] == piece.id) mine.push_back(p);
        if (mine.empty()) continue;
        std::sort(mine.begin(), mine.end());
        mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
        out.emplace_back(piece.id, std::move(mine));
    }
    return out;
}

std::vector<std::uint32_t> AssemblyLeafIndex::leavesOf(std::uint64_t id, std::span<const std::uint32_t> pixels) const
{
    const Piece* piece = find(id);
    if (!piece) return {};
    std::vector<std::uint32_t> local;
    local.reserve(pixels.size());
    for (std::uint32_t p : pixels)
        if (shownAt(p) == id)
            if (const std::int64_t l = localPixel(*piece, p); l >= 0) local.push_back(std::uint32_t(l));
    return piece->index.leavesOf(local);
}

std::vector<std::uint32_t> AssemblyLeafIndex::pixelsOf(std::uint64_t id, std::span<const std::uint32_t> leaves) const
{
    const Piece* piece = find(id);
    if (!piece) return {};
    std::vector<std::uint32_t> out = piece->index.pixelsOf(leaves); // window pixels, ascending
    const int w = piece->index.width();
    for (std::uint32_t& p : out) p = std::uint32_t(piece->top + int(p) / w) * std::uint32_t(m_width) + std::uint32_t(piece->left + int(p) % w);
    return out; // row-major order is kept: the window's rows map to the image's in order
}

} // namespace stylos::core::annotation
