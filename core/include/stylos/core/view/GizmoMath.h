#pragma once
/** @file
 * @brief The maths of the 3D view's gizmos, without GL or Qt: where a view ray meets a translate arrow's
 *        line (the closest parameter along it) and a rotate ring's plane (the signed angle about its axis),
 *        how far the cursor is from a handle on screen (pixels, through core::view::Camera), and the
 *        snapping rules of a drag (angle steps: the flute pitch, 1°, 0.1°; length steps: 1 mm, 0.1 mm;
 *        Shift moves at a tenth of the speed).
 *
 * Frames: everything is in the scene frame (metres) except cursors and distances on screen, which are in
 * the camera's logical pixels (x right, y down; Camera::rayAt, Camera::project). Angles: radians,
 * counter-clockwise about the given axis (right-hand rule).
 * Thread-safety: pure functions, and FineDrag, a small value type. Failure modes: degenerate geometry
 * (a ray parallel to an arrow, a ring seen edge-on, a handle behind the eye) gives nullopt or +∞, never NaN.
 */
#include "stylos/core/view/Camera.h"

#include <Eigen/Core>

#include <optional>

namespace stylos::core::view {

/** @brief One degree in radians. */
inline constexpr double Degree = 0.017453292519943295;

/**
 * @brief The parameter s of the point origin + s·direction of the line closest to @p ray (metres along a
 *        unit @p direction). nullopt when the ray and the line are parallel within 1e-9 (sin² of the angle):
 *        an arrow pointing at the eye cannot be dragged.
 */
std::optional<double> closestAxisParameter(const Ray& ray, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction);

/** @brief Where @p ray meets the plane through @p point with unit normal @p normal; nullopt when the ray is
 *         parallel to it (|cos| < 1e-6) or the plane lies behind the ray's origin. */
std::optional<Eigen::Vector3d> rayPlane(const Ray& ray, const Eigen::Vector3d& point, const Eigen::Vector3d& normal);

/** @brief The signed angle from @p from to @p to about the unit @p axis, in (−π, π]; both are projected on the
 *         plane normal to @p axis first. 0 when either has no component in that plane. */
double signedAngle(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3d& axis);

/**
 * @brief The angle on a rotate ring: where @p ray meets the ring's plane (through @p centre, normal @p axis),
 *        as the signed angle about @p axis from the direction @p zero (e.g. centre → the press point).
 *        nullopt when the ray misses the plane (see rayPlane) or meets it at the centre.
 */
std::optional<double> ringAngle(const Ray& ray, const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                                const Eigen::Vector3d& zero);

/** @brief @p now brought within π of @p previous by whole turns: follows a drag around a ring past ±π. */
double unwrapAngle(double previous, double now);

/** @brief Metres per logical pixel at @p point's depth (the same everywhere in orthographic views);
 *         nullopt when @p point is at or behind the eye. */
std::optional<double> metresPerPixel(const Camera& camera, const Eigen::Vector3d& point);

/** @brief Distance in pixels from @p cursor to the segment @p a – @p b of the scene as projected by @p camera;
 *         +∞ when an end lies behind the eye. */
double pixelDistanceToSegment(const Camera& camera, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector2d& cursor);

/** @brief Distance in pixels from @p cursor to the ring (circle of @p radius metres about the unit @p axis
 *         through @p centre) as projected by @p camera, measured on a polygon of @p segments sides (≥ 3);
 *         +∞ when all of it lies behind the eye. */
double pixelDistanceToRing(const Camera& camera, const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                           double radius, const Eigen::Vector2d& cursor, int segments = 96);

/** @brief The modifiers that change a drag (the keyboard's, sampled on each mouse event). */
struct DragModifiers {
    bool fine = false;     ///< Shift: a tenth of the motion, and the fine step
    bool precise = false;  ///< Ctrl: an angle snaps by degrees instead of by the flute pitch
};

/**
 * @brief The step an angle snaps to: the flute pitch (@p pitch > 0, radians) unless Ctrl; otherwise 1°, or
 *        0.1° with Shift. So θ about a drum axis: the pitch, Ctrl 1°, Ctrl+Shift 0.1°; a ring without
 *        flutes (pitch 0): 1°, Shift 0.1°.
 */
double angleStep(double pitch, DragModifiers modifiers);
/** @brief The step a length snaps to: 1 mm, or 0.1 mm with Shift (metres). */
double lengthStep(DragModifiers modifiers);
/** @brief @p value rounded to the nearest multiple of @p step (> 0; halves away from zero); @p value when
 *         @p step ≤ 0. */
double snapToStep(double value, double step);

/**
 * @brief What a drag has moved so far, in the handle's own unit (metres along an arrow, radians about a ring):
 *        the raw motion of the cursor accumulated increment by increment, each at a tenth with Shift, so that
 *        pressing or releasing Shift mid-drag never jumps. value() is then snapped by the caller.
 */
class FineDrag {
public:
    /** @brief Starts at @p raw (the raw parameter at the press): value() is 0. */
    explicit FineDrag(double raw = 0.0) : m_last(raw) {}
    /** @brief The raw parameter is now @p raw; returns value(). */
    double feed(double raw, bool fine);
    double value() const { return m_value; }

private:
    double m_last;
    double m_value = 0.0;
};

} // namespace stylos::core::view
