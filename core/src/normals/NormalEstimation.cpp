#include "stylos/core/normals/NormalEstimation.h"

#include "NeighbourIndex.h"
#include "NormalJob.h"
#include "stylos/core/normals/NeighbourhoodPca.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace stylos::core::normals {
namespace detail {
namespace {

using Vec3 = std::array<double, 3>;

constexpr double kBuildShare = 0.25;       ///< progress fraction given to building the index
constexpr std::size_t kLeavesPerChunk = 64; ///< ~750 points: the unit of work and of cancel checks

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/** @p v normalised, or @p fallback when it has no length. */
Vec3 unitOr(const Vec3& v, const Vec3& fallback)
{
    const double length = std::sqrt(dot(v, v));
    if (!(length > 0.0) || !std::isfinite(length)) return fallback;
    return {v[0] / length, v[1] / length, v[2] / length};
}

/** Any unit vector perpendicular to the unit vector @p a. */
Vec3 perpendicular(const Vec3& a)
{
    const Vec3 helper = std::abs(a[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 c{a[1] * helper[2] - a[2] * helper[1], a[2] * helper[0] - a[0] * helper[2],
                 a[0] * helper[1] - a[1] * helper[0]};
    return unitOr(c, {0, 0, 1});
}

/** Everything a worker needs, shared read-only (plus the atomics). */
struct Shared {
    const NormalJob& job;
    const NormalOptions& options;
    const NeighbourIndex& index;
    Vec3 localCentre;    ///< centre − origin
    Vec3 localViewpoint; ///< viewpoint − origin
    std::optional<std::array<double, 6>> localBox;
    std::atomic<std::size_t> nextChunk{0};
    std::atomic<std::size_t> pointsDone{0};
    std::atomic<bool> cancelled{false};
    std::atomic<std::uint64_t> degenerate{0};
    std::atomic<std::uint64_t> truncated{0};
};

/** Normal, quality and flags of one query whose neighbours are in @p scratch row @p q. */
void finishPoint(Shared& shared, const KnnScratch& scratch, std::size_t q, std::uint32_t rank,
                 std::uint64_t& degenerate, std::uint64_t& truncated)
{
    const NeighbourIndex& index = shared.index;
    const std::size_t count = scratch.counts[q];
    CovarianceAccumulator accumulator;
    for (std::size_t j = 0; j < count; ++j) {
        const double* p = index.localPosition(scratch.neighbour(q, j));
        accumulator.add(p[0], p[1], p[2]);
    }
    const PlaneFit fit = fitPlane(accumulator.covariance(), count);
    const double* p = index.localPosition(rank);
    const Vec3 point{p[0], p[1], p[2]};
    const bool towardViewpoint = shared.options.orientation == NormalOrientation::TowardViewpoint;
    const Vec3 reference = towardViewpoint
        ? Vec3{shared.localViewpoint[0] - p[0], shared.localViewpoint[1] - p[1], shared.localViewpoint[2] - p[2]}
        : Vec3{p[0] - shared.localCentre[0], p[1] - shared.localCentre[1], p[2] - shared.localCentre[2]};

    Vec3 normal = fit.normal;
    if (fit.shape == NeighbourhoodShape::Surface) {
        if (shared.options.orientation != NormalOrientation::Unoriented && dot(normal, reference) < 0.0)
            normal = {-normal[0], -normal[1], -normal[2]};
    } else if (fit.shape == NeighbourhoodShape::Collinear) {
        const double along = dot(reference, fit.axis);
        const Vec3 across{reference[0] - along * fit.axis[0], reference[1] - along * fit.axis[1],
                          reference[2] - along * fit.axis[2]};
        normal = dot(across, across) > 1e-24 * dot(reference, reference) ? unitOr(across, perpendicular(fit.axis))
                                                                       : perpendicular(fit.axis);
        ++degenerate;
    } else {
        normal = unitOr(reference, {0, 0, 1});
        ++degenerate;
    }

    const std::size_t source = index.sourceOf(rank);
    for (int d = 0; d < 3; ++d) shared.job.normals[3 * source + d] = static_cast<float>(normal[d]);
    if (!shared.job.quality.empty()) shared.job.quality[source] = static_cast<float>(fit.surfaceVariation);

    if (shared.localBox) {
        const auto& box = *shared.localBox;
        double room = std::numeric_limits<double>::max();
        for (int d = 0; d < 3; ++d) room = std::min({room, point[d] - box[d], box[3 + d] - point[d]});
        const double reach = count == 0 ? 0.0 : std::sqrt(double(scratch.squaredDistance(q, count - 1)));
        const bool fewer = count < shared.options.neighbours && count < shared.job.cloudPoints;
        if (fewer || reach * 1.0001 >= room) ++truncated;
    }
}

void work(Shared& shared, bool reportsProgress, ProgressSink* progress)
{
    const NeighbourIndex& index = shared.index;
    const auto leaves = index.leaves();
    const std::size_t chunks = (leaves.size() + kLeavesPerChunk - 1) / kLeavesPerChunk;
    const std::size_t queryCount = shared.job.queryCount;
    KnnScratch scratch;
    std::vector<std::uint32_t> queries;
    std::uint64_t degenerate = 0, truncated = 0;
    for (;;) {
        if (shared.cancelled.load(std::memory_order_relaxed)) break;
        if (progress && progress->isCancelRequested()) {
            shared.cancelled.store(true);
            break;
        }
        const std::size_t chunk = shared.nextChunk.fetch_add(1);
        if (chunk >= chunks) break;
        std::size_t done = 0;
        const std::size_t last = std::min(leaves.size(), (chunk + 1) * kLeavesPerChunk);
        for (std::size_t l = chunk * kLeavesPerChunk; l < last; ++l) {
            queries.clear();
            for (std::uint32_t position = leaves[l].begin; position < leaves[l].end; ++position)
                if (index.sourceOf(index.rankAt(position)) < queryCount) queries.push_back(position);
            if (queries.empty()) continue;
            index.search(queries, shared.options.neighbours, scratch);
            for (std::size_t q = 0; q < queries.size(); ++q)
                finishPoint(shared, scratch, q, index.rankAt(queries[q]), degenerate, truncated);
            done += queries.size();
        }
        const std::size_t total = shared.pointsDone.fetch_add(done) + done;
        if (reportsProgress && progress)
            progress->update(kBuildShare + (1.0 - kBuildShare) * double(total) / double(queryCount));
    }
    shared.degenerate += degenerate;
    shared.truncated += truncated;
}

} // namespace

std::optional<Error> checkNormalOptions(const NormalOptions& options)
{
    if (options.neighbours < 3 || options.neighbours > 256)
        return Error{ErrorCode::InvalidArgument,
                     "normal estimation: neighbours must be in [3, 256], got " + std::to_string(options.neighbours)};
    if (options.leafSize < 1 || options.leafSize > 1024)
        return Error{ErrorCode::InvalidArgument,
                     "normal estimation: leafSize must be in [1, 1024], got " + std::to_string(options.leafSize)};
    return std::nullopt;
}

Result<NormalReport> runNormalJob(const NormalJob& job, const NormalOptions& options, ProgressSink* progress)
{
    if (auto error = checkNormalOptions(options)) return *error;
    NormalReport report;
    report.points = job.queryCount;
    report.centre = job.centre;
    if (progress) progress->update(0.0);
    if (job.queryCount == 0) return report;
    const std::size_t n = job.positions.size() / 3;
    unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::clamp<std::size_t>(job.queryCount / 8192, 1, std::min(threads, 256u)));
    try {
        const NeighbourIndex index(job.positions, job.origin, options.leafSize, threads);
        if (progress && progress->isCancelRequested()) return Error{ErrorCode::Cancelled, "normal estimation: cancelled"};
        if (progress) progress->update(kBuildShare);
        Shared shared{job, options, index, {}, {}, std::nullopt};
        for (int d = 0; d < 3; ++d) {
            shared.localCentre[d] = job.centre[d] - job.origin[d];
            shared.localViewpoint[d] = options.viewpoint[d] - job.origin[d];
        }
        if (job.validBox) {
            std::array<double, 6> box = *job.validBox;
            for (int d = 0; d < 6; ++d) box[d] -= job.origin[d % 3];
            shared.localBox = box;
        }
        std::vector<std::thread> workers;
        workers.reserve(threads); // no allocation once threads run
        for (unsigned t = 1; t < threads; ++t) {
            try {
                workers.emplace_back([&shared, progress] { work(shared, false, progress); });
            } catch (const std::system_error&) {
                break; // fewer threads: the others share the work (chunks are handed out on demand)
            }
        }
        work(shared, true, progress);
        for (auto& worker : workers) worker.join();
        if (shared.cancelled) return Error{ErrorCode::Cancelled, "normal estimation: cancelled"};
        report.degenerate = shared.degenerate;
        report.truncated = shared.truncated;
    } catch (const std::bad_alloc&) {
        return Error{ErrorCode::OutOfBudget,
                     "normal estimation: out of memory for " + std::to_string(n) + " points"};
    }
    if (progress) progress->update(1.0);
    return report;
}

} // namespace detail

Result<NormalReport> estimateNormals(std::span<const double> positions, std::span<float> normals,
                                     const NormalOptions& options, ProgressSink* progress, std::span<float> quality)
{
    const std::size_t n = positions.size() / 3;
    if (positions.size() % 3 != 0 || normals.size() != positions.size() || (!quality.empty() && quality.size() != n))
        return Error{ErrorCode::InvalidArgument,
                     "estimateNormals: sizes disagree: " + std::to_string(positions.size()) + " coordinates, " +
                         std::to_string(normals.size()) + " normal components, " + std::to_string(quality.size()) +
                         " quality values"};
    if (n >= std::numeric_limits<std::uint32_t>::max())
        return Error{ErrorCode::InvalidArgument,
                     "estimateNormals: " + std::to_string(n) + " points is over 2^32 - 1; use estimateNormalsForFile"};
    if (auto error = detail::checkNormalOptions(options)) return *error;

    // The search frame is the bounding-box centre; the default orientation centre the centroid.
    std::array<double, 3> lo{}, hi{}, sum{};
    lo.fill(std::numeric_limits<double>::max());
    hi.fill(std::numeric_limits<double>::lowest());
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) {
            const double v = positions[3 * i + d];
            if (!std::isfinite(v))
                return Error{ErrorCode::InvalidArgument,
                             "estimateNormals: point " + std::to_string(i) + " has a non-finite coordinate"};
            lo[d] = std::min(lo[d], v);
            hi[d] = std::max(hi[d], v);
            sum[d] += v;
        }
    detail::NormalJob job;
    job.positions = positions;
    job.queryCount = n;
    job.normals = normals;
    job.quality = quality;
    for (int d = 0; d < 3; ++d) {
        job.origin[d] = n ? 0.5 * (lo[d] + hi[d]) : 0.0;
        job.centre[d] = n ? sum[d] / double(n) : 0.0;
    }
    if (options.centre) job.centre = *options.centre;
    return detail::runNormalJob(job, options, progress);
}

std::size_t normalEstimationBytesPerPoint()
{
    // Kept by the index: double local copy 24, float SoA 12, rank and source 8, nodes, leaves and leaf
    // boxes ~6; transient while building: sort keys 16, float copy 12, nanoflann's index 4. Rounded up.
    return 88;
}

} // namespace stylos::core::normals
