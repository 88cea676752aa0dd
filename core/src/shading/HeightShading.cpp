#include "stylos/core/shading/HeightShading.h"

#include "NearestRank.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace stylos::core::shading {

Result<HeightRange> robustHeightRange(const HeightField& field, double lowPercentile, double highPercentile)
{
    if (!detail::validPercentiles(lowPercentile, highPercentile))
        return Error{ErrorCode::InvalidArgument, "height shading: percentiles " + std::to_string(lowPercentile)
                                                     + " and " + std::to_string(highPercentile)
                                                     + " are not 0 <= low <= high <= 1"};
    std::vector<float> values;
    values.reserve(field.pixelCount());
    const auto heights = field.heights();
    const auto states = field.states();
    for (std::size_t i = 0; i < heights.size(); ++i)
        if (states[i] != PixelState::Empty) values.push_back(heights[i]);
    if (values.empty()) return HeightRange{};
    const float low = detail::nearestRank(values, lowPercentile);
    const float high = detail::nearestRank(values, highPercentile);
    return HeightRange{low, high};
}

Result<ShadedImage> shadeHeight(const HeightField& field, const HeightShadingOptions& options)
{
    HeightRange range;
    if (options.range) {
        range = *options.range;
        if (!std::isfinite(range.low) || !std::isfinite(range.high) || range.low > range.high)
            return Error{ErrorCode::InvalidArgument, "height shading: range " + std::to_string(range.low) + " .. "
                                                         + std::to_string(range.high) + " m is not low <= high"};
    } else {
        auto robust = robustHeightRange(field, options.lowPercentile, options.highPercentile);
        if (!robust) return robust.error();
        range = *robust;
    }

    ShadedImage image{field.width(), field.height(), field.pixelSize(), {}, {}};
    image.values.assign(field.pixelCount(), 0.0f);
    image.coverage.assign(field.pixelCount(), 0);
    const auto heights = field.heights();
    const auto states = field.states();
    const double span = range.high - range.low;
    for (std::size_t i = 0; i < heights.size(); ++i) {
        if (states[i] == PixelState::Empty) continue;
        image.coverage[i] = 1;
        image.values[i] = span > 0.0 ? float(std::clamp((heights[i] - range.low) / span, 0.0, 1.0)) : 0.5f;
    }
    return image;
}

} // namespace stylos::core::shading
