#pragma once
/** @file
 * @brief The parallel rasterised lines along one azimuth that cover every pixel of a grid exactly
 *        once: the profiles on which the skydome finds horizons.
 *
 * Azimuth a is clockwise from up (HeightField.h), so the direction in pixel-index space (column, row)
 * is d = (sin a, −cos a). The major axis is the one along which |d| is larger (columns when
 * |sin a| ≥ |cos a|); with m = d_minor / d_major ∈ [−1, 1], pixel (major index A, minor index B) lies
 * on line B − floor(A · m + 0.5): each line advances one pixel along the major axis per step and 0 or
 * 1 along the minor one (a Bresenham line; the lines are translates of each other along the minor axis).
 * m is rounded to a multiple of 2^-32, so azimuths a and a + π give the same lines (walked in opposite
 * orders) even though their sines and cosines differ in the last bits.
 *
 * Distance along a line: pixels are placed by the projection of their centre on d,
 * along(c, r) = c · d_c + r · d_r (pixels); it grows strictly (by at least 1/√2 per step) toward d, and
 * the distance between two pixels of a line is the difference of their projections. The profile of a
 * pixel in direction a is the pixels of its line with a larger projection.
 *
 * Thread-safety: immutable after construction; share freely. Units: pixels (the shadings multiply
 * by the pixel size).
 */
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <utility>
#include <vector>

namespace stylos::core::shading {

/** @brief The lines of one direction over a width × height grid (see the file comment). */
class DirectionRaster {
public:
    /** @param azimuth radians, clockwise from up; width, height ≥ 0. */
    DirectionRaster(int width, int height, double azimuth);

    double azimuth() const { return m_azimuth; }
    /** Unit direction in pixel-index space: column and row components. */
    double columnStep() const { return m_dc; }
    double rowStep() const { return m_dr; }
    /** True when the lines advance one column per step (|d_c| ≥ |d_r|). */
    bool columnMajor() const { return m_columnMajor; }

    int lineCount() const { return m_lineCount; }
    /** The line (in [0, lineCount())) through pixel (column, row). */
    int lineOf(int column, int row) const
    {
        const int a = m_columnMajor ? column : row, b = m_columnMajor ? row : column;
        return b - offset(a) - m_firstLine;
    }
    /** Projection of the pixel centre on the direction, pixels (see the file comment). */
    double along(int column, int row) const { return column * m_dc + row * m_dr; }

    /**
     * @brief Calls f(column, row) for every pixel of @p line, in walk order: from the end of the line
     *        that d points to, backward, so each pixel comes after every pixel of its profile.
     */
    template <typename F>
    void forEachPixel(int line, F&& f) const
    {
        assert(line >= 0 && line < m_lineCount && "DirectionRaster::forEachPixel(): no such line");
        const int i = line + m_firstLine;
        const auto [first, last] = majorRange(i);
        if (first >= last) return;
        if (m_majorStep > 0) {
            for (int a = last - 1; a >= first; --a) visit(a, i, f);
        } else {
            for (int a = first; a < last; ++a) visit(a, i, f);
        }
    }

    /** Number of pixels of @p line. */
    int lineLength(int line) const
    {
        const auto [first, last] = lineSpan(line);
        return std::max(0, last - first);
    }

    /** Longest line, pixels (the size of a buffer that holds any line). */
    int longestLine() const { return majorSize(); }

    // The geometry, for sweeps that walk several lines at once (HorizonSweep.h).
    /** Grid extent along the major axis (columns when columnMajor()) and along the minor one. */
    int majorSize() const { return m_columnMajor ? m_width : m_height; }
    int minorSize() const { return m_minorSize; }
    /** +1 when d points toward increasing major index, else −1 (the walk runs the other way). */
    int majorStep() const { return m_majorStep; }
    /** Minor index of @p line at major index @p a, possibly outside the grid: intercept(line) + offset(a). */
    int intercept(int line) const { return line + m_firstLine; }
    int offset(int a) const { return m_offsets[std::size_t(a)]; }
    /** Major indices [first, last) where @p line is inside the grid. */
    std::pair<int, int> lineSpan(int line) const { return majorRange(line + m_firstLine); }

private:
    /** Major indices [first, last) where line i (in minor units, before m_firstLine) is in the grid. */
    std::pair<int, int> majorRange(int i) const;

    template <typename F>
    void visit(int a, int i, F& f) const
    {
        const int b = i + offset(a);
        if (m_columnMajor)
            f(a, b);
        else
            f(b, a);
    }

    double m_azimuth;
    int m_width, m_height;
    double m_dc, m_dr;
    bool m_columnMajor;
    int m_majorStep;            ///< sign of d's major component (+1 or −1)
    int m_minorSize;            ///< grid extent along the minor axis
    std::vector<int> m_offsets; ///< floor(A · m + 0.5) per major index A (monotone)
    int m_firstLine;            ///< minor intercept of line 0
    int m_lineCount;
};

} // namespace stylos::core::shading
