#include "stylos/core/shading/ContrastStretch.h"

#include "NearestRank.h"

#include <algorithm>
#include <string>
#include <vector>

namespace stylos::core::shading {

Result<ValueRange> stretchContrast(ShadedImage& image, double lowPercentile, double highPercentile)
{
    if (!detail::validPercentiles(lowPercentile, highPercentile))
        return Error{ErrorCode::InvalidArgument, "contrast stretch: percentiles " + std::to_string(lowPercentile) +
                                                     " and " + std::to_string(highPercentile) +
                                                     " are not 0 <= low <= high <= 1"};
    std::vector<float> covered;
    covered.reserve(image.values.size());
    for (std::size_t i = 0; i < image.values.size(); ++i)
        if (image.coverage[i]) covered.push_back(image.values[i]);
    if (covered.empty()) return ValueRange{};
    const ValueRange range{detail::nearestRank(covered, lowPercentile), detail::nearestRank(covered, highPercentile)};
    const float span = range.high - range.low;
    for (std::size_t i = 0; i < image.values.size(); ++i) {
        if (!image.coverage[i]) continue;
        image.values[i] = span > 0.0f ? std::clamp((image.values[i] - range.low) / span, 0.0f, 1.0f) : 0.5f;
    }
    return range;
}

} // namespace stylos::core::shading
