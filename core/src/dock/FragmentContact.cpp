#include "stylos/core/dock/FragmentContact.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace stylos::core::dock {
namespace {

Error invalid(const cloud::PointCloud& cloud, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, cloud.source.empty() ? "<memory>" : cloud.source, {}, problem);
}

/** nanoflann dataset adaptor over the other's points (fragment-local coordinates). */
struct Points {
    std::vector<Eigen::Vector3d> p;
    std::size_t kdtree_get_point_count() const { return p.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return p[i][Eigen::Index(d)]; }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Points, double, std::uint32_t>,
                                                 Points, 3, std::uint32_t>;

std::size_t strideFor(std::size_t n, std::size_t cap)
{
    return std::max<std::size_t>(1, (n + cap - 1) / std::max<std::size_t>(cap, 1));
}

} // namespace

Result<ContactReadout> measureFragmentContact(const cloud::PointCloud& fragment, const cloud::PointCloud& other,
                                              const Eigen::Isometry3d& otherToFragment,
                                              const FragmentContactOptions& options)
{
    if (!other.hasNormals()) return invalid(other, "the other fragment has no normals to measure a contact against");
    if (!otherToFragment.matrix().allFinite()) return invalid(fragment, "the pose of the other fragment is not finite");
    // The other's points in the fragment's cloud-local coordinates (small numbers, whatever the site frame).
    Eigen::Isometry3d toLocal = Eigen::Translation3d(-fragment.origin) * otherToFragment;
    Points points;
    std::vector<Eigen::Vector3d> normals;
    const std::size_t otherStride = strideFor(other.size(), options.maxOtherPoints);
    points.p.reserve(other.size() / otherStride + 1);
    normals.reserve(points.p.capacity());
    for (std::size_t i = 0; i < other.size(); i += otherStride) {
        const Eigen::Vector3d q = toLocal * other.world(i);
        const Eigen::Vector3d n = toLocal.linear() * other.normal(i);
        if (!q.allFinite() || !(n.norm() > 0.5)) continue;
        points.p.push_back(q);
        normals.push_back(n.normalized());
    }
    if (points.p.empty()) return summariseContact({});
    Tree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(16));

    const double band2 = options.band * options.band;
    std::vector<double> d;
    const std::size_t stride = strideFor(fragment.size(), options.maxPoints);
    for (std::size_t i = 0; i < fragment.size(); i += stride) {
        const Eigen::Vector3d p = fragment.local(i);
        std::uint32_t nearest = 0;
        double distance2 = 0.0;
        if (tree.knnSearch(p.data(), 1, &nearest, &distance2) != 1 || !(distance2 <= band2)) continue;
        const Eigen::Vector3d& n = normals[nearest];
        if (fragment.hasNormals() && std::abs(n.dot(fragment.normal(i))) < options.normalCosine) continue;
        d.push_back((p - points.p[nearest]).dot(n));
    }
    return summariseContact(std::move(d));
}

} // namespace stylos::core::dock
