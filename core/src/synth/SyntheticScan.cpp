#include "stylos/core/synth/SyntheticScan.h"

#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/FragmentShape.h"
#include "stylos/core/synth/GroundTruth.h"
#include "stylos/core/synth/OmphalosShape.h"
#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/ScanSimulator.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <system_error>

namespace stylos::core::synth {
namespace {

constexpr double kMaxPoints = 2.0e9; ///< refuse to generate more (the estimate, not the exact count)
constexpr double kMinPoints = 100.0; ///< nor fewer: a spacing that large samples no surface
const Eigen::Vector3d kMuseumOrigin(1000.0, 2000.0, 50.0);
constexpr double kPoseSpread = 3.0;  ///< the pose's translation is kMuseumOrigin ± this, metres

const char* kindName(SyntheticKind kind)
{
    switch (kind) {
    case SyntheticKind::Drum: return "drum";
    case SyntheticKind::Omphalos: return "omphalos";
    case SyntheticKind::Fragment: return "fragment";
    }
    return "drum";
}

/** @p value in at most 6 significant digits, exponent when needed: 1e-07, 3.5e+12, 0.002. */
std::string shortNumber(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

Error invalid(const std::filesystem::path& output, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, output.string(), {}, problem);
}

/** Empty when the options are usable, otherwise what is wrong. */
std::string optionsProblem(const SyntheticOptions& o)
{
    if (!std::isfinite(o.spacing) || !(o.spacing > 0.0)) return "spacing must be a positive number of metres";
    if (!std::isfinite(o.noise) || o.noise < 0.0) return "noise must be a non-negative number of metres";
    if (o.scans < 1 || o.scans > 255) return "scans must be between 1 and 255";
    if (!(o.scanHalfAngle > 0.0 && o.scanHalfAngle <= std::numbers::pi))
        return "scan half angle must be in (0, pi] radians";
    return {};
}

std::unique_ptr<SyntheticObject> makeObject(SyntheticKind kind, const SyntheticOptions& options, Random& random)
{
    std::optional<Random> design;
    if (options.designSeed) design.emplace(*options.designSeed);
    Random& drumRandom = design ? *design : random;
    switch (kind) {
    case SyntheticKind::Omphalos: return std::make_unique<OmphalosShape>(OmphalosParameters::random(random));
    case SyntheticKind::Fragment: {
        const DrumParameters drum = DrumParameters::fromOptions(options, drumRandom);
        return std::make_unique<FragmentShape>(drum, FragmentParameters::random(drum, random));
    }
    case SyntheticKind::Drum: break;
    }
    return std::make_unique<DrumShape>(DrumParameters::fromOptions(options, drumRandom));
}

Eigen::Affine3d randomPose(std::uint64_t seed)
{
    Random random(Random::derive(seed, 0x9053));
    Eigen::Affine3d pose = Eigen::Affine3d::Identity();
    pose.linear() = random.rotation();
    Eigen::Vector3d shift;
    for (int i = 0; i < 3; ++i) shift[i] = random.uniform(-kPoseSpread, kPoseSpread);
    pose.translation() = kMuseumOrigin + shift;
    return pose;
}

} // namespace

std::unique_ptr<SyntheticObject> makeSyntheticObject(SyntheticKind kind, const SyntheticOptions& options)
{
    Random random(options.seed);
    return makeObject(kind, options, random);
}

Eigen::Affine3d syntheticPose(const SyntheticOptions& options) { return randomPose(options.seed); }

std::optional<SyntheticKind> syntheticKindFromName(std::string_view name)
{
    if (name == "drum") return SyntheticKind::Drum;
    if (name == "omphalos") return SyntheticKind::Omphalos;
    if (name == "fragment") return SyntheticKind::Fragment;
    return std::nullopt;
}

std::filesystem::path truthPathFor(const std::filesystem::path& output)
{
    std::filesystem::path truth = output;
    truth.replace_extension(".truth.json");
    return truth;
}

Result<SyntheticReport> generateScan(SyntheticKind kind, const SyntheticOptions& options,
                                     const std::filesystem::path& output, ProgressSink* progress)
{
    if (std::string problem = optionsProblem(options); !problem.empty()) return invalid(output, problem);
    Random random(options.seed);
    if (kind != SyntheticKind::Omphalos) {
        Random probe(options.designSeed.value_or(options.seed));
        if (std::string problem = DrumParameters::fromOptions(options, probe).problem(); !problem.empty())
            return invalid(output, problem);
    }
    const std::unique_ptr<SyntheticObject> object = makeObject(kind, options, random);
    const Eigen::Affine3d pose = randomPose(options.seed);
    ScanSimulator simulator(*object, options, pose, options.seed);
    const double estimate = simulator.estimatePoints();
    if (!(estimate <= kMaxPoints))
        return invalid(output, "spacing " + shortNumber(options.spacing) + " m would give about " +
                                   shortNumber(estimate) + " points (limit 2e9)");
    if (!(estimate >= kMinPoints))
        return invalid(output, "spacing " + shortNumber(options.spacing) + " m would give about " +
                                   shortNumber(std::round(estimate)) + " points: too coarse to be a scan (at least " +
                                   shortNumber(kMinPoints) + ")");

    io::PointSchema schema;
    schema.hasNormals = options.writeNormals;
    schema.scalarNames = {"scan_id"};
    io::PlyWriterOptions plyOptions;
    plyOptions.scalarTypes = {io::PlyScalarType::UInt8};
    plyOptions.comments = {std::string("Stylos synthetic ") + kindName(kind) + " seed " +
                               std::to_string(options.seed),
                           "truth in " + truthPathFor(output).filename().string()};
    Result<io::PlyWriter> writer = io::PlyWriter::create(output, schema, plyOptions);
    if (!writer) return writer.error();
    Result<std::uint64_t> points = simulator.run(*writer, progress);
    if (!points) {
        if (points.error().code == ErrorCode::Cancelled)
            return Error::at(ErrorCode::Cancelled, output.string(), {}, "cancelled");
        return points.error();
    }
    if (Status s = writer->finish(); !s) return s.error();

    GroundTruthInput input;
    input.kind = kindName(kind);
    input.options = &options;
    input.object = object.get();
    input.simulator = &simulator;
    input.pose = pose;
    input.points = *points;
    SyntheticReport report;
    report.points = *points;
    report.truthPath = truthPathFor(output);
    if (Status s = writeGroundTruth(report.truthPath, buildGroundTruth(input)); !s) {
        std::error_code ignored;
        std::filesystem::remove(output, ignored); // both files or neither
        return s.error();
    }
    return report;
}

} // namespace stylos::core::synth
