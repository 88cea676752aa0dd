#include "AxisArgument.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace stylos::cli {

bool parseNumberList(const std::string& text, const std::string& option, std::size_t count, std::vector<double>& values,
                     std::string& problem)
{
    values.clear();
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v)) {
            problem = option + ": \"" + item + "\" is not a number";
            return false;
        }
        values.push_back(v);
    }
    if (values.size() != count) {
        problem = option + " needs " + std::to_string(count) + " numbers, got " + std::to_string(values.size());
        return false;
    }
    return true;
}

bool parseAxis(const std::string& text, core::unroll::Axis& axis, std::string& problem)
{
    std::vector<double> values;
    if (!parseNumberList(text, "--axis", 6, values, problem)) {
        if (problem.find("numbers, got") != std::string::npos)
            problem = "--axis needs six numbers PX,PY,PZ,DX,DY,DZ, got " + std::to_string(values.size());
        return false;
    }
    axis.point = {values[0], values[1], values[2]};
    axis.direction = {values[3], values[4], values[5]};
    if (axis.direction.norm() < 1e-12) {
        problem = "--axis: the direction is a zero vector";
        return false;
    }
    axis.direction.normalize();
    return true;
}

bool parsePose(const std::string& text, Eigen::Isometry3d& pose, std::string& problem)
{
    std::vector<double> values;
    if (!parseNumberList(text, "--pose", 12, values, problem)) return false;
    Eigen::Matrix3d r;
    for (int i = 0; i < 9; ++i) r(i / 3, i % 3) = values[std::size_t(i)];
    if (!(r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-6) || !(r.determinant() > 0.0)) {
        problem = "--pose: the first nine numbers are not a rotation (orthonormal rows, determinant +1)";
        return false;
    }
    pose = Eigen::Isometry3d::Identity();
    pose.linear() = r;
    pose.translation() = Eigen::Vector3d(values[9], values[10], values[11]);
    return true;
}

} // namespace stylos::cli
