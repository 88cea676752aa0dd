#pragma once
/** @file
 * @brief The contact of a docked fragment against the guides of a drum: how far its outer face lies from the
 *        guides' flute profile (FluteModel), point by point, summed up as the largest interpenetration and the
 *        distribution of the gaps — what the Properties dock shows after a dock or a move.
 *
 * Each point of the fragment (its file frame, placed into the drum file frame by the pose) is taken into the
 * drum frame (DrumFrame): distance ρ from the axis, azimuth φ. Its signed distance to the profile along the
 * profile's normal is d = (ρ − P(φ)) / √(1 + (P′(φ)/ρ)²), the first-order distance DockRegistration minimises
 * (exact on a flat part of the profile, P′ = 0): positive outside the drum (a gap), negative inside it (the
 * fragment would cut into the drum). The outer face is the points with |d| ≤ band (5 mm by default, like the
 * registration's inliers the fracture faces and beds far from the profile carry no weight) and, when the cloud
 * has normals, whose normal is within acos(normalCosine) of the profile's normal either way (so the fracture faces
 * that meet the outer face, perpendicular to it, are left out even inside the band).
 *
 * The readout over those points: the largest interpenetration max(0, −min d); the median, 90th and 99th
 * percentiles of d (linear interpolation between order statistics: p·(n − 1)); the share with |d| ≤ 0.5 mm;
 * their number. A fragment that does not touch the drum (fewer than minShare of its points measured in the band:
 * none, or a few strays) gives points = 0 and zeros.
 *
 * Failure (InvalidArgument, naming the fragment's source): guides without a flute profile, a pose that is not
 * finite. Units: metres, radians. Thread-safety: reentrant. Cost: O(n), a fixed stride down to maxPoints,
 * then one sort of the kept distances.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/dock/FluteModel.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace stylos::core::dock {

struct ContactOptions {
    double band = 0.005;             ///< metres: points within ± band of the profile are the outer face
    double normalCosine = 0.8;       ///< with normals: |n · profile normal| at least this
    std::size_t maxPoints = 200'000; ///< fragment points used (fixed stride)
    double minShare = 0.01;          ///< fewer of the points measured on the outer face: it does not touch
};

struct ContactReadout {
    std::size_t points = 0;               ///< outer-face points measured
    double largestInterpenetration = 0.0; ///< metres, ≥ 0: how deep the deepest point lies inside the profile
    double medianGap = 0.0;               ///< metres, signed (negative: inside)
    double gap90 = 0.0;                   ///< 90th percentile of the signed distance, metres
    double gap99 = 0.0;                   ///< 99th percentile, metres
    double withinHalfMillimetre = 0.0;    ///< share of the points with |d| ≤ 0.5 mm, 0..1
};

/** @brief The readout of the signed distances @p distances (metres, any order): their number, the largest
 *         interpenetration, the percentiles and the share within 0.5 mm as above; zeros when empty. */
ContactReadout summariseContact(std::vector<double> distances);

/** @brief The signed distance (metres) of @p framePoint (drum frame) to the profile of @p model along its normal,
 *         and that unit normal (drum frame, outward) in @p normal when given. See the file comment. */
double profileDistance(const FluteModel& model, const Eigen::Vector3d& framePoint, Eigen::Vector3d* normal = nullptr);

/** @brief The contact of @p fragment (its file frame) placed by @p pose into the drum file frame against
 *         @p guides (with a profile). See the file comment. */
Result<ContactReadout> measureContact(const cloud::PointCloud& fragment, const DrumGuides& guides,
                                      const Eigen::Isometry3d& pose, const ContactOptions& options = {});

} // namespace stylos::core::dock
