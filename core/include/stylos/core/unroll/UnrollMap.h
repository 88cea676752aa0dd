#pragma once
/** @file
 * @brief The map between a développée image and 3D, both ways, and its JSON sidecar.
 *
 * Frame: the surface's axis (point o, unit direction a), a reference direction e1 ⊥ a (chosen by the
 * unroller, see defaultReferenceDir(), and stored), e2 = a × e1. For a world point p, d = p − o:
 *     t = d·a,  x = d·e1,  y = d·e2,  r = √(x² + y²),  φ = atan2(y, x)   (counter-clockwise about a),
 *     u = R · ((φ − cutAngle) mod 2π) ∈ [0, 2π·R)      (R = surface.referenceRadius()),
 *     (v, h) = surface.meridianCoords(t, r)             (Surface.h; h positive outward).
 * u grows to the right for a viewer outside the surface with the axis pointing up, so (u, v, h) is
 * right-handed like the HeightField frame (x right, y up, z toward the viewer).
 * The inverse: (t, r) = surface.meridianPoint(v, h), φ = u / R + cutAngle,
 *     p = o + t·a + r·(cos φ · e1 + sin φ · e2).
 *
 * Image (s = pixel size): column c covers u ∈ [c·s, (c+1)·s); row r covers v ∈ (vTop − (r+1)·s, vTop − r·s]
 * (row 0 at the top, v upward). Continuous pixel coordinates: column = u / s, row = (vTop − v) / s, so
 * pixel (c, r) is the set floor(column) = c, floor(row) = r and its centre is (c + 0.5, r + 0.5).
 * The width is ceil(2π·R / s) for the whole turn: u wraps with a period of P = 2π·R / s columns, generally
 * not an integer, so the last column is partial. A fragment's image (UnrollOptions::cropToPoints) covers only
 * its arc, from the cut: width < P, and pixelOf() gives columns ≥ width for points off the arc (outside). pixelOf() gives columns in [0, P); worldAtPixel() takes any
 * column (periodic in P), so a position of the last column past P comes back from pixelOf() as P less.
 *
 * Exactness: worldAt() and surfaceCoords() are inverses up to rounding (a few 1e-16 relative), for any
 * surface wherever the surface's own meridian map is (Meridian.h). pixelOf(worldAtPixel(c, r, h)) gives
 * back (c, r, h) to rounding for c in [0, P); hence clicks map to within half a pixel.
 *
 * Sidecar: a JSON object
 *     {"format": "stylos-unroll", "version": 1, "units": "metres, radians",
 *      "surface": Surface::toJson(), "reference_dir": [x, y, z], "cut_angle": radians,
 *      "pixel_size": metres, "width": pixels, "height": pixels, "v_top": metres}
 * written atomically (temporary file beside the target, then rename) next to the image (OUT + ".json" is
 * the CLI's choice). Reading checks every key: "format" must be "stylos-unroll", "version" must be 1,
 * numbers finite, pixel_size > 0, width and height integers in [1, HeightField::kMaxSide], reference_dir
 * a unit vector (within 1e-6) perpendicular to the axis (within 1e-6). Doubles are written in their
 * shortest exact form, so a map read back is the map written (but for the last bit of the axis
 * direction, which Surface::fromJson normalises again).
 *
 * Units: metres, radians. Thread-safety: a value type; const methods are safe concurrently.
 */
#include "stylos/core/unroll/Surface.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

namespace stylos::core::unroll {

/** @brief Where a 3D point lands: continuous pixel coordinates and its height. */
struct PixelHit {
    double column = 0.0; ///< continuous: pixel c spans [c, c+1)
    double row = 0.0;
    double h = 0.0;      ///< metres above the surface
};

/**
 * @brief The deterministic reference direction e1 for an axis direction @p axisDirection (unit):
 *        world X made perpendicular to it, or world Y when |X · a| > 0.9 (X nearly along the axis);
 *        a unit vector ⊥ a.
 */
Eigen::Vector3d defaultReferenceDir(const Eigen::Vector3d& axisDirection);

class UnrollMap {
public:
    static constexpr int kVersion = 1;          ///< sidecar version written and read
    static constexpr const char* kFormat = "stylos-unroll";

    /**
     * @brief The map of an image of @p width × @p height pixels of @p pixelSize metres.
     * @param referenceDir e1: made exactly perpendicular to the axis and unit when it is off by more
     *        than 1e-12 (kept bit for bit otherwise, so a sidecar round trip is exact). Programmer
     *        errors (asserted): referenceDir within 30° of the axis or not finite, pixelSize ≤ 0 or not
     *        finite, a negative size, cutAngle or vTop not finite.
     */
    UnrollMap(Surface surface, Eigen::Vector3d referenceDir, double cutAngle, double pixelSize, int width,
              int height, double vTop);

    const Surface& surface() const { return m_surface; }
    const Eigen::Vector3d& referenceDir() const { return m_e1; }
    /** e2 = axis direction × e1. */
    const Eigen::Vector3d& secondDir() const { return m_e2; }
    double cutAngle() const { return m_cutAngle; }
    double pixelSize() const { return m_pixelSize; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    double vTop() const { return m_vTop; }
    /** 2π · referenceRadius, metres: the period of u. */
    double circumference() const { return m_circumference; }

    /** @brief A world point about the axis: d = p − o, t = d·a, x = d·e1, y = d·e2, r = √(x² + y²), metres. */
    struct AxialCoords {
        double t = 0.0;
        double x = 0.0;
        double y = 0.0;
        double r = 0.0;
    };
    AxialCoords axialCoords(const Eigen::Vector3d& world) const
    {
        // Written out (not Eigen's dot) so that every caller computes the same bits.
        const Eigen::Vector3d& o = m_surface.axis().point;
        const Eigen::Vector3d& a = m_surface.axis().direction;
        const double dx = world.x() - o.x(), dy = world.y() - o.y(), dz = world.z() - o.z();
        AxialCoords c;
        c.t = dx * a.x() + dy * a.y() + dz * a.z();
        c.x = dx * m_e1.x() + dy * m_e1.y() + dz * m_e1.z();
        c.y = dx * m_e2.x() + dy * m_e2.y() + dz * m_e2.z();
        c.r = std::sqrt(c.x * c.x + c.y * c.y);
        return c;
    }
    /** @brief (atan2(y, x) − cutAngle) mod 2π, in [0, 2π): the angle from the seam of a point whose
     *         axialCoords are (x, y) (−0 rounding past 2π is mapped to 0). u = referenceRadius · angle. */
    double angleFrom(double x, double y) const;

    /** @brief (u, v, h) of a world point, metres; nullopt when the surface gives it no meridian
     *         coordinates (a revolution, farther than the meridian's reach) or it is not finite. */
    std::optional<Eigen::Vector3d> surfaceCoords(const Eigen::Vector3d& world) const;
    /** @brief World point at surface coordinates (u, v, h), any u (periodic): the exact inverse of
     *         surfaceCoords() (up to rounding). */
    Eigen::Vector3d worldAt(double u, double v, double h) const;
    /** @brief Continuous pixel coordinates and h of a world point (may fall outside the image rows);
     *         nullopt as for surfaceCoords(). */
    std::optional<PixelHit> pixelOf(const Eigen::Vector3d& world) const;
    /** @brief World point at continuous pixel coordinates and height @p h (metres). */
    Eigen::Vector3d worldAtPixel(double column, double row, double h) const;

    /** The sidecar object (see the file comment). */
    nlohmann::json toJson() const;
    /** @brief Reads toJson()'s object; Malformed "SOURCE: KEY: problem" naming the key that is missing
     *         or wrong (a wrong "format" or "version" included). */
    static Result<UnrollMap> fromJson(const nlohmann::json& json, const std::string& source);
    /** @brief Writes toJson() to @p path atomically (PATH.part, then rename); WriteFailed naming the
     *         path, nothing left behind. */
    Status writeSidecar(const std::filesystem::path& path) const;
    /** @brief Reads a sidecar: NotFound (no such file), Unreadable, Malformed (not JSON, with the line and
     *         column; or a key missing or wrong, as fromJson), each naming the path. */
    static Result<UnrollMap> readSidecar(const std::filesystem::path& path);

private:
    Surface m_surface;
    Eigen::Vector3d m_e1, m_e2;
    double m_cutAngle;
    double m_pixelSize;
    int m_width;
    int m_height;
    double m_vTop;
    double m_circumference;
};

} // namespace stylos::core::unroll
