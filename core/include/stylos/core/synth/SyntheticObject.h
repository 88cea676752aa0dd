#pragma once
/** @file
 * @brief What the scan simulator needs from a synthetic object: its surface as patches, where its
 *        scanners stand, and its ground truth. The object frame has the axis of revolution (drum,
 *        omphalos, the fragment's parent drum) through the origin along +z, z = 0 at the lower bed or
 *        base. Units: metres, radians. Immutable once built; thread-safe.
 */
#include "stylos/core/synth/SurfacePatch.h"

#include <nlohmann/json_fwd.hpp>

#include <Eigen/Core>

#include <vector>

namespace stylos::core::synth {

class SyntheticObject {
public:
    virtual ~SyntheticObject() = default;

    /** The surface, as patches that together close the object (or the scanned part of it). */
    virtual std::vector<const SurfacePatch*> patches() const = 0;
    /** Point the scanners look at, object frame (metres); patches' azimuths are about the vertical
     *  line through it. */
    virtual Eigen::Vector3d scanCentre() const = 0;
    /** Radius of a horizontal circle around scanCentre() that encloses the object, metres. */
    virtual double extent() const = 0;
    /** Height of the object above z = 0, metres (scanners stand a little above it). */
    virtual double height() const = 0;
    /** Adds the kind-specific truth (shape parameters, object frame) to @p truth. */
    virtual void describe(nlohmann::json& truth) const = 0;
};

} // namespace stylos::core::synth
