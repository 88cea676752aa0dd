#pragma once
/** @file
 * @brief Internal to the octree access code: the six clip planes of an OpenGL view-projection matrix,
 *        expressed relative to an origin (the octree's root box corner), and a conservative test of
 *        axis-aligned cubes against them. Units: metres. Pure value type, thread-safe.
 */
#include <array>
#include <cstdint>

namespace stylos::core::octree {

class Frustum {
public:
    /** @brief Bit set meaning "every plane still has to be tested" (one bit per plane). */
    static constexpr std::uint8_t AllPlanes = 0x3F;

    /**
     * @brief The planes −w ≤ x, y, z ≤ w of clip = @p viewProjection · (p, 1) (column-major, OpenGL
     *        convention), for points p given relative to @p origin. Planes are normalised (unit
     *        normal, distance in metres); a plane with a zero normal (degenerate matrix) is never
     *        tested, so the test stays conservative.
     */
    static Frustum fromViewProjection(const std::array<double, 16>& viewProjection,
                                      const std::array<double, 3>& origin);

    /**
     * @brief Tests the cube of centre @p centre and half edge @p half against the planes whose bit is
     *        set in @p planes. Returns false when the cube lies entirely outside one plane (with a small
     *        tolerance in favour of keeping it: a cube that touches or crosses the frustum is never
     *        rejected). Otherwise clears in @p planes the bits of the planes the cube lies entirely
     *        inside, which its sub-cubes then need not test.
     */
    bool keep(const std::array<double, 3>& centre, double half, std::uint8_t& planes) const;

private:
    struct Plane {
        std::array<double, 3> n{};   ///< unit normal pointing inside
        double d = 0;                ///< n · p + d ≥ 0 inside
    };
    std::array<Plane, 6> m_planes{};
    std::uint8_t m_usable = 0;       ///< bits of the planes with a non-zero normal
};

} // namespace stylos::core::octree
