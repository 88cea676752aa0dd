#pragma once
/** @file
 * @brief What the développée view draws of an annotation layer: the class id each pixel shows (row-major,
 *        the développée's grid) and the same as colours (the legend's, opaque; transparent for id 0), kept
 *        side by side so that a stroke recolours only the pixels it changed. The ids are never blended or
 *        resampled (the view may smooth the colours on screen, never the ids). GUI thread only.
 */
#include <QImage>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace stylos::widgets {

class LabelOverlay {
public:
    /** @brief Colour per id (index); alpha 0 hides an id. */
    using Colours = std::array<QRgb, 256>;

    bool isEmpty() const { return m_ids.empty(); }
    int width() const { return m_image.width(); }
    int height() const { return m_image.height(); }

    /** @brief Every pixel at once (@p ids: width × height, row-major); an empty vector hides the overlay. */
    void setIds(int width, int height, std::vector<std::uint8_t> ids);
    /** @brief Pixels @p pixels (row-major indices) take @p ids (one each); pixels outside are ignored. */
    void setPixels(std::span<const std::uint32_t> pixels, std::span<const std::uint8_t> ids);
    /** @brief New colours: every pixel is recoloured. */
    void setColours(const Colours& colours);
    void clear();

    const std::vector<std::uint8_t>& ids() const { return m_ids; }
    std::uint8_t idAt(int column, int row) const;
    /** @brief Format_ARGB32_Premultiplied, the grid's size; null when empty. */
    const QImage& image() const { return m_image; }

private:
    void recolour();

    std::vector<std::uint8_t> m_ids;
    QImage m_image;
    Colours m_colours{};
};

} // namespace stylos::widgets
