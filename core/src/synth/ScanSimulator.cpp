#include "stylos/core/synth/ScanSimulator.h"

#include "stylos/core/synth/GroundTruth.h"
#include "stylos/core/synth/Random.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stylos::core::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kJitter = 0.25;          ///< grid jitter, ± this fraction of the spacing
constexpr double kScannerDistance = 1.5;  ///< from the object's enclosing circle, metres
constexpr double kScannerHeight = 0.8;    ///< above the object's top, metres
constexpr int kAreaRows = 256;            ///< rows used to integrate a patch's area

/** Rows of a patch at @p spacing with grid offset @p offset in [0, 1). */
std::int64_t rowCount(const ParameterRange& rows, double spacing, double offset)
{
    return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(rows.length() / spacing - offset)) + 1);
}

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

} // namespace

struct ScanSimulator::Sampler {
    io::PlyWriter* writer = nullptr;
    ProgressSink* progress = nullptr;
    io::PointSchema schema;
    io::PointBatch batch;   ///< sized for kBatchPoints; the first `filled` points are real
    std::size_t filled = 0;
    Random random{0};
    std::uint64_t written = 0;
    std::uint64_t rowsDone = 0;
    std::uint64_t rowsTotal = 1;

    void shape(std::size_t points)
    {
        batch.positions.resize(3 * points);
        if (schema.hasNormals) batch.normals.resize(3 * points);
        batch.scalars[0].resize(points);
    }

    void append(const Eigen::Vector3d& p, const Eigen::Vector3d* n, int scan)
    {
        double* position = batch.positions.data() + 3 * filled;
        position[0] = p.x();
        position[1] = p.y();
        position[2] = p.z();
        if (n) {
            float* normal = batch.normals.data() + 3 * filled;
            normal[0] = static_cast<float>(n->x());
            normal[1] = static_cast<float>(n->y());
            normal[2] = static_cast<float>(n->z());
        }
        batch.scalars[0][filled] = static_cast<double>(scan);
        ++filled;
    }

    Status flush()
    {
        if (filled == 0) return {};
        shape(filled);
        if (Status s = writer->write(batch); !s) return s;
        written += filled;
        filled = 0;
        shape(kBatchPoints);
        if (progress && progress->isCancelRequested()) return Error{ErrorCode::Cancelled, "cancelled"};
        return {};
    }
};

ScanSimulator::ScanSimulator(const SyntheticObject& object, const SyntheticOptions& options,
                             const Eigen::Affine3d& pose, std::uint64_t seed)
    : m_object(object), m_options(options), m_pose(pose), m_seed(seed)
{
    Random random(Random::derive(seed, 0x5CA7));
    const double firstAzimuth = random.uniform(0.0, kTwoPi);
    const Eigen::Vector3d centre = object.scanCentre();
    const double distance = object.extent() + kScannerDistance;
    for (int k = 0; k < options.scans; ++k) {
        ScanStation s;
        s.viewAzimuth = wrapAngle(firstAzimuth + kTwoPi * k / options.scans);
        s.scanner = Eigen::Vector3d(centre.x() + distance * std::cos(s.viewAzimuth),
                                    centre.y() + distance * std::sin(s.viewAzimuth),
                                    object.height() + kScannerHeight);
        s.registrationAxis = random.unitVector();
        s.registrationAngle = random.uniform(0.0, kMaxRegistrationAngle);
        s.registrationShift = random.unitVector() * random.uniform(0.0, kMaxRegistrationShift);
        // Registration error: rotate about the scan centre, then shift.
        Eigen::Affine3d registration = Eigen::Affine3d::Identity();
        registration.translate(centre + s.registrationShift);
        registration.rotate(Eigen::AngleAxisd(s.registrationAngle, s.registrationAxis));
        registration.translate(-centre);
        s.toOutput = pose * registration;
        m_stations.push_back(s);
    }
}

double ScanSimulator::estimatePoints() const
{
    double area = 0.0;
    for (const SurfacePatch* patch : m_object.patches()) {
        const ParameterRange rows = patch->rows();
        const double step = rows.length() / kAreaRows;
        for (int i = 0; i < kAreaRows; ++i) area += step * patch->columns(rows.min + (i + 0.5) * step).length();
    }
    const double seen = std::min(1.0, m_options.scanHalfAngle / std::numbers::pi);
    return area * seen * m_options.scans / (m_options.spacing * m_options.spacing);
}

double ScanSimulator::registrationBound() const
{
    const double reach = std::hypot(m_object.extent(), std::max(m_object.scanCentre().z(),
                                                                m_object.height() - m_object.scanCentre().z()));
    // Chord of the largest rotation at the farthest point, plus the largest shift.
    return 2.0 * reach * std::sin(0.5 * kMaxRegistrationAngle) + kMaxRegistrationShift;
}

Result<std::uint64_t> ScanSimulator::run(io::PlyWriter& writer, ProgressSink* progress)
{
    Sampler sampler;
    sampler.writer = &writer;
    sampler.progress = progress;
    sampler.schema.hasNormals = m_options.writeNormals;
    sampler.schema.scalarNames = {"scan_id"};
    sampler.batch.reset(sampler.schema, kBatchPoints);
    sampler.shape(kBatchPoints);
    std::uint64_t rows = 0;
    for (const SurfacePatch* patch : m_object.patches())
        rows += static_cast<std::uint64_t>(rowCount(patch->rows(), m_options.spacing, 0.0));
    sampler.rowsTotal = std::max<std::uint64_t>(1, rows * m_stations.size());

    for (int k = 0; k < static_cast<int>(m_stations.size()); ++k) {
        sampler.random = Random(Random::derive(m_seed, 1000 + static_cast<std::uint64_t>(k)));
        for (const SurfacePatch* patch : m_object.patches())
            if (Status s = samplePatch(*patch, k, sampler); !s) return s.error();
    }
    if (Status s = sampler.flush(); !s) return s.error();
    if (progress) progress->update(1.0);
    return sampler.written;
}

Status ScanSimulator::samplePatch(const SurfacePatch& patch, int scan, Sampler& sampler) const
{
    const ScanStation& station = m_stations[static_cast<std::size_t>(scan)];
    const Eigen::Matrix3d rotation = station.toOutput.linear();
    const Eigen::Vector3d translation = station.toOutput.translation();
    const double spacing = m_options.spacing;
    const double sigma = m_options.noise;
    const double halfAngle = m_options.scanHalfAngle;
    const bool normals = m_options.writeNormals;
    Random& random = sampler.random;

    const ParameterRange rows = patch.rows();
    const double rowOffset = random.uniform();
    const double columnOffset = random.uniform();
    const std::int64_t rowTotal = rowCount(rows, spacing, rowOffset);
    for (std::int64_t i = 0; i < rowTotal; ++i) {
        const double b0 = std::min(rows.max, rows.min + (static_cast<double>(i) + rowOffset) * spacing);
        const ParameterRange columns = patch.columns(b0);
        std::int64_t columnTotal = 0;
        double step = spacing;
        if (columns.wraps) {
            columnTotal = std::max<std::int64_t>(1, std::llround(columns.length() / spacing));
            step = columns.length() / static_cast<double>(columnTotal);
        } else if (columns.length() >= 0.0) {
            columnTotal = rowCount(columns, spacing, columnOffset);
        }
        // On a row around the scan axis, visit only the nodes near the scan's window.
        std::int64_t first = 0;
        std::int64_t last = columnTotal - 1;
        const double scale = columns.wraps ? patch.azimuthScale(b0) : 0.0;
        if (scale > 0.0) {
            const double half = halfAngle / scale / step;
            if (2.0 * half + 4.0 < static_cast<double>(columnTotal)) {
                const double centre = (station.viewAzimuth / scale - columns.min) / step - columnOffset;
                first = static_cast<std::int64_t>(std::floor(centre - half)) - 1;
                last = static_cast<std::int64_t>(std::ceil(centre + half)) + 1;
            }
        }
        for (std::int64_t node = first; node <= last; ++node) {
            const std::int64_t j = columns.wraps ? ((node % columnTotal) + columnTotal) % columnTotal : node;
            const double a0 = columns.min + (static_cast<double>(j) + columnOffset) * step;
            if (!columns.wraps && a0 > columns.max) break;
            if (std::fabs(wrapAngle(patch.azimuth(a0, b0) - station.viewAzimuth)) > halfAngle)
                continue;
            const double jitterA = random.uniform(-kJitter, kJitter) * step;
            const double b = std::clamp(b0 + random.uniform(-kJitter, kJitter) * spacing, rows.min, rows.max);
            double a = patch.carry(a0, b0, b) + jitterA;
            if (!columns.wraps) {
                const ParameterRange moved = patch.columns(b);
                a = std::clamp(a, moved.min, moved.max);
            }
            Eigen::Vector3d p = patch.position(a, b);
            if (!patch.contains(a, b, p)) continue;
            const double n = std::clamp(random.normal(), -kNoiseClamp, kNoiseClamp) * sigma;
            p += n * (p - station.scanner).normalized();
            const Eigen::Vector3d q = rotation * p + translation;
            if (normals) {
                const Eigen::Vector3d m = rotation * patch.normal(a, b);
                sampler.append(q, &m, scan);
            } else {
                sampler.append(q, nullptr, scan);
            }
            if (sampler.filled >= kBatchPoints)
                if (Status s = sampler.flush(); !s) return s;
        }
        ++sampler.rowsDone;
        if (sampler.progress) {
            if (sampler.progress->isCancelRequested()) return Error{ErrorCode::Cancelled, "cancelled"};
            sampler.progress->update(0.99 * static_cast<double>(sampler.rowsDone) /
                                     static_cast<double>(sampler.rowsTotal));
        }
    }
    return {};
}

nlohmann::json ScanSimulator::stationsTruth() const
{
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t k = 0; k < m_stations.size(); ++k) {
        const ScanStation& s = m_stations[k];
        list.push_back({{"id", k},
                        {"viewAzimuth", s.viewAzimuth},
                        {"scanner", vectorJson(m_pose * s.scanner)},
                        {"registrationAxis", vectorJson(s.registrationAxis)},
                        {"registrationAngle", s.registrationAngle},
                        {"registrationShift", vectorJson(s.registrationShift)},
                        {"toOutput", transformJson(s.toOutput)}});
    }
    return list;
}

} // namespace stylos::core::synth
