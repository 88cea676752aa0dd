#pragma once
/** @file
 * @brief Draws a composed plate with a QPainter whose units are millimetres on the page (the writers scale it):
 *        each panel's image at its exact place and size, the hatches of its classes as vector strokes, its letter
 *        and view, its "1:N", its graphic scale bar (alternating black and white segments, ticks labelled in
 *        the bar's unit), the angle ruler 0–360° and the axis arrow of a développée, the axis triad of a 3D view;
 *        then the legend (colour swatch or hatch swatch per class present in the panels) and the caption.
 *
 * Lines are at least 0.3 pt (journals' minimum); fonts are DejaVu Sans / Serif, sized in points whatever the
 * device's resolution (fontFor()). Nothing here knows the output format: PDF, SVG and raster pages are the
 * same drawing. Thread-safety: a QPainter is used from one thread.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/plate/PlateLayout.h"
#include "stylos/core/plate/PlateSources.h"

#include <QImage>
#include <QString>

#include <array>
#include <functional>

#include <vector>

class QPainter;

namespace stylos::plate {

/** @brief The words a plate writes besides the caption: English by default (the command line); the workbench
 *         gives them in the user's language (widgets/plate/PlateTexts.h). */
struct PlateTexts {
    std::array<QString, 8> views;          ///< per PanelView: "développée", "front view", …, "orthographic view"
    std::array<QString, 4> shadings;       ///< per PanelShading: "skydome", "light", "height", "headlight"
    std::array<QString, 2> layerTitles;    ///< legend titles: "Material / condition", "Tool marks"
    QString axis = QStringLiteral("axis");
    QString decimalPoint = QStringLiteral("."); ///< in the bars' labels and "1:N" (a comma in French)
    /** A class's name on the plate; default: the legend's name as stored. */
    std::function<QString(core::annotation::AnnotationLayer, const core::annotation::LegendClass&)> className;
    static PlateTexts english();
};

/** @brief Everything a plate page shows, rendered and placed. */
struct PlateContent {
    core::plate::PlateSpec spec;
    core::plate::PlateLayout layout;
    std::vector<core::plate::RenderedPanel> panels;
    core::annotation::Legend legend;
    PlateTexts texts = PlateTexts::english();
};

/**
 * @brief The width on paper (mm) of @p panel's title line (its letter when @p lettered, view and shading, a 3D
 *        view's triad) and of its scale bar with its labels and "1:N", as paintPlate() draws them with @p texts:
 *        what the layout keeps free beside a small image (core::plate::layoutPlate's label widths).
 */
double panelLabelWidthMm(const core::plate::PanelSpec& panel, bool lettered, const PlateTexts& texts);

/** @brief Rows of the legend for @p panels (a title row per layer in use, one row per class present). */
int legendRows(const core::plate::PlateSpec& spec, const std::vector<core::plate::RenderedPanel>& panels,
               const core::annotation::Legend& legend);

/** @brief The caption's height in mm when wrapped to @p widthMm (0 for no caption). */
double captionHeightMm(const QString& caption, double widthMm);

/** @brief A panel image as a QImage: Grayscale8 / RGB888, or Grayscale16 / RGBX64 when @p sixteenBits. */
QImage panelQImage(const core::plate::PanelImage& image, bool sixteenBits);

/** @brief Paints @p plate; @p painter's user units must be millimetres from the page's top-left corner. */
void paintPlate(QPainter& painter, const PlateContent& plate);

} // namespace stylos::plate
