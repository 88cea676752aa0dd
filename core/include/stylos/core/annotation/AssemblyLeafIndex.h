#pragma once
/** @file
 * @brief The pixel ↔ leaf index of an assembly's développée (developpee/AssemblyDeveloppee.h): one index per
 *        piece (the drum and each docked fragment), each holding only the leaves that land on the pixels that
 *        piece shows (its `pieceAt` value). Painting a set of pixels splits it by the piece shown at each pixel
 *        and finds, per piece, the leaves at its own pixels — never those of a piece hidden under another; a
 *        change of a piece's labels finds the pixels to redraw.
 *
 * - posedLeafPixels(): the pixel of every leaf of an octree whose leaves are first carried by a pose (piece file
 *   frame → the map's frame, the drum's file frame): as leafPixels() (LabelRaster.h) with the pose applied to
 *   each leaf centre — the identity gives exactly leafPixels().
 * - AssemblyLeafIndex::build(): from those pixels per piece and the développée's `pieceAt` (0 where the drum or
 *   nothing shows; the drum's piece has id 0). A leaf whose pixel shows another piece is dropped (−1).
 *
 * Memory: per piece a PixelLeafIndex on the bounding window of its kept leaves' pixels: 4 bytes per leaf, 4 per
 * kept leaf, 4 per window pixel (a docked fragment's window is small); plus the shared `pieceAt`.
 * Units: pixels. Thread-safety: a value; const members are reentrant. Failure: posedLeafPixels() returns
 * Cancelled (naming the octree) when @p progress asks.
 */
#include "stylos/core/annotation/PixelLeafIndex.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace stylos::core::annotation {

/** @brief The pixel (row · width + column) of every leaf of @p octree carried by @p pose; −1 off the image, and,
 *         with a finite @p visibleDepth, −1 for the leaves not on the surface the développée shows (leafPixels()). */
Result<std::vector<std::int64_t>> posedLeafPixels(const octree::PackedOctree& octree, const Eigen::Isometry3d& pose,
                                                  const unroll::UnrollMap& map, ProgressSink* progress = nullptr,
                                                  double visibleDepth = std::numeric_limits<double>::infinity());

class AssemblyLeafIndex {
public:
    /** @brief One piece: its leaves on the pixels it shows, indexed on a window of the image. */
    struct Piece {
        std::uint64_t id = 0; ///< its value in pieceAt (0: the drum)
        int left = 0;         ///< the window's first column in the image
        int top = 0;          ///< the window's first row
        PixelLeafIndex index; ///< on the window (its width × height); leafCount() is the octree's
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity(); ///< what it was indexed with (piece → drum frame)
        std::string source;   ///< the octree it was indexed from (for a stale check)
    };
    /** @brief Input of build(): a piece's id and posedLeafPixels() (consumed). */
    struct PieceLeaves {
        std::uint64_t id = 0;
        std::vector<std::int64_t> pixels;
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        std::string source;
    };

    AssemblyLeafIndex() = default;
    /** @brief See the file comment. @p pieceAt: width × height (asserted); ids must be distinct (asserted).
     *         With @p states (the développée's height field's, width × height, asserted), each piece also lends its
     *         leaves (PixelLeafIndex::lendLeaves) to the pixels it shows with a height but no leaf of its own
     *         (filled, or a gap between its leaves), never across another piece's pixels: a piece's window then
     *         also spans every pixel it shows. */
    static AssemblyLeafIndex build(int width, int height, std::shared_ptr<const std::vector<std::uint64_t>> pieceAt,
                                   std::vector<PieceLeaves> pieces, std::span<const shading::PixelState> states = {});

    int width() const { return m_width; }
    int height() const { return m_height; }
    const std::vector<Piece>& pieces() const { return m_pieces; }
    /** @brief The piece of id @p id; null when none. */
    const Piece* find(std::uint64_t id) const;
    /** @brief The piece shown at image pixel @p pixel (0 outside the image). */
    std::uint64_t shownAt(std::uint32_t pixel) const;

    /** @brief @p pixels (image pixels, any order) grouped by the piece shown there, in the order of pieces();
     *         pieces with no pixel are left out; each group ascending and unique. */
    std::vector<std::pair<std::uint64_t, std::vector<std::uint32_t>>> split(std::span<const std::uint32_t> pixels) const;
    /** @brief The leaves of piece @p id at those of @p pixels it shows: ascending, unique (empty for no piece). */
    std::vector<std::uint32_t> leavesOf(std::uint64_t id, std::span<const std::uint32_t> pixels) const;
    /** @brief The image pixels piece @p id shows @p leaves at: ascending, unique. */
    std::vector<std::uint32_t> pixelsOf(std::uint64_t id, std::span<const std::uint32_t> leaves) const;
    /** @brief The image pixel whose leaves of its shown piece @p pixel shows: itself, the pixel that lends it
     *         them (build() with states), or −1 (none). */
    std::int64_t shownPixel(std::uint32_t pixel) const;
    /** @brief The label image pixel @p pixel shows: the majority of its shown piece's leaves there (as
     *         PixelLeafIndex::majorityLabel; a borrower its lender's), by @p labelsOf(id) — that piece's labels, or
     *         an empty span (0). */
    template <class LabelsOf> std::uint8_t majorityLabel(std::uint32_t pixel, LabelsOf&& labelsOf) const
    {
        const Piece* piece = find(shownAt(pixel));
        if (!piece) return 0;
        const std::span<const std::uint8_t> labels = labelsOf(piece->id);
        if (labels.size() != piece->index.leafCount()) return 0;
        const auto local = localPixel(*piece, pixel);
        return local < 0 ? std::uint8_t(0) : piece->index.majorityLabel(std::uint32_t(local), labels);
    }

private:
    /** @p pixel (image) in @p piece's window; −1 outside it. */
    std::int64_t localPixel(const Piece& piece, std::uint32_t pixel) const;

    int m_width = 0;
    int m_height = 0;
    std::shared_ptr<const std::vector<std::uint64_t>> m_pieceAt;
    std::vector<Piece> m_pieces;
};

} // namespace stylos::core::annotation
