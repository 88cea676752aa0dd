#include "stylos/core/dock/ContactReadout.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stylos::core::dock {
namespace {

constexpr double kHalfMillimetre = 0.0005;

Error invalid(const cloud::PointCloud& cloud, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, cloud.source.empty() ? "<memory>" : cloud.source, {}, problem);
}

/** The @p p-quantile of the sorted @p values, linear between order statistics at p·(n − 1). */
double quantile(const std::vector<double>& values, double p)
{
    const double at = p * double(values.size() - 1);
    const std::size_t low = std::size_t(std::floor(at));
    const std::size_t high = std::min(low + 1, values.size() - 1);
    return values[low] + (at - double(low)) * (values[high] - values[low]);
}

} // namespace

ContactReadout summariseContact(std::vector<double> d)
{
    ContactReadout readout;
    readout.points = d.size();
    if (d.empty()) return readout;
    std::sort(d.begin(), d.end());
    readout.largestInterpenetration = std::max(0.0, -d.front());
    readout.medianGap = quantile(d, 0.5);
    readout.gap90 = quantile(d, 0.9);
    readout.gap99 = quantile(d, 0.99);
    const auto within = std::count_if(d.begin(), d.end(), [](double v) { return std::abs(v) <= kHalfMillimetre; });
    readout.withinHalfMillimetre = double(within) / double(d.size());
    return readout;
}

double profileDistance(const FluteModel& model, const Eigen::Vector3d& p, Eigen::Vector3d* normal)
{
    return model.distance(p, normal);
}

Result<ContactReadout> measureContact(const cloud::PointCloud& fragment, const DrumGuides& guides,
                                      const Eigen::Isometry3d& pose, const ContactOptions& options)
{
    auto model = FluteModel::fromGuides(guides);
    if (!model) return invalid(fragment, model.error().message);
    if (!pose.matrix().allFinite()) return invalid(fragment, "the pose is not finite");
    const DrumFrame frame(guides);
    // Cloud-local → drum frame, in one rigid motion.
    Eigen::Isometry3d toFrame = Eigen::Isometry3d::Identity();
    toFrame.linear() = frame.rows * pose.linear();
    toFrame.translation() = frame.rows * (pose * fragment.origin - frame.origin);

    const std::size_t n = fragment.size();
    const std::size_t stride = std::max<std::size_t>(1, (n + options.maxPoints - 1) / std::max<std::size_t>(options.maxPoints, 1));
    std::vector<double> d;
    d.reserve(n / stride + 1);
    Eigen::Vector3d normal;
    std::size_t measured = 0;
    for (std::size_t i = 0; i < n; i += stride) {
        const Eigen::Vector3d q = toFrame * fragment.local(i);
        if (!q.allFinite()) continue;
        ++measured;
        const double distance = profileDistance(*model, q, &normal);
        if (!(std::abs(distance) <= options.band)) continue;
        if (fragment.hasNormals() && std::abs(normal.dot(toFrame.linear() * fragment.normal(i))) < options.normalCosine)
            continue;
        d.push_back(distance);
    }
    // A few stray points in the band (a fragment 15 cm off the drum read "4.95 mm interpenetration" from one) are
    // no contact.
    if (double(d.size()) < options.minShare * double(measured)) d.clear();
    return summariseContact(std::move(d));
}

} // namespace stylos::core::dock
