#pragma once
/** @file
 * @brief The 3D view's screen-space gap filling, on the CPU: the rule the GL pass (widgets' ViewComposite) follows,
 *        kept here so that it is tested without a GL context. After the splats are drawn, a pixel is a *gap* when
 *        nearer surface surrounds it — background between discs, the scalloped notches between round discs along an
 *        outline, or a far surface seen through a narrow gap in a nearer one (the visibility operator of Pintus et
 *        al. 2011, "Real-time rendering of massive unstructured raw point clouds using screen-space operators") —
 *        and takes the depth, colour and reach of its nearest-in-depth surrounding neighbour.
 *
 * The rule, for every pixel p of depth z_p (linear depth, +∞ for background), from the input image only (one pass,
 * nothing filled feeds another fill): walk each of the 8 directions (±1, 0), (0, ±1), (±1, ±1) for s = 1 …
 * maxSteps pixels (steps, a diagonal step being one step) and stop at the first pixel q that is *in front of* p,
 * z_q < z_p · (1 − depthMargin); that direction *encloses* p when such a q is found within q's own reach, s ≤
 * reach_q (the reach is the size of the disc q belongs to, in pixels: a gap counts only as wide as the splats
 * around it could have left). p is filled when at least minDirections of the 8 directions enclose it, from the
 * enclosing q of smallest depth (the first in the order E, W, N, S, NE, NW, SE, SW on a tie).
 *
 * What it closes and what it keeps, with minDirections 5 and walks of r = min(maxSteps, reach) steps: an enclosed
 * gap or a slit up to r wide (a pixel in it sees both walls: W, E and four diagonals); of a slit between r and 2 r
 * only the middle, where both walls are within r; notches along an outline up to r wide (a notch pixel sees the
 * two discs beside it and the surface under it: 5 directions). A straight outline (3 directions), a convex corner
 * (at most 3) and a slit or opening 2 r wide or wider stay, except an opening's concave corners (an r × r square
 * each, the rounding of any closing at that scale). Walks that leave the picture enclose nothing.
 *
 * Thread-safety: pure functions. Units: pixels, the caller's depth unit. Failure modes: none (arrays whose size is
 * not width × height are a programmer error, asserted).
 */
#include <cstdint>
#include <limits>
#include <vector>

namespace stylos::core::view {

/** @brief A rendered frame, row-major, @p width × @p height: linear depth (+∞ background), an opaque colour word
 *         per pixel (copied, never read) and the reach of each drawn pixel (pixels, 0–127). */
struct GapFrame {
    int width = 0;
    int height = 0;
    std::vector<float> depth;
    std::vector<std::uint32_t> colour;
    std::vector<std::uint8_t> reach;

    static constexpr float Background = std::numeric_limits<float>::infinity();
};

struct GapFillOptions {
    int maxSteps = 8;             ///< the longest walk in each direction, pixels
    int minDirections = 5;        ///< of 8
    float depthMargin = 0.05f;    ///< relative: q is in front of p when z_q < z_p · (1 − margin)
};

/** @brief Fills the gaps of @p frame (see the file comment); returns how many pixels were filled. */
std::int64_t fillGaps(GapFrame& frame, const GapFillOptions& options = {});

/** @brief The reach stored for a disc of @p radiusPixels on screen: rounded, at least 1, at most 127. */
std::uint8_t gapReach(double radiusPixels);

} // namespace stylos::core::view
