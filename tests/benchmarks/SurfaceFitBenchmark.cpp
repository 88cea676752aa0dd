// stylos_fit_benchmark: the surface fit's targets (issue 4, docs/benchmarks.md): fitting 30 M points in
// under 2 s on 2 cores, with the axis within 0.02° and 0.1 mm and the radius within 0.1 mm of the truth.
//
//   stylos_fit_benchmark [--points N] [--threads T] [--grooves G] [--noise M] [--outliers SHARE]
//                        [--kind cylinder|cone|revolution] [--normals] [--repeat R] [--seed S]
//     Builds a procedural drum of N points in memory (synth::openSyntheticStream: radius 0.55 m, height
//     0.5 m, G flutes (default 48; 0 = a plain cylinder), both bed faces, Gaussian noise σ along the
//     normal), breaks it (a cavity 35 mm deep over ±0.26 rad × 0.1–0.28 m, as generateScan's drums),
//     replaces SHARE of the points (default 2 %) by clutter uniform in the drum's box, and places it in
//     a random pose at museum coordinates (about 1 km from the origin). Normals are dropped unless
//     --normals (real scans have none: the fit then estimates them on its seed sample). Then fits R
//     times (loading excluded) and prints each wall time, the best, and the accuracy: the angle between
//     the fitted and true axes, the largest distance between the lines over the drum's height, and the
//     radius against the least-squares radius of the intact lateral points about the true axis (0.55 m
//     for a plain drum; for a fluted one the mean radius of the flutes, as the points sample them).
// A table goes to stderr, one JSON document to stdout.
#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/SyntheticStream.h"
#include "stylos/core/unroll/SurfaceFit.h"

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace synth = stylos::core::synth;
namespace unroll = stylos::core::unroll;
namespace cloud = stylos::core::cloud;
using nlohmann::json;

namespace {

constexpr double kRadius = 0.55, kHeight = 0.5;
constexpr double kCavityCentre = 1.0, kCavityHalfAngle = 0.26, kCavityZMin = 0.1, kCavityZMax = 0.28;
constexpr double kCavityDepth = 0.035;

struct Settings {
    std::uint64_t points = 30'000'000;
    unsigned threads = 2;
    int grooves = 48;
    double noise = 0.00033;
    double outliers = 0.02;
    unroll::SurfaceKind kind = unroll::SurfaceKind::Cylinder;
    bool normals = false;
    int repeat = 3;
    std::uint64_t seed = 1;
};

/** Depth of the cavity at (θ, z), metres (0 outside): a smooth bowl. */
double cavityDepth(double theta, double z)
{
    const double a = std::remainder(theta - kCavityCentre, 2.0 * std::numbers::pi) / kCavityHalfAngle;
    const double b = (z - 0.5 * (kCavityZMin + kCavityZMax)) / (0.5 * (kCavityZMax - kCavityZMin));
    if (std::abs(a) >= 1.0 || std::abs(b) >= 1.0) return 0.0;
    const double wa = std::cos(0.5 * std::numbers::pi * a), wb = std::cos(0.5 * std::numbers::pi * b);
    return kCavityDepth * wa * wa * wb * wb;
}

struct Drum {
    cloud::PointCloud cloud;
    unroll::Axis axis;        ///< the true axis, world
    double lateralMean = 0.0; ///< mean distance from the true axis of the intact lateral points
    std::uint64_t lateral = 0;
};

Drum makeDrum(const Settings& s)
{
    synth::SyntheticStreamOptions o;
    o.points = s.points;
    o.seed = s.seed;
    o.radius = kRadius;
    o.height = kHeight;
    o.grooves = s.grooves;
    o.noise = s.noise;
    auto reader = synth::openSyntheticStream(o);
    if (!reader) {
        std::fprintf(stderr, "%s\n", reader.error().message.c_str());
        std::exit(1);
    }
    synth::Random random(synth::Random::derive(s.seed, 77));
    Eigen::Affine3d pose = Eigen::Affine3d::Identity();
    pose.linear() = random.rotation();
    pose.translation() = Eigen::Vector3d(1000.0, 2000.0, 50.0) + random.unitVector();
    Drum drum;
    drum.axis.point = pose.translation();
    drum.axis.direction = pose.linear().col(2);
    drum.cloud.origin = pose.translation().array().round();
    drum.cloud.source = "synthetic-drum";
    drum.cloud.positions.reserve(3 * s.points);
    if (s.normals) drum.cloud.normals.reserve(3 * s.points);
    const Eigen::Matrix3f rotation = pose.linear().cast<float>();
    const Eigen::Vector3d shift = pose.translation() - drum.cloud.origin;
    stylos::core::io::PointBatch batch;
    double lateralSum = 0.0;
    const double box = kRadius + 0.1;
    for (std::uint64_t index = 0;;) {
        auto got = (*reader)->read(batch, 1 << 16);
        if (!got || *got == 0) break;
        for (std::size_t i = 0; i < batch.size(); ++i, ++index) {
            Eigen::Vector3d p(batch.positions[3 * i], batch.positions[3 * i + 1], batch.positions[3 * i + 2]);
            Eigen::Vector3f n(batch.normals[3 * i], batch.normals[3 * i + 1], batch.normals[3 * i + 2]);
            // Clutter: a share of the points anywhere in the drum's box (a fixed pattern of indices).
            const bool clutter = double((index * 0x9E3779B97F4A7C15ull) >> 11) * 0x1p-53 < s.outliers;
            if (clutter) {
                p = Eigen::Vector3d(random.uniform(-box, box), random.uniform(-box, box),
                                    random.uniform(-0.1, kHeight + 0.1));
            } else if (std::abs(n.z()) < 0.5) { // the lateral surface (the beds' normals are ±z)
                const double theta = std::atan2(p.y(), p.x());
                const double depth = cavityDepth(theta, p.z());
                const double r = std::hypot(p.x(), p.y());
                p.x() *= (r - depth) / r;
                p.y() *= (r - depth) / r;
                if (depth == 0.0) {
                    lateralSum += r;
                    ++drum.lateral;
                }
            }
            const Eigen::Vector3d local = pose.linear() * p + shift;
            drum.cloud.positions.insert(drum.cloud.positions.end(),
                                        {float(local.x()), float(local.y()), float(local.z())});
            if (s.normals) {
                const Eigen::Vector3f m = rotation * n;
                drum.cloud.normals.insert(drum.cloud.normals.end(), {m.x(), m.y(), m.z()});
            }
        }
    }
    drum.lateralMean = lateralSum / double(std::max<std::uint64_t>(1, drum.lateral));
    return drum;
}

double distanceToLine(const Eigen::Vector3d& p, const unroll::Axis& axis)
{
    const Eigen::Vector3d w = p - axis.point;
    return (w - w.dot(axis.direction) * axis.direction).norm();
}

} // namespace

int main(int argc, char** argv)
{
    Settings s;
    std::string command = argv[0];
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        command.append(" ").append(a);
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", a.c_str());
                std::exit(2);
            }
            command.append(" ").append(argv[i + 1]);
            return argv[++i];
        };
        if (a == "--points")
            s.points = std::stoull(next());
        else if (a == "--threads")
            s.threads = unsigned(std::stoul(next()));
        else if (a == "--grooves")
            s.grooves = std::stoi(next());
        else if (a == "--noise")
            s.noise = std::stod(next());
        else if (a == "--outliers")
            s.outliers = std::stod(next());
        else if (a == "--normals")
            s.normals = true;
        else if (a == "--repeat")
            s.repeat = std::max(1, std::stoi(next()));
        else if (a == "--seed")
            s.seed = std::stoull(next());
        else if (a == "--kind") {
            const auto kind = unroll::surfaceKindFromName(next());
            if (!kind) {
                std::fprintf(stderr, "--kind: cylinder, cone or revolution\n");
                return 2;
            }
            s.kind = *kind;
        } else {
            std::fprintf(stderr,
                         "usage: %s [--points N] [--threads T] [--grooves G] [--noise M] [--outliers SHARE] "
                         "[--kind cylinder|cone|revolution] [--normals] [--repeat R] [--seed S]\n",
                         argv[0]);
            return 2;
        }
    }
    double load[3] = {0, 0, 0};
    getloadavg(load, 3);
    const auto built = std::chrono::steady_clock::now();
    const Drum drum = makeDrum(s);
    const double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - built).count();
    std::fprintf(stderr, "%s\n%llu points built in %.2f s (load average before: %.2f %.2f %.2f)\n", command.c_str(),
                 (unsigned long long)drum.cloud.size(), buildSeconds, load[0], load[1], load[2]);

    unroll::FitOptions options;
    options.kind = s.kind;
    options.threads = s.threads;
    std::vector<double> times;
    unroll::FitReport report;
    for (int r = 0; r < s.repeat; ++r) {
        const auto start = std::chrono::steady_clock::now();
        auto fitted = unroll::fitSurface(drum.cloud, options);
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (!fitted) {
            std::fprintf(stderr, "fit failed: %s\n", fitted.error().message.c_str());
            return 1;
        }
        report = *fitted;
        std::fprintf(stderr, "  fit %d: %.3f s\n", r + 1, times.back());
    }
    getloadavg(load, 3);
    const unroll::Surface& f = report.surface;
    const double angle = std::atan2(f.axis().direction.cross(drum.axis.direction).norm(),
                                    std::abs(f.axis().direction.dot(drum.axis.direction))) *
                         180.0 / std::numbers::pi;
    const double distance = std::max(distanceToLine(f.axis().point, drum.axis),
                                     distanceToLine(f.axis().point + kHeight * f.axis().direction, drum.axis));
    const double best = *std::min_element(times.begin(), times.end());
    std::fprintf(stderr,
                 "kind %s, %u threads: best %.3f s (%.1f M points/s)\n"
                 "axis: %.5f deg from the truth, lines %.4f mm apart over the drum\n"
                 "radius %.6f m: %+.4f mm from the lateral points' least-squares radius %.6f m (%+.4f mm from %.2f m)\n"
                 "RMS residual %.3f mm, inliers %.1f %%, %d iterations (load average after: %.2f %.2f %.2f)\n",
                 unroll::surfaceKindName(s.kind), s.threads, best, double(drum.cloud.size()) / best * 1e-6, angle,
                 distance * 1e3, f.referenceRadius(), (f.referenceRadius() - drum.lateralMean) * 1e3, drum.lateralMean,
                 (f.referenceRadius() - kRadius) * 1e3, kRadius, report.rmsResidual * 1e3,
                 report.inlierFraction * 100.0, report.iterations, load[0], load[1], load[2]);
    json out{{"command", command},
             {"points", drum.cloud.size()},
             {"threads", s.threads},
             {"kind", unroll::surfaceKindName(s.kind)},
             {"seconds", times},
             {"best_seconds", best},
             {"axis_angle_deg", angle},
             {"axis_distance_mm", distance * 1e3},
             {"radius", f.referenceRadius()},
             {"radius_error_mm", (f.referenceRadius() - drum.lateralMean) * 1e3},
             {"rms_residual_mm", report.rmsResidual * 1e3},
             {"inlier_fraction", report.inlierFraction},
             {"iterations", report.iterations}};
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
}
