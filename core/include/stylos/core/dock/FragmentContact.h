#pragma once
/** @file
 * @brief The contact of a docked fragment against another fragment of its assembly: how far the fragment's points
 *        lie from the other's surface, summed up as ContactReadout does against the drum's guides (the largest
 *        interpenetration, the median, 90th and 99th percentiles of the signed distance, the share within 0.5 mm).
 *
 * Method. The other's points (a fixed stride down to maxOtherPoints), with their normals, are carried into the
 * fragment's file frame by @p otherToFragment and put in a k-d tree (nanoflann). For each fragment point (a fixed
 * stride down to maxPoints), its nearest other point q with normal n gives the signed distance d = (p − q)·n:
 * positive outside the other piece (a gap), negative inside it (the pieces would cut into each other) — the
 * point-to-plane distance, exact on a flat break face sampled around q. A point counts when |p − q| ≤ band (5 mm:
 * the faces that meet; the rest of the piece is far away) and, when the fragment has normals, its normal is within
 * acos(normalCosine) of ±n (the facing break faces, n_p ≈ −n, and the outer faces beside the joint).
 * No point within the band: points = 0 and zeros (the pieces do not touch).
 *
 * Failure (InvalidArgument): the other cloud without normals (naming its source), a pose that is not finite.
 * Units: metres. Thread-safety: reentrant. Cost: O(m log m) to build the tree over m ≤ maxOtherPoints, O(log m)
 * per fragment point; memory 40 bytes per other point kept.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/dock/ContactReadout.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <cstddef>

namespace stylos::core::dock {

struct FragmentContactOptions {
    double band = 0.005;                   ///< metres: how near the other's surface a point must be
    double normalCosine = 0.8;             ///< with normals: |n_p · n| at least this
    std::size_t maxPoints = 100'000;       ///< fragment points used (fixed stride)
    std::size_t maxOtherPoints = 200'000;  ///< other points in the tree (fixed stride)
};

/** @brief The contact of @p fragment (its file frame) with @p other (its file frame, with normals) placed into the
 *         fragment's frame by @p otherToFragment. See the file comment. */
Result<ContactReadout> measureFragmentContact(const cloud::PointCloud& fragment, const cloud::PointCloud& other,
                                              const Eigen::Isometry3d& otherToFragment,
                                              const FragmentContactOptions& options = {});

} // namespace stylos::core::dock
