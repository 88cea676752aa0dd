#pragma once
// Internal to the skydome: the field as the horizon bands read it, and the transposes between layouts.
#include "HorizonBand.h"
#include "stylos/core/shading/DirectionRaster.h"
#include "stylos/core/shading/HeightField.h"

#include <vector>

namespace stylos::core::shading::detail {

/**
 * The field in both layouts a band reads contiguously: itself for row-major rasters (a step is a row)
 * and, built only when asked, a transposed copy with Empty pixels as NaN for column-major ones (a step
 * is a column: a row of the copy). Read-only once built: shared by the workers. Memory: 4 bytes per
 * pixel for the copy.
 */
class HorizonSources {
public:
    /** @param transposed build the transposed copy (needed by column-major rasters). */
    HorizonSources(const HeightField& field, bool transposed, unsigned threads);

    /** Where the bands of @p raster read (asserts that the copy exists for a column-major raster). */
    BandSource source(const DirectionRaster& raster) const;

private:
    const HeightField& m_field;
    std::vector<float> m_transposed; // width rows of height elements
};

/** sum[r · width + c] += transposed[c · height + r] for every pixel, in parallel. */
void addTransposed(float* sum, const float* transposed, int width, int height, unsigned threads);

} // namespace stylos::core::shading::detail
