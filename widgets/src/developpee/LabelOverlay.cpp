// The annotation overlay of the développée: ids and their colours, updated pixel by pixel.
#include "stylos/widgets/developpee/LabelOverlay.h"

#include <cassert>

namespace stylos::widgets {

void LabelOverlay::setIds(int width, int height, std::vector<std::uint8_t> ids)
{
    if (ids.empty() || width <= 0 || height <= 0) {
        clear();
        return;
    }
    assert(ids.size() == std::size_t(width) * std::size_t(height) && "LabelOverlay::setIds(): one id per pixel");
    m_ids = std::move(ids);
    if (m_image.width() != width || m_image.height() != height)
        m_image = QImage(width, height, QImage::Format_ARGB32_Premultiplied);
    recolour();
}

void LabelOverlay::setPixels(std::span<const std::uint32_t> pixels, std::span<const std::uint8_t> ids)
{
    assert(pixels.size() == ids.size() && "LabelOverlay::setPixels(): one id per pixel");
    if (m_ids.empty()) return;
    const std::uint32_t w = std::uint32_t(m_image.width());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const std::uint32_t p = pixels[i];
        if (p >= m_ids.size()) continue;
        m_ids[p] = ids[i];
        reinterpret_cast<QRgb*>(m_image.scanLine(int(p / w)))[p % w] = m_colours[ids[i]];
    }
}

void LabelOverlay::setColours(const Colours& colours)
{
    m_colours = colours;
    m_colours[0] = 0; // unlabelled: nothing drawn
    recolour();
}

void LabelOverlay::clear()
{
    m_ids.clear();
    m_image = {};
}

std::uint8_t LabelOverlay::idAt(int column, int row) const
{
    if (m_ids.empty() || column < 0 || row < 0 || column >= m_image.width() || row >= m_image.height()) return 0;
    return m_ids[std::size_t(row) * std::size_t(m_image.width()) + std::size_t(column)];
}

void LabelOverlay::recolour()
{
    if (m_ids.empty()) return;
    const int w = m_image.width();
    for (int row = 0; row < m_image.height(); ++row) {
        auto* line = reinterpret_cast<QRgb*>(m_image.scanLine(row));
        const std::uint8_t* ids = m_ids.data() + std::size_t(row) * std::size_t(w);
        for (int column = 0; column < w; ++column) line[column] = m_colours[ids[column]];
    }
}

} // namespace stylos::widgets
