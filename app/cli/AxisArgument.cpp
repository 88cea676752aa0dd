#include "AxisArgument.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace stylos::cli {

bool parseAxis(const std::string& text, core::unroll::Axis& axis, std::string& problem)
{
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v)) {
            problem = "--axis: \"" + item + "\" is not a number";
            return false;
        }
        values.push_back(v);
    }
    if (values.size() != 6) {
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

} // namespace stylos::cli
