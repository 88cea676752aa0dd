#include "AxisArgument.h"

#include <Eigen/SVD>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace stylos::cli {

std::vector<std::string> splitCommaList(const std::string& text)
{
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        items.push_back(std::move(item));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return items;
}

bool parseNumberList(const std::string& text, const std::string& option, std::size_t count, std::vector<double>& values,
                     std::string& problem)
{
    values.clear();
    // Decimal numbers only ("1", "-0.5", "+2e-3", spaces around them as in "0, 0, 0"): not hexadecimal ("0x10", which
    // strtod takes), not an empty item (a trailing comma, which getline dropped).
    for (const std::string& item : splitCommaList(text)) {
        const char* first = item.c_str() + (item.size() > 1 && item[0] == '+' && item[1] != '-' ? 1 : 0);
        const char* last = item.c_str() + item.size();
        double v = 0.0;
        const auto [end, error] = std::from_chars(first, last, v, std::chars_format::general);
        if (item.empty() || error != std::errc() || end != last || !std::isfinite(v)) {
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
    // A rotation as other tools print it (MeshLab, CloudCompare: 6 decimals, off orthonormal by ~1e-6) is taken and
    // made exact (the nearest rotation); one further off is refused with how far.
    constexpr double kTolerance = 1e-4;
    const double off = (r * r.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(off <= kTolerance) || !(r.determinant() > 0.0)) {
        char text[200];
        if (!(r.determinant() > 0.0))
            std::snprintf(text, sizeof text, "--pose: the first nine numbers are not a rotation (determinant %.3g, not +1)",
                          r.determinant());
        else
            std::snprintf(text, sizeof text, "--pose: the first nine numbers are not a rotation: their rows are off "
                          "orthonormal by %.2g (at most %.0e is taken)", off, kTolerance);
        problem = text;
        return false;
    }
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
    pose = Eigen::Isometry3d::Identity();
    pose.linear() = svd.matrixU() * svd.matrixV().transpose();
    pose.translation() = Eigen::Vector3d(values[9], values[10], values[11]);
    return true;
}

} // namespace stylos::cli
