#include "stylos/core/shading/LightShading.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace stylos::core::shading {
namespace {

/**
 * Derivative of the height along one axis at a pixel whose neighbours before and after (in the axis's
 * increasing direction) are given, with the presence of each; per metre.
 */
double difference(double before, bool hasBefore, double here, double after, bool hasAfter, double pixelSize)
{
    if (hasBefore && hasAfter) return (after - before) / (2.0 * pixelSize);
    if (hasAfter) return (after - here) / pixelSize;
    if (hasBefore) return (here - before) / pixelSize;
    return 0.0;
}

} // namespace

Result<ShadedImage> shadeLight(const HeightField& field, const LightShadingOptions& options)
{
    if (!(options.elevation >= 0.0 && options.elevation <= 0.5 * std::numbers::pi))
        return Error{ErrorCode::InvalidArgument,
                     "light shading: elevation " + std::to_string(options.elevation) + " rad is not in [0, pi/2]"};
    if (!std::isfinite(options.azimuth))
        return Error{ErrorCode::InvalidArgument, "light shading: the azimuth is not a finite number"};
    if (!(options.verticalExaggeration > 0.0) || !std::isfinite(options.verticalExaggeration))
        return Error{ErrorCode::InvalidArgument, "light shading: vertical exaggeration "
                                                     + std::to_string(options.verticalExaggeration)
                                                     + " is not a positive number"};

    const double lx = std::sin(options.azimuth) * std::cos(options.elevation);
    const double ly = std::cos(options.azimuth) * std::cos(options.elevation);
    const double lz = std::sin(options.elevation);
    const double k = options.verticalExaggeration;
    const double s = field.pixelSize();

    ShadedImage image{field.width(), field.height(), s, {}, {}};
    image.values.assign(field.pixelCount(), 0.0f);
    image.coverage.assign(field.pixelCount(), 0);
    auto at = [&](int c, int r, bool& present) {
        present = field.contains(c, r) && field.hasHeight(c, r);
        return present ? double(field.heightAt(c, r)) : 0.0;
    };
    for (int r = 0; r < field.height(); ++r)
        for (int c = 0; c < field.width(); ++c) {
            if (!field.hasHeight(c, r)) continue;
            const double h = field.heightAt(c, r);
            bool left, right, up, down;
            const double hl = at(c - 1, r, left), hr = at(c + 1, r, right);
            const double hu = at(c, r - 1, up), hd = at(c, r + 1, down);
            const double dx = difference(hl, left, h, hr, right, s);
            const double dy = difference(hd, down, h, hu, up, s); // y grows toward row 0
            const double nx = -k * dx, ny = -k * dy;
            const double dot = (nx * lx + ny * ly + lz) / std::sqrt(nx * nx + ny * ny + 1.0);
            const std::size_t i = field.index(c, r);
            image.coverage[i] = 1;
            image.values[i] = float(std::clamp(dot, 0.0, 1.0));
        }
    return image;
}

} // namespace stylos::core::shading
