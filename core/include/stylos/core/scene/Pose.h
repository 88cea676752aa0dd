#pragma once
/** @file
 * @brief A fragment's pose: the rigid transform from the fragment's own frame (its octree's coordinates)
 *        to the scene frame, as a 4×4 matrix of doubles, row-major (element (row, col) at m[4·row + col]),
 *        acting on column vectors: p_scene = R·p_local + t. Units: metres (translation), radians (angles).
 *        Doubles throughout: scene coordinates can be large (site frames).
 *        Thread-safety: a value type; the functions are pure.
 */
#include <array>

namespace stylos::core::scene {

/** @brief A translation and three rotation angles: R = Rz(angles[2]) · Ry(angles[1]) · Rx(angles[0]). */
struct TranslationAngles {
    std::array<double, 3> translation{};  ///< metres
    std::array<double, 3> angles{};       ///< radians, about x then y then z (fixed axes)

    bool operator==(const TranslationAngles&) const = default;
};

class Pose {
public:
    /** @brief The identity. */
    Pose() = default;
    /** @brief From 16 row-major values (not checked: see isRigid()). */
    explicit Pose(const std::array<double, 16>& rowMajor) : m_m(rowMajor) {}

    /** @brief A translation followed by no rotation. */
    static Pose translation(const std::array<double, 3>& t);
    /** @brief The pose with rotation Rz·Ry·Rx of @p value's angles and its translation. */
    static Pose fromTranslationAngles(const TranslationAngles& value);

    /** @brief Element (row, col), 0..3 each. */
    double operator()(int row, int col) const { return m_m[static_cast<std::size_t>(4 * row + col)]; }
    /** @brief The 16 values, row-major. */
    const std::array<double, 16>& rowMajor() const { return m_m; }
    /** @brief The translation column, metres. */
    std::array<double, 3> translationPart() const { return {m_m[3], m_m[7], m_m[11]}; }

    /** @brief This pose with its translation replaced (the rotation untouched, bit for bit). */
    Pose withTranslation(const std::array<double, 3>& t) const;
    /** @brief This pose with its rotation replaced by Rz·Ry·Rx of @p angles (translation untouched). */
    Pose withAngles(const std::array<double, 3>& angles) const;
    /**
     * @brief The translation and angles of this pose: angles[1] in [-π/2, π/2], the others in (-π, π].
     *        At gimbal lock (|angles[1]| = π/2) angles[0] is 0. Meaningful for rigid poses only.
     */
    TranslationAngles toTranslationAngles() const;

    /** @brief p_scene = this · p_local. */
    std::array<double, 3> apply(const std::array<double, 3>& p) const;
    /** @brief this · @p other (apply @p other first). */
    Pose operator*(const Pose& other) const;
    /** @brief The inverse of a rigid pose (Rᵀ, −Rᵀt). */
    Pose rigidInverse() const;

    /**
     * @brief Whether the upper 3×3 block is a rotation (orthonormal, determinant +1) within
     *        @p tolerance per element of RᵀR − I, the last row is exactly (0 0 0 1) and every value is finite.
     */
    bool isRigid(double tolerance = 1e-6) const;

    bool operator==(const Pose&) const = default;
    /** @brief Whether every element differs from @p other's by at most @p tolerance. */
    bool approxEqual(const Pose& other, double tolerance) const;

private:
    std::array<double, 16> m_m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
};

} // namespace stylos::core::scene
