#include "stylos/core/synth/GroundTruth.h"

#include "stylos/core/util/AtomicTextFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace stylos::core::synth {

nlohmann::json transformJson(const Eigen::Affine3d& transform)
{
    nlohmann::json m = nlohmann::json::array();
    const Eigen::Matrix4d a = transform.matrix();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m.push_back(a(r, c));
    return m;
}

nlohmann::json buildGroundTruth(const GroundTruthInput& input)
{
    const SyntheticOptions& o = *input.options;
    const Eigen::Vector3d axisPoint = input.pose * Eigen::Vector3d::Zero();
    const Eigen::Vector3d axisDirection = (input.pose.linear() * Eigen::Vector3d::UnitZ()).normalized();

    nlohmann::json t;
    t["format"] = "stylos-synthetic-truth";
    t["version"] = 1;
    t["units"] = "metres, radians";
    t["kind"] = input.kind;
    t["seed"] = o.seed;
    if (o.designSeed) t["designSeed"] = *o.designSeed;
    t["spacing"] = o.spacing;
    t["noise"] = o.noise;
    t["noiseClamp"] = ScanSimulator::kNoiseClamp * o.noise;
    t["scans"] = o.scans;
    t["scanHalfAngle"] = o.scanHalfAngle;
    t["writeNormals"] = o.writeNormals;
    t["points"] = input.points;
    t["pose"] = transformJson(input.pose);
    t["axis"] = {{"point", {axisPoint.x(), axisPoint.y(), axisPoint.z()}},
                 {"direction", {axisDirection.x(), axisDirection.y(), axisDirection.z()}}};
    t["registrationBound"] = input.simulator->registrationBound();
    t["stations"] = input.simulator->stationsTruth();
    input.object->describe(t);
    if (t.contains("fragment")) // where the piece goes: output frame → the parent drum's frame
        t["fragment"]["poseInDrum"] = transformJson(input.pose.inverse());
    return t;
}

Status writeGroundTruth(const std::filesystem::path& path, const nlohmann::json& truth)
{
    return writeTextFileAtomically(path, truth.dump(2) + "\n");
}

} // namespace stylos::core::synth
