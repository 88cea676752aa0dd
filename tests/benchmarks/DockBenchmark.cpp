// stylos_dock_benchmark [--starts N] [--spacing M] [--fragments K]: docking against the guides of a
// generated drum, as the docking issue measures it. A drum (design seed 21, one all-round station, so the
// points' frame is known exactly from the truth) and K fragments of the same design (their own noise,
// registration and pose) are generated into a scratch folder; the drum's guides are fitted; each fragment
// is docked from N random starts (uniform in ±3° about the axis, a tilt of up to 5° in a random direction,
// ±15 mm radially) and compared with the truth in the drum frame. Success: θ within 0.01°, tilt within
// 0.02°, radial within 0.05 mm. Also: the RMS against the RMS at the true pose (what the noise leaves),
// the fragment's own axis (fitted without help) against the drum's, the flute snap on 5 k points and the
// registration on 100 k points, one core. Prints one line per measure and a JSON summary.
#include "DockGeometry.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/dock/DockRegistration.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/dock/FluteModel.h"
#include "stylos/core/dock/FluteSnap.h"
#include "stylos/core/synth/SyntheticScan.h"
#include "stylos/core/unroll/SurfaceFit.h"
#include "stylos/core/util/ScratchFolder.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace stylos;
namespace dock = core::dock;

namespace {

Eigen::Affine3d stationPose(const std::filesystem::path& truthPath)
{
    const auto j = nlohmann::json::parse(std::ifstream(truthPath));
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = j["stations"][0]["toOutput"][std::size_t(i)].get<double>();
    return Eigen::Affine3d(m);
}

struct Scan {
    core::cloud::PointCloud cloud;
    Eigen::Affine3d pose; // object → file
};

Scan generate(core::synth::SyntheticKind kind, std::uint64_t seed, double spacing, const std::filesystem::path& path)
{
    core::synth::SyntheticOptions o;
    o.spacing = spacing;
    o.seed = seed;
    o.designSeed = 21;
    o.scans = 1;
    o.scanHalfAngle = std::numbers::pi;
    auto report = core::synth::generateScan(kind, o, path);
    if (!report) throw std::runtime_error(report.error().message);
    auto cloud = core::cloud::loadPointCloud(path);
    if (!cloud) throw std::runtime_error(cloud.error().message);
    return {std::move(cloud).value(), stationPose(report->truthPath)};
}

double seconds(std::chrono::steady_clock::time_point since)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

double percentile(std::vector<double> v, double q)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::size_t(q * double(v.size() - 1))];
}

} // namespace

int main(int argc, char** argv)
{
    int starts = 100, fragments = 3;
    double spacing = 0.002;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--starts")) starts = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--spacing")) spacing = std::atof(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--fragments")) fragments = std::atoi(argv[i + 1]);
    }
    core::ScratchFolder scratch;
    if (auto s = scratch.create(std::filesystem::temp_directory_path() / "stylos-dock-benchmark", "scans"); !s) {
        std::fprintf(stderr, "%s\n", s.error().message.c_str());
        return 1;
    }
    const core::ScratchFolder* folder = &scratch;
    try {
        const Scan drum = generate(core::synth::SyntheticKind::Drum, 101, spacing, folder->path() / "drum.ply");
        auto t0 = std::chrono::steady_clock::now();
        auto guides = dock::fitDrumGuides(drum.cloud);
        if (!guides) throw std::runtime_error(guides.error().message);
        std::printf("drum: %zu points, %d flutes, leading radius %.3f mm, guides in %.2f s\n", drum.cloud.size(),
                    guides->flutes, guides->radius * 1e3, seconds(t0));
        const dock::DrumFrame frame(*guides);
        auto model = dock::FluteModel::fromGuides(*guides);
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::vector<double> thetaErr, tiltErr, radialErr, times, rmsRatio;
        int ok = 0, total = 0, failed = 0;
        nlohmann::json fragmentsJson = nlohmann::json::array();
        for (int f = 0; f < fragments; ++f) {
            const std::uint64_t seed = 3 + 2 * std::uint64_t(f);
            const Scan frag = generate(core::synth::SyntheticKind::Fragment, seed, spacing,
                                       folder->path() / ("fragment" + std::to_string(f) + ".ply"));
            const Eigen::Affine3d t = drum.pose * frag.pose.inverse();
            Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
            truth.linear() = t.linear();
            truth.translation() = t.translation();
            const Eigen::Vector3d centre = test::cloudCentre(frag.cloud);

            // The fragment's own axis, without help, against the drum's (both in the drum file frame).
            auto own = core::unroll::fitSurface(frag.cloud);
            double ownDeg = -1.0;
            if (own) {
                const Eigen::Vector3d d = truth.linear() * own->surface.axis().direction;
                ownDeg = std::acos(std::min(1.0, std::abs(d.dot(guides->axis.direction)))) * 180.0 / std::numbers::pi;
            }
            dock::DockOptions fixed;
            fixed.locked.fill(true);
            const auto atTruth = dock::dockFragment(frag.cloud, *guides, truth, fixed);
            int fragOk = 0;
            for (int s = 0; s < starts; ++s) {
                const double theta = 3.0 * unit(random), tilt = 5.0 * std::abs(unit(random)),
                             direction = std::numbers::pi * unit(random), radial = 0.015 * unit(random);
                const double k = std::numbers::pi / 180.0;
                const Eigen::Isometry3d start = test::perturbed(truth, frame, truth * centre, theta * k,
                                                                tilt * k * std::cos(direction), radial,
                                                                tilt * k * std::sin(direction));
                ++total;
                auto docked = dock::dockFragment(frag.cloud, *guides, start);
                if (!docked) {
                    ++failed;
                    std::printf("  fragment %d start %d (%.2f°, tilt %.2f°, %.1f mm): %s\n", f, s, theta, tilt,
                                radial * 1e3, docked.error().message.c_str());
                    continue;
                }
                const auto e = test::dockErrors(docked->pose, truth, frame, centre);
                thetaErr.push_back(e.thetaDeg);
                tiltErr.push_back(e.tiltDeg);
                radialErr.push_back(e.radialMm);
                times.push_back(docked->seconds);
                if (atTruth) rmsRatio.push_back(docked->rms / atTruth->rms);
                const bool good = e.thetaDeg < 0.01 && e.tiltDeg < 0.02 && e.radialMm < 0.05;
                ok += good, fragOk += good;
            }
            std::printf("fragment %d (seed %d): %zu points, own axis %.4f° from the drum's, %d/%d starts docked within "
                        "the targets, RMS at the truth %.3f mm\n", f, int(seed), frag.cloud.size(), ownDeg, fragOk, starts,
                        atTruth ? atTruth->rms * 1e3 : -1.0);
            fragmentsJson.push_back({{"seed", seed}, {"points", frag.cloud.size()}, {"own_axis_deg", ownDeg},
                                     {"docked", fragOk}, {"starts", starts}});

            if (f == 0 && model) { // speed on this fragment: snap on 5 k points, registration on 100 k, one core
                std::vector<Eigen::Vector3d> points;
                const std::size_t stride = std::max<std::size_t>(1, frag.cloud.size() / 5000);
                for (std::size_t i = 0; i < frag.cloud.size() && points.size() < 5000; i += stride)
                    points.push_back(frame.toFrame(truth * frag.cloud.world(i)));
                t0 = std::chrono::steady_clock::now();
                constexpr int kRepeats = 100;
                double sink = 0.0;
                for (int r = 0; r < kRepeats; ++r) sink += dock::snapToFlutes(points, *model, 0.001).rotation;
                std::printf("flute snap on %zu points: %.3f ms (checksum %.3g)\n", points.size(),
                            seconds(t0) / kRepeats * 1e3, sink);
            }
        }
        std::printf("all: %d/%d starts within θ 0.01°, tilt 0.02°, radial 0.05 mm (%d refused); worst θ %.4f°, tilt "
                    "%.4f°, radial %.4f mm; 99th percentile θ %.4f°, tilt %.4f°, radial %.4f mm; RMS / RMS at truth "
                    "%.3f–%.3f; docking %.3f s median, %.3f s worst\n",
                    ok, total, failed, percentile(thetaErr, 1.0), percentile(tiltErr, 1.0), percentile(radialErr, 1.0),
                    percentile(thetaErr, 0.99), percentile(tiltErr, 0.99), percentile(radialErr, 0.99),
                    percentile(rmsRatio, 0.0), percentile(rmsRatio, 1.0), percentile(times, 0.5), percentile(times, 1.0));
        nlohmann::json summary{{"starts", total}, {"docked_within_targets", ok}, {"refused", failed},
                               {"worst_theta_deg", percentile(thetaErr, 1.0)}, {"worst_tilt_deg", percentile(tiltErr, 1.0)},
                               {"worst_radial_mm", percentile(radialErr, 1.0)}, {"median_seconds", percentile(times, 0.5)},
                               {"fragments", fragmentsJson}};
        std::printf("%s\n", summary.dump().c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stylos_dock_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
