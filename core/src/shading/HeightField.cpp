#include "stylos/core/shading/HeightField.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace stylos::core::shading {

HeightField::HeightField(int width, int height, double pixelSize)
    : m_width(width), m_height(height), m_pixelSize(pixelSize),
      m_heights(std::size_t(width) * std::size_t(height), 0.0f),
      m_states(std::size_t(width) * std::size_t(height), PixelState::Empty)
{
}

Result<HeightField> HeightField::create(int width, int height, double pixelSize)
{
    const std::string size = std::to_string(width) + " x " + std::to_string(height) + " pixels";
    if (width < 0 || height < 0)
        return Error{ErrorCode::InvalidArgument, "height field: negative size " + size};
    if (width > kMaxSide || height > kMaxSide)
        return Error{ErrorCode::InvalidArgument, "height field: " + size + " is larger than "
                                                     + std::to_string(kMaxSide) + " pixels a side"};
    if (!(pixelSize > 0.0) || !std::isfinite(pixelSize))
        return Error{ErrorCode::InvalidArgument,
                     "height field: pixel size " + std::to_string(pixelSize) + " m is not a positive number"};
    return HeightField(width, height, pixelSize);
}

std::size_t HeightField::count(PixelState state) const
{
    return std::size_t(std::count(m_states.begin(), m_states.end(), state));
}

void HeightField::set(std::size_t i, float height, PixelState state)
{
    assert((state == PixelState::Empty || std::isfinite(height)) && "HeightField::set(): height not finite");
    m_heights[i] = height;
    m_states[i] = state;
}

} // namespace stylos::core::shading
