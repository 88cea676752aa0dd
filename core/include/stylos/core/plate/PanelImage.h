#pragma once
/** @file
 * @brief The picture of one plate panel at print resolution: grey or RGB samples, 16 bits, white where there
 *        is nothing (paper), and, when an annotation layer is drawn, the class id under each pixel (so hatches
 *        are traced from the data, never from colours). Plus the resampling that brings a développée computed
 *        at its own pixel size to the plate's pixels: bilinear for the shading, nearest for class ids (ids are
 *        never blended), with paper where the source has no value.
 *
 * Units: pixelSizeM is metres on the object per image pixel. Thread-safety: value types, pure functions.
 */
#include "stylos/core/annotation/Legend.h"

#include <array>
#include <cstdint>
#include <vector>

namespace stylos::core::plate {

struct PanelImage {
    int width = 0;
    int height = 0;
    int channels = 1;                     ///< 1 (grey) or 3 (RGB)
    std::vector<std::uint16_t> samples;   ///< width × height × channels, row 0 at the top; 65535 = white
    std::vector<std::uint8_t> classes;    ///< width × height class ids (0 = none), or empty without a layer
    double pixelSizeM = 0;
    std::uint16_t sample(int x, int y, int c = 0) const
    {
        return samples[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c)];
    }
};

/**
 * @brief The classes that @p image shows as a region, judged on blocks of @p block × @p block pixels (each block the
 *        class that fills more than half of it, else none): those with a block whose four neighbours hold the same
 *        class. A class seen only in scattered pixels or slivers — a painted patch on the far side of a 3D view
 *        glimpsed at the silhouette or through a pinhole of the near surface — is not shown, and the legend leaves it
 *        out. The plate takes blocks of about 1/72 inch on paper, so its preview (72 dpi) and its file (any dpi) list
 *        the same classes. Indexed by class id; none without classes.
 */
std::array<bool, 256> shownClasses(const PanelImage& image, int block = 1);

/** @brief A grey value in [0, 1] with a coverage flag per pixel, and optional class ids, at some pixel size. */
struct GreyField {
    int width = 0;
    int height = 0;
    std::vector<float> values;            ///< [0, 1]
    std::vector<std::uint8_t> coverage;   ///< 1 where there is a value
    std::vector<std::uint8_t> classes;    ///< optional, width × height
};

/**
 * @brief Resamples @p source to @p width × @p height, where the source spans @p sourceColumns columns (may be
 *        fractional: a développée's period) and all its rows; columns wrap when @p periodic. Grey where covered
 *        (bilinear over the covered neighbours), paper elsewhere; classes nearest.
 */
PanelImage resampleField(const GreyField& source, double sourceColumns, bool periodic, int width, int height);

/**
 * @brief Tints @p image by its classes with @p legend's colours of @p layer: grey g becomes g · (1 − a + a · c)
 *        per channel (a = 0.65), so the relief stays readable under the colour; the image becomes RGB.
 *        Pixels of class 0 or of an id the legend lacks stay grey.
 */
void tintByClass(PanelImage& image, const annotation::Legend& legend, annotation::AnnotationLayer layer);

} // namespace stylos::core::plate
