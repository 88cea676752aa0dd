// Surface area per annotation class: the density of leaves on the surface in a sphere around each query cell.
#include "stylos/core/annotation/LabelArea.h"

#include "stylos/core/ao/AoCells.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace stylos::core::annotation {
namespace {

/** A cell of the closed-surface level: where it lies in its query cell (in its own edges) and its leaves. */
struct Sample {
    std::uint32_t leaves = 0;
    std::array<std::uint8_t, 3> local{};
    std::array<float, 3> normal{}; ///< the cell's (pulled) unit normal
};

struct QueryCell {
    std::array<std::uint32_t, 3> coords{};
    std::uint64_t firstSample = 0, firstLeaf = 0;
    std::array<float, 3> normal{};
};

std::uint64_t firstAt(const octree::PackedOctree& octree, int from, int to, std::uint64_t index)
{
    if (index >= octree.cellCount(from)) return octree.cellCount(to);
    for (int l = from; l < to; ++l) index = octree.firstChild(l, index);
    return index;
}

std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z)
{
    return std::uint64_t(x) | (std::uint64_t(y) << 21) | (std::uint64_t(z) << 42);
}

/** The samples within the sphere, weighted by their leaves: how many, their mean (query frame) and covariance. */
struct SphereFit {
    double weight = 0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

/** The leaves of the surface's slab within the kernel's reach: how many, and Σ w |nᵢ·n| K(ρ). */
struct KernelSum {
    double weight = 0;
    double kernel = 0;
};

class AreaEstimator {
public:
    AreaEstimator(const octree::PackedOctree& octree, int queryLevel, int sampleLevel, double radiusInQueryEdges)
        : m_octree(octree), m_shift(sampleLevel - queryLevel)
    {
        m_sampleEdge = octree.root().size / double(std::uint64_t{1} << sampleLevel);
        m_queryEdge = m_sampleEdge * double(1 << m_shift);
        m_radius = radiusInQueryEdges * m_queryEdge;
        m_slab = 1.5 * m_sampleEdge;
    }

    bool read(int queryLevel, int sampleLevel, ProgressSink* progress)
    {
        const int depth = m_octree.depth();
        m_queries.reserve(m_octree.cellCount(queryLevel) + 1);
        m_octree.forEachCell(queryLevel, [&](const octree::CellView& cell) {
            m_index.emplace(key(cell.coords[0], cell.coords[1], cell.coords[2]), std::uint32_t(m_queries.size()));
            m_queries.push_back({cell.coords, firstAt(m_octree, queryLevel, sampleLevel, cell.index),
                                 firstAt(m_octree, queryLevel, depth, cell.index), cell.normal});
            return true;
        });
        m_queries.push_back({{}, m_octree.cellCount(sampleLevel), m_octree.cellCount(depth), {}});
        m_samples.resize(m_octree.cellCount(sampleLevel));
        std::size_t owner = 0;
        bool cancelled = false;
        m_octree.forEachCell(sampleLevel, [&](const octree::CellView& cell) {
            if (cell.index % (64 * 1024) == 0 && progress && progress->isCancelRequested()) {
                cancelled = true;
                return false;
            }
            while (cell.index >= m_queries[owner + 1].firstSample) ++owner;
            Sample& s = m_samples[cell.index];
            for (int a = 0; a < 3; ++a) s.local[std::size_t(a)] = std::uint8_t(cell.coords[std::size_t(a)] - (m_queries[owner].coords[std::size_t(a)] << m_shift));
            s.normal = cell.normal;
            s.leaves = std::uint32_t(firstAt(m_octree, sampleLevel, depth, cell.index + 1) - firstAt(m_octree, sampleLevel, depth, cell.index));
            return true;
        });
        return !cancelled;
    }

    std::size_t queries() const { return m_queries.size() - 1; }

    /** The area of each leaf under query cell @p j, m². */
    double leafArea(std::size_t j) const
    {
        const QueryCell& q = m_queries[j];
        std::array<std::uint32_t, 27> near{};
        std::size_t nearCount = 0;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const auto found = m_index.find(key(std::int64_t(q.coords[0]) + dx, std::int64_t(q.coords[1]) + dy, std::int64_t(q.coords[2]) + dz));
                    if (found != m_index.end()) near[nearCount++] = found->second;
                }
        // The start: the centroid of the cell's own leaves.
        Eigen::Vector3d start = Eigen::Vector3d::Zero();
        double own = 0;
        for (std::uint64_t s = q.firstSample; s < m_queries[j + 1].firstSample; ++s) {
            start += m_samples[s].leaves * position(j, j, m_samples[s]);
            own += m_samples[s].leaves;
        }
        if (own == 0) return 0;
        start /= own;
        // Fit the plane through the leaves in the sphere, move the centre onto it, and again.
        Eigen::Vector3d centre = start, normal = Eigen::Vector3d::Zero();
        for (int round = 0; round < 3; ++round) {
            const SphereFit fit = fitSphere(j, near, nearCount, centre);
            if (fit.weight < kMinLeaves) return fallback(j);
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
            eigen.computeDirect(fit.covariance);
            // A line or a point is no surface to measure a density on.
            if (!(eigen.eigenvalues()(1) > 1e-3 * m_radius * m_radius)) return fallback(j);
            normal = eigen.eigenvectors().col(0);
            centre = start - normal * normal.dot(start - fit.mean);
        }
        const KernelSum sum = kernelSum(j, near, nearCount, centre, normal);
        if (sum.weight < kMinLeaves || !(sum.kernel > 0)) return fallback(j);
        // The leaves per m² around the centre: Σ w K(ρ) / ∫K dA with K(ρ) = (1 − ρ²/R²)², ∫K dA = π R² / 3.
        // A smooth kernel, not a hard disc: the leaves sit on a lattice, and a hard edge counts them unevenly.
        return std::numbers::pi * m_radius * m_radius / 3.0 / sum.kernel;
    }

    std::uint64_t firstLeaf(std::size_t j) const { return m_queries[j].firstLeaf; }

private:
    static constexpr double kMinLeaves = 8;

    /** A sample's centre, metres, relative to the corner of query cell @p frame. */
    Eigen::Vector3d position(std::size_t frame, std::size_t owner, const Sample& s) const
    {
        Eigen::Vector3d p;
        for (int a = 0; a < 3; ++a) {
            const std::size_t k = std::size_t(a);
            const double cells = double(std::int64_t(m_queries[owner].coords[k]) - std::int64_t(m_queries[frame].coords[k])) * double(1 << m_shift);
            p[a] = (cells + s.local[k] + 0.5) * m_sampleEdge;
        }
        return p;
    }

    /** Calls fn(d, sample) for every sample of the cells @p near, d its position relative to @p centre. */
    template <typename Fn>
    void forNear(std::size_t j, const std::array<std::uint32_t, 27>& near, std::size_t nearCount, const Eigen::Vector3d& centre,
                 Fn&& fn) const
    {
        for (std::size_t n = 0; n < nearCount; ++n) {
            const std::size_t k = near[n];
            for (std::uint64_t s = m_queries[k].firstSample; s < m_queries[k + 1].firstSample; ++s)
                fn(Eigen::Vector3d(position(j, k, m_samples[s]) - centre), m_samples[s]);
        }
    }

    SphereFit fitSphere(std::size_t j, const std::array<std::uint32_t, 27>& near, std::size_t nearCount,
                        const Eigen::Vector3d& centre) const
    {
        SphereFit fit;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
        const double r2 = m_radius * m_radius;
        forNear(j, near, nearCount, centre, [&](const Eigen::Vector3d& d, const Sample& s) {
            if (d.squaredNorm() > r2) return;
            fit.weight += s.leaves;
            sum += s.leaves * d;
            scatter += s.leaves * d * d.transpose();
        });
        if (fit.weight > 0) {
            const Eigen::Vector3d mean = sum / fit.weight; // relative to the centre, where the sums were taken
            fit.covariance = scatter / fit.weight - mean * mean.transpose();
            fit.mean = mean + centre;
        }
        return fit;
    }

    KernelSum kernelSum(std::size_t j, const std::array<std::uint32_t, 27>& near, std::size_t nearCount,
                        const Eigen::Vector3d& centre, const Eigen::Vector3d& normal) const
    {
        KernelSum sum;
        const double r2 = m_radius * m_radius;
        forNear(j, near, nearCount, centre, [&](const Eigen::Vector3d& d, const Sample& s) {
            // The leaves of the surface's slab, weighted by their distance along the plane.
            const double h = normal.dot(d), rho2 = d.squaredNorm() - h * h;
            if (rho2 >= r2 || std::abs(h) > m_slab) return;
            // The surface beside the sample leans on the plane by |nᵢ · n|: its leaves per m² of the plane are
            // its leaves per m² of surface divided by that, which the weight gives back.
            const double lean = std::abs(s.normal[0] * normal[0] + s.normal[1] * normal[1] + s.normal[2] * normal[2]);
            const double k = 1.0 - rho2 / r2;
            sum.weight += s.leaves;
            sum.kernel += s.leaves * k * k * lean;
        });
        return sum;
    }

    /** Too few leaves around, or no plane: the crossing density of the query cell (e² / |n|₁) shared by its leaves. */
    double fallback(std::size_t j) const
    {
        const auto& n = m_queries[j].normal;
        const double l1 = std::abs(double(n[0])) + std::abs(double(n[1])) + std::abs(double(n[2]));
        const double norm = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
        const double cellArea = m_queryEdge * m_queryEdge / (norm > 0 ? std::clamp(l1 / norm, 1.0, std::sqrt(3.0)) : 1.0);
        const std::uint64_t leaves = m_queries[j + 1].firstLeaf - m_queries[j].firstLeaf;
        return leaves > 0 ? cellArea / double(leaves) : 0.0;
    }

    const octree::PackedOctree& m_octree;
    int m_shift = 0;
    double m_sampleEdge = 0, m_queryEdge = 0, m_radius = 0, m_slab = 0;
    std::vector<QueryCell> m_queries;
    std::vector<Sample> m_samples;
    std::unordered_map<std::uint64_t, std::uint32_t> m_index;
};

} // namespace

Result<std::vector<double>> leafAreas(const octree::PackedOctree& octree, const LeafAreaOptions& options,
                                      ProgressSink* progress)
{
    const int depth = octree.depth();
    std::vector<double> areas(octree.cellCount(depth), 0.0);
    if (areas.empty()) return areas;
    const int sampleLevel = ao::closedSurfaceLevel(octree);
    const int queryLevel = std::max(0, sampleLevel - std::clamp(options.levelsUp, 0, 7));
    AreaEstimator estimator(octree, queryLevel, sampleLevel, options.radius);
    auto cancelled = [&] {
        return Error::at(ErrorCode::Cancelled, octree.path().string(), "", "areas cancelled while reading the cells");
    };
    if (!estimator.read(queryLevel, sampleLevel, progress)) return cancelled();
    const std::size_t count = estimator.queries();
    for (std::size_t j = 0; j < count; ++j) {
        if (j % 4096 == 0 && progress) {
            if (progress->isCancelRequested()) return cancelled();
            progress->update(double(j) / double(count));
        }
        const double area = estimator.leafArea(j);
        std::fill(areas.begin() + std::ptrdiff_t(estimator.firstLeaf(j)), areas.begin() + std::ptrdiff_t(estimator.firstLeaf(j + 1)), area);
    }
    if (progress) progress->update(1.0);
    return areas;
}

std::vector<ClassMeasure> measureClasses(std::span<const std::uint8_t> labels, std::span<const double> areas)
{
    assert(labels.size() == areas.size() && "measureClasses(): one area per label");
    std::vector<ClassMeasure> measures(256);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        ++measures[labels[i]].cells;
        measures[labels[i]].areaM2 += areas[i];
    }
    return measures;
}

} // namespace stylos::core::annotation
