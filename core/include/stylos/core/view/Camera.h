#pragma once
/** @file
 * @brief The 3D view's camera, pure maths (no GL, no Qt): an orbit camera looking at a target from a
 *        distance, oriented by a rotation, with a perspective or an orthographic projection; standard
 *        views, fitting a box, the OpenGL view and projection matrices, and the ray through a pixel.
 *
 * Frames: the scene frame is right-handed with +Z up (scans are levelled). The camera frame is OpenGL's:
 * the camera looks along its −Z, +Y is up on screen, +X right. orientation() rotates camera axes into
 * scene axes (its columns are right, up and back = −forward, in scene coordinates); the eye is
 * target + back · distance.
 * Pixels: x to the right, y downwards, (0, 0) the top-left corner of the viewport and (width, height)
 * its bottom-right corner (so the centre of the pixel (i, j) is (i + 0.5, j + 0.5)).
 * Orthographic: the view height at any depth is the perspective view height at the target,
 * 2 · distance · tan(fov / 2), so switching projection keeps what is at the target the same size.
 * Clip planes follow the scene bounds (setSceneBounds) so that the whole scene is never clipped.
 * Units: metres, radians, pixels. Thread-safety: a plain value type; not thread-safe for writing, copy it
 * to share. Failure modes: none; out-of-range values are clamped (setViewport, setFieldOfView, setDistance)
 * or ignored (dolly by a non-positive factor, fit to an empty box).
 */
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include <optional>

namespace stylos::core::view {

/** @brief The standard views: where the camera looks from (Front: from −Y toward +Y, Z up). */
enum class StandardView { Front, Back, Left, Right, Top, Bottom, Iso };

/** @brief A ray in the scene frame; `direction` is unit. */
struct Ray {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();
};

class Camera {
public:
    /** @brief A 640 × 480 perspective camera (45° vertical field) looking at the origin from the front, 2 m away. */
    Camera();

    /** @brief The viewport in pixels; both ≥ 1 (smaller values count as 1). */
    void setViewport(int width, int height);
    int width() const { return m_width; }
    int height() const { return m_height; }
    double aspect() const { return double(m_width) / double(m_height); }

    /** @brief Vertical field of view in radians, clamped to [1e-3, 3]. */
    void setFieldOfView(double radians);
    double fieldOfView() const { return m_fov; }

    void setOrthographic(bool orthographic) { m_orthographic = orthographic; }
    bool isOrthographic() const { return m_orthographic; }

    void setTarget(const Eigen::Vector3d& target) { m_target = target; }
    const Eigen::Vector3d& target() const { return m_target; }
    /** @brief Distance from the eye to the target in metres, clamped to ≥ 1e-6. */
    void setDistance(double metres);
    double distance() const { return m_distance; }
    /** @brief Camera → scene rotation (normalised on the way in). */
    void setOrientation(const Eigen::Quaterniond& orientation);
    const Eigen::Quaterniond& orientation() const { return m_orientation; }

    Eigen::Vector3d eye() const;
    Eigen::Vector3d forward() const;   ///< unit, scene frame
    Eigen::Vector3d up() const;        ///< unit, scene frame
    Eigen::Vector3d right() const;     ///< unit, scene frame

    /** @brief The scene's bounds, used for the clip planes; an empty box means unknown. */
    void setSceneBounds(const Eigen::AlignedBox3d& bounds) { m_bounds = bounds; }
    const Eigen::AlignedBox3d& sceneBounds() const { return m_bounds; }

    /**
     * @brief Turntable orbit about the target: @p yaw about the scene's +Z axis (positive: the eye moves
     *        counter-clockwise seen from above), then @p pitch about the camera's right axis (positive: the
     *        eye rises). Radians. The distance and the target are kept.
     */
    void orbit(double yaw, double pitch);
    /** @brief Moves the target (and the eye) so that the scene follows a drag of (@p dx, @p dy) pixels. */
    void pan(double dx, double dy);
    /** @brief Multiplies the distance by @p factor (> 0; < 1 moves closer). Also zooms an orthographic view. */
    void dolly(double factor);
    /** @brief Orientation of a standard view; keeps the target and distance. */
    void setStandardView(StandardView view);
    /** @brief The rotation of a standard view (camera → scene). */
    static Eigen::Quaterniond standardOrientation(StandardView view);
    /**
     * @brief Centres on @p box and sets the smallest distance at which its eight corners are in view,
     *        with a 5 % margin, keeping the orientation and projection. An empty box is ignored.
     */
    void fit(const Eigen::AlignedBox3d& box);
    /**
     * @brief Frames @p points (scene frame; e.g. the corners of the cells a scene occupies): keeping the
     *        orientation and projection, the eye goes where the points' picture is centred and fills the view
     *        in width or in height, then backs off by the 5 % margin; the target is at the depth of the
     *        points' bounding box centre (what an orbit turns about). Exact for a perspective view: the
     *        smallest distance at which every point is inside the frustum. No points: ignored.
     */
    void fit(const std::vector<Eigen::Vector3d>& points);

    /** @brief Scene → camera (OpenGL convention). */
    Eigen::Matrix4d viewMatrix() const;
    /** @brief Camera → clip (OpenGL convention, depth in [−1, 1]). */
    Eigen::Matrix4d projectionMatrix() const;
    Eigen::Matrix4d viewProjection() const { return projectionMatrix() * viewMatrix(); }
    /** @brief Distances to the near and far clip planes along the view direction, metres (near may be
     *         negative in orthographic mode). */
    double nearPlane() const;
    double farPlane() const;

    /** @brief Height of the view at the target's depth, metres (the orthographic view height). */
    double viewHeight() const;
    /** @brief Perspective: viewport height / field of view (pixels per radian at the centre). */
    double pixelsPerRadian() const { return double(m_height) / m_fov; }
    /** @brief Pixels per metre at the target's depth (everywhere in orthographic mode). */
    double pixelsPerMetre() const { return double(m_height) / viewHeight(); }

    /** @brief The ray through the pixel position (@p x, @p y): from the eye (perspective) or from the
     *         near plane's point (orthographic), direction unit. */
    Ray rayAt(double x, double y) const;
    /** @brief (pixel x, pixel y, NDC depth) of @p point; empty when it lies behind the eye (w ≤ 0). */
    std::optional<Eigen::Vector3d> project(const Eigen::Vector3d& point) const;

private:
    void clipRange(double& nearPlane, double& farPlane) const;

    int m_width = 640;
    int m_height = 480;
    double m_fov = 0.7853981633974483;
    bool m_orthographic = false;
    Eigen::Vector3d m_target = Eigen::Vector3d::Zero();
    double m_distance = 2.0;
    Eigen::Quaterniond m_orientation;
    Eigen::AlignedBox3d m_bounds;
};

} // namespace stylos::core::view
