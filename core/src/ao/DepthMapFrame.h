#pragma once
// Internal to the DepthMap skydome kernel: the projection across one direction and the map's layout.
#include <array>
#include <cstdint>

namespace stylos::core::ao::detail {

/**
 * The frame of one direction d (unit, toward the sky): e1 = the horizontal unit vector ⊥ d (z × d
 * normalised; x when d is vertical), e2 = d × e1. A cell centre c (cell edges) projects to pixel
 * coordinates (c·e1 + u0, c·e2 + v0), each ≥ 1, on a map of width × height pixels of one cell edge;
 * its key c·d grows toward the sky and is stored as the fixed-point integer (c·d − keyMin)·keyScale + 1
 * (23 bits: exact order to 2^-23 of the key range, 1/2048 cell at level 11).
 * The unit cube seen along d is the hexagon {q : |q·N_k| ≤ h_k, k = 0, 1, 2} (N_k = (nu[k], nv[k]) ⊥ the
 * projected axis k), grown by a hair so that neighbouring cubes' hexagons share their edges.
 */
struct DepthMapFrame {
    float e1[3], e2[3], d[3];
    float u0 = 0, v0 = 0;
    int width = 0, height = 0;
    float nu[3], nv[3], h[3];
    float keyMin = 0, keyScale = 1, keyInverse = 1;
};

/** The frame of @p d for cell centres within the box [@p lo, @p hi] (cell edges, lo ≤ hi). */
DepthMapFrame makeDepthMapFrame(const std::array<float, 3>& d, const std::array<float, 3>& lo,
                                const std::array<float, 3>& hi);

} // namespace stylos::core::ao::detail
