#include "FitSeed.h"

#include "stylos/core/util/SubProgress.h"

#include "stylos/core/normals/NormalEstimation.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace stylos::core::unroll::detail {

namespace {

constexpr int kRounds = 10;
constexpr double kKeep = 2.5 * 1.482602218505602; ///< lines kept within this many median residuals

} // namespace

Status estimateSampleNormals(FitPoints& sample, const Eigen::Vector3d& centre, unsigned threads, const FitStage& stage,
                             const std::string& source)
{
    const std::size_t n = sample.size();
    std::vector<double> positions(3 * n);
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            positions[3 * i + k] = static_cast<double>(sample.xyz[3 * i + k]) - centre[k];
    sample.normals.assign(3 * n, 0.0f);
    normals::NormalOptions options;
    options.threads = threads;
    options.orientation = normals::NormalOrientation::Unoriented;
    SubProgress sink(stage.sink, stage.from, stage.to);
    auto report = normals::estimateNormals(positions, sample.normals, options, &sink);
    if (!report) {
        sample.normals.clear();
        if (report.error().code == ErrorCode::Cancelled)
            return Error::at(ErrorCode::Cancelled, source, {}, "surface fit cancelled");
        return Error::at(report.error().code, source, {}, "normal estimation failed: " + report.error().message);
    }
    return {};
}

FitLine lineComplexAxis(const FitPoints& sample, const Eigen::Vector3d& centre, double scale)
{
    const std::size_t n = sample.size();
    using Vector6d = Eigen::Matrix<double, 6, 1>;
    using Matrix6d = Eigen::Matrix<double, 6, 6>;
    std::vector<Vector6d> lines(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d p((static_cast<double>(sample.xyz[3 * i]) - centre.x()) / scale,
                                (static_cast<double>(sample.xyz[3 * i + 1]) - centre.y()) / scale,
                                (static_cast<double>(sample.xyz[3 * i + 2]) - centre.z()) / scale);
        Eigen::Vector3d l(sample.normals[3 * i], sample.normals[3 * i + 1], sample.normals[3 * i + 2]);
        const double length = l.norm();
        l = length > 0.0 ? Eigen::Vector3d(l / length) : Eigen::Vector3d::Zero();
        lines[i] << p.cross(l), l; // (l̄, l)
    }
    std::vector<char> keep(n, 1);
    std::vector<double> residual(n), sorted;
    Eigen::Vector3d c = Eigen::Vector3d::UnitZ(), cBar = Eigen::Vector3d::Zero();
    for (int round = 0; round < kRounds; ++round) {
        Matrix6d m = Matrix6d::Zero();
        for (std::size_t i = 0; i < n; ++i)
            if (keep[i]) m.selfadjointView<Eigen::Lower>().rankUpdate(lines[i]);
        m = m.selfadjointView<Eigen::Lower>();
        const Eigen::Matrix3d a = m.topLeftCorner<3, 3>(), b = m.topRightCorner<3, 3>();
        Eigen::Matrix3d cc = m.bottomRightCorner<3, 3>();
        cc.diagonal().array() += 1e-9 * cc.trace() + 1e-300;
        const Eigen::LDLT<Eigen::Matrix3d> cSolver(cc);
        Eigen::Matrix3d schur = a - b * cSolver.solve(b.transpose());
        schur = 0.5 * (schur + schur.transpose()).eval();
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(schur);
        Eigen::Vector3d next = eigen.eigenvectors().col(0).normalized();
        if (next.dot(c) < 0.0) next = -next; // keep the sign from round to round
        const double moved = (next - c).norm();
        c = next;
        cBar = -cSolver.solve(b.transpose() * c);
        // Trim the lines far from the complex.
        sorted.clear();
        for (std::size_t i = 0; i < n; ++i) {
            residual[i] = std::abs(c.dot(lines[i].head<3>()) + cBar.dot(lines[i].tail<3>()));
            sorted.push_back(residual[i]);
        }
        if (sorted.empty()) break;
        const auto middle = sorted.begin() + std::ptrdiff_t(sorted.size() / 2);
        std::nth_element(sorted.begin(), middle, sorted.end());
        const double limit = std::max(kKeep * *middle, 1e-12);
        for (std::size_t i = 0; i < n; ++i)
            keep[i] = residual[i] <= limit ? 1 : 0;
        if (round > 0 && moved < 1e-12) break;
    }
    FitLine line;
    line.direction = c;
    line.point = scale * c.cross(cBar);
    return line;
}

} // namespace stylos::core::unroll::detail
