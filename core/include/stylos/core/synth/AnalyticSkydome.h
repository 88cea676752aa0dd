#pragma once
/** @file
 * @brief The 3D skydome of a synthetic object's TRUE surface, against its exact solid: the reference
 *        that the octree methods (core/ao) are measured with in stylos_ao_truth (docs/benchmarks.md).
 *
 * The value of a true surface point p with true unit normal n, over a direction set d_k (those of the
 * method, ao/Directions.h, given here in the object's frame): Σ_k [n·d_k > 0]·free_k / Σ_k [n·d_k > 0]
 * (0 when no direction is in front), the definition of AmbientOcclusion.h with binary visibility. A
 * direction is free when the ray p + t·d, t from `start` to where it leaves the solid's bounding sphere,
 * never enters the solid. The ray is marched: where the solid's clearance (a lower bound of the distance
 * to it) is positive the march steps by it (sphere tracing), elsewhere by `step` (well below the finest
 * feature of the generated shapes: claw marks 0.3 mm deep at a 3 mm pitch, flutes 8 mm deep), testing
 * inside(q) at every sample. A feature thinner than `step` along the ray can be missed.
 * Thread-safety: reentrant (the solids are immutable). Failure modes: none.
 */
#include "stylos/core/synth/SyntheticObject.h"

#include <Eigen/Core>

#include <array>
#include <memory>
#include <vector>

namespace stylos::core::synth {

class DrumShape;
class FragmentShape;

/** @brief A solid the analytic skydome marches rays against (object frame, metres). */
class AnalyticSolid {
public:
    virtual ~AnalyticSolid() = default;
    /** Whether @p p lies inside the solid. */
    virtual bool inside(const Eigen::Vector3d& p) const = 0;
    /** A lower bound of the distance from @p p to the solid: > 0 only where @p p is surely outside. */
    virtual double clearance(const Eigen::Vector3d& p) const = 0;
    /** A sphere holding the whole solid: its centre and radius. */
    virtual Eigen::Vector3d boundCentre() const = 0;
    virtual double boundRadius() const = 0;
};

/** The drum's solid (DrumShape::inside); clearance: the distance to its bounding cylinder. */
std::unique_ptr<AnalyticSolid> drumSolid(const DrumShape& drum);
/** The fragment's solid (FragmentShape::inside); clearance: the distance to the sector of annulus
 *  (fracture bound included) that holds it. */
std::unique_ptr<AnalyticSolid> fragmentSolid(const FragmentShape& fragment);
/** The solid of a DrumShape or FragmentShape; nullptr for any other object (the omphalos). */
std::unique_ptr<AnalyticSolid> analyticSolid(const SyntheticObject& object);

struct AnalyticSkydomeOptions {
    double step = 1e-4;   ///< march step where the clearance is 0, metres
    double start = 1e-6;  ///< first t along the ray, metres (the point lies on the surface)
};

/** @brief What one point sees: directions in front of its normal and how many of them are free. */
struct AnalyticSkyCount {
    int front = 0;
    int free = 0;
    double value() const { return front > 0 ? double(free) / double(front) : 0.0; }
};

/** @brief The visible-sky count of the point @p p (on the solid's surface) with unit normal @p n over
 *         @p directions (unit, object frame). */
AnalyticSkyCount analyticSkydome(const AnalyticSolid& solid, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                 const std::vector<std::array<double, 3>>& directions,
                                 const AnalyticSkydomeOptions& options = {});

/** @brief Whether the ray @p p + t·@p d (t ≥ options.start) enters the solid before leaving its
 *         bounding sphere. */
bool analyticRayBlocked(const AnalyticSolid& solid, const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                        const AnalyticSkydomeOptions& options = {});

} // namespace stylos::core::synth
