#pragma once
/** @file
 * @brief A height field: a grid of heights (metres) with a per-pixel state (empty, measured, filled),
 *        the raster the Unroller produces and every shading reads.
 *
 * Layout: row-major, `width` columns by `height` rows; pixel (column c, row r) is element
 * `r * width + c`. Row 0 is the TOP row of the image, column 0 its left column. The centre of pixel
 * (c, r) lies at ((c + 0.5) · pixelSize, (r + 0.5) · pixelSize) from the top-left corner, x to the
 * right, y downward. The shadings work in a right-handed frame x = right, y = up (toward row 0),
 * z = height (toward the viewer); azimuths there are measured clockwise from "up" (0 = toward row 0,
 * π/2 = toward the last column), as on a map with north up.
 *
 * A pixel is Empty (no data: its height is meaningless and shown transparent), Measured (from the
 * scan) or Filled (invented by hole filling from its neighbours). Heights of non-empty pixels are
 * finite.
 *
 * Units: heights and pixel size in metres. Thread-safety: a value type; concurrent reads are safe,
 * writes need exclusive access. Failure modes: create() refuses sizes that are zero-pixel-size,
 * negative, or larger than kMaxSide a side (InvalidArgument, with the size asked for).
 */
#include "stylos/core/util/Result.h"

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::shading {

/** @brief What a pixel holds. */
enum class PixelState : std::uint8_t {
    Empty = 0,    ///< no data (transparent in images, never occludes in the skydome)
    Measured = 1, ///< a height from the scan
    Filled = 2,   ///< a height invented by hole filling (HoleFilling.h)
};

/** @brief width × height heights in metres with a state per pixel (see the file comment). */
class HeightField {
public:
    /** Largest width or height accepted by create(), pixels (the développée issue's limit). */
    static constexpr int kMaxSide = 32768;

    /** @brief An empty 0 × 0 field with pixel size 1 m. */
    HeightField() = default;

    /**
     * @brief A field of @p width × @p height Empty pixels (heights 0).
     * @param pixelSize metres, finite and > 0.
     * @return the field, or InvalidArgument naming the size (negative, > kMaxSide a side, or a pixel
     *         size that is not a positive finite number). 0 × 0 is allowed.
     */
    static Result<HeightField> create(int width, int height, double pixelSize);

    int width() const { return m_width; }
    int height() const { return m_height; }
    /** Side of a pixel, metres. */
    double pixelSize() const { return m_pixelSize; }
    std::size_t pixelCount() const { return m_heights.size(); }

    /** Element index of pixel (column, row); asserts that it is inside. */
    std::size_t index(int column, int row) const
    {
        assert(contains(column, row) && "HeightField::index(): pixel outside the field");
        return std::size_t(row) * std::size_t(m_width) + std::size_t(column);
    }
    bool contains(int column, int row) const
    {
        return column >= 0 && row >= 0 && column < m_width && row < m_height;
    }

    float heightAt(int column, int row) const { return m_heights[index(column, row)]; }
    PixelState stateAt(int column, int row) const { return m_states[index(column, row)]; }
    /** True when the pixel is Measured or Filled. */
    bool hasHeight(int column, int row) const { return stateAt(column, row) != PixelState::Empty; }

    /** Sets a measured height (metres, finite). */
    void setMeasured(int column, int row, float height) { set(index(column, row), height, PixelState::Measured); }
    /** Sets a filled height (metres, finite). */
    void setFilled(int column, int row, float height) { set(index(column, row), height, PixelState::Filled); }
    /** Makes the pixel Empty (its height becomes 0). */
    void clear(int column, int row) { set(index(column, row), 0.0f, PixelState::Empty); }

    /** All heights, row-major (see the file comment). Heights of Empty pixels are meaningless. */
    std::span<float> heights() { return m_heights; }
    std::span<const float> heights() const { return m_heights; }
    /** All states, row-major. Writers must keep non-empty heights finite. */
    std::span<PixelState> states() { return m_states; }
    std::span<const PixelState> states() const { return m_states; }

    /** Number of pixels in @p state. */
    std::size_t count(PixelState state) const;

private:
    HeightField(int width, int height, double pixelSize);
    void set(std::size_t i, float height, PixelState state);

    int m_width = 0;
    int m_height = 0;
    double m_pixelSize = 1.0;
    std::vector<float> m_heights;
    std::vector<PixelState> m_states;
};

} // namespace stylos::core::shading
