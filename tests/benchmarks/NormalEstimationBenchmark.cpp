// Normal estimation speed: the in-memory kernel on a generated 1 M-point drum (1 and 2 threads), the
// neighbourhood solver against Eigen's, and the file driver (generated PLY; a real scan when
// STYLOS_SHARED_DATA points at the shared data folder). Rates are points per second of wall time.
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/normals/NeighbourhoodPca.h"
#include "stylos/core/normals/NormalEstimation.h"
#include "stylos/core/normals/NormalFileEstimation.h"

#include <Eigen/Eigenvalues>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::normals;

namespace {

/**
 * A column drum in a museum frame: fluted side (radius 0.9 m, 48 flutes 12 mm deep, height 0.5 m) and
 * its two faces, sampled at random with 0.3 mm noise. Deterministic.
 */
const std::vector<double>& drum(std::size_t points)
{
    static std::vector<double> cloud;
    if (cloud.size() == 3 * points) return cloud;
    cloud.clear();
    cloud.reserve(3 * points);
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, 0.0003);
    constexpr double pi = 3.14159265358979323846, radius = 0.9, height = 0.5;
    const double sideShare = 2 * pi * radius * height / (2 * pi * radius * height + 2 * pi * radius * radius);
    for (std::size_t i = 0; i < points; ++i) {
        const double a = 2 * pi * unit(random);
        double r, z;
        if (unit(random) < sideShare) {
            r = radius - 0.012 * std::pow(std::abs(std::sin(24 * a)), 0.5);
            z = height * unit(random);
        } else {
            r = radius * std::sqrt(unit(random));
            z = unit(random) < 0.5 ? 0.0 : height;
        }
        cloud.insert(cloud.end(), {4321.0 + r * std::cos(a) + noise(random), -1234.0 + r * std::sin(a) + noise(random),
                                   87.0 + z + noise(random)});
    }
    return cloud;
}

void BM_EstimateNormals(benchmark::State& state)
{
    const auto& positions = drum(static_cast<std::size_t>(state.range(0)));
    std::vector<float> normals(positions.size());
    NormalOptions options;
    options.threads = static_cast<unsigned>(state.range(1));
    for (auto _ : state) {
        auto report = estimateNormals(positions, normals, options);
        if (!report) state.SkipWithError(report.error().message.c_str());
        benchmark::DoNotOptimize(normals.data());
    }
    state.counters["points/s"] =
        benchmark::Counter(double(positions.size() / 3), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_EstimateNormals)->Args({1000000, 1})->Args({1000000, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

/** Sixteen-point neighbourhoods of a noisy plane, randomly turned: covariance + solver per call. */
std::vector<Covariance3> neighbourhoods()
{
    std::mt19937_64 random(2);
    std::normal_distribution<double> gauss;
    std::vector<Covariance3> result;
    for (int n = 0; n < 1024; ++n) {
        const Eigen::Matrix3d turn =
            Eigen::Quaterniond(gauss(random), gauss(random), gauss(random), gauss(random)).normalized().toRotationMatrix();
        std::vector<double> xyz;
        for (int j = 0; j < 16; ++j) {
            const Eigen::Vector3d p = turn * Eigen::Vector3d(gauss(random), gauss(random), 0.02 * gauss(random));
            xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
        }
        result.push_back(neighbourhoodCovariance(xyz, 16));
    }
    return result;
}

void BM_FitPlane(benchmark::State& state)
{
    const auto covariances = neighbourhoods();
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(fitPlane(covariances[i++ & 1023], 16));
}
BENCHMARK(BM_FitPlane);

void BM_EigenComputeDirect(benchmark::State& state)
{
    const auto covariances = neighbourhoods();
    std::size_t i = 0;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    for (auto _ : state) {
        const Covariance3& c = covariances[i++ & 1023];
        Eigen::Matrix3d m;
        m << c.xx, c.xy, c.xz, c.xy, c.yy, c.yz, c.xz, c.yz, c.zz;
        solver.computeDirect(m);
        benchmark::DoNotOptimize(solver.eigenvectors()(0, 0));
    }
}
BENCHMARK(BM_EigenComputeDirect);

/** Runs the file driver on @p input for every iteration; budget in MiB from range(0). */
void runFileDriver(benchmark::State& state, const std::filesystem::path& input)
{
    const auto output = std::filesystem::temp_directory_path() / "stylos-normal-benchmark-out.ply";
    NormalFileOptions options;
    options.memoryBudget = static_cast<std::size_t>(state.range(0)) << 20;
    std::uint64_t points = 0;
    for (auto _ : state) {
        auto report = estimateNormalsForFile(input, output, options);
        if (!report) {
            state.SkipWithError(report.error().message.c_str());
            break;
        }
        points = report->normals.points;
        state.counters["tiles"] = double(report->tiles);
    }
    std::filesystem::remove(output);
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_FileDriverGeneratedDrum(benchmark::State& state)
{
    const auto input = std::filesystem::temp_directory_path() / "stylos-normal-benchmark-drum.ply";
    if (!std::filesystem::exists(input)) {
        const auto& positions = drum(1000000);
        auto writer = io::PlyWriter::create(input, io::PointSchema{});
        io::PointBatch batch;
        batch.positions = positions;
        if (!writer || !writer->write(batch) || !writer->finish()) {
            state.SkipWithError("cannot write the generated drum");
            return;
        }
    }
    runFileDriver(state, input);
}
BENCHMARK(BM_FileDriverGeneratedDrum)->Arg(256)->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

void BM_FileDriverHappyBuddha(benchmark::State& state)
{
    const char* shared = std::getenv("STYLOS_SHARED_DATA");
    const auto input = std::filesystem::path(shared ? shared : "") / "scans" / "happy_buddha_1.1M.ply";
    if (!shared || !std::filesystem::exists(input)) {
        state.SkipWithError("set STYLOS_SHARED_DATA to the shared data folder to run this one");
        return;
    }
    runFileDriver(state, input);
}
BENCHMARK(BM_FileDriverHappyBuddha)->Arg(256)->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

} // namespace
