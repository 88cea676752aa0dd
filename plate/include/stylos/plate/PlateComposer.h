#pragma once
/** @file
 * @brief Makes a plate from its sources and its statement, for the command line and the workbench alike:
 *        renders every panel at the plate's dpi (core/plate/PlateSources.h), sizes the legend and the caption,
 *        and places everything (core/plate/PlateLayout.h). Failure modes: the spec's, the panels' and the
 *        layout's errors (a panel too large for the page says how large and which scale would fit), Cancelled.
 *        Thread-safety: may run in a worker thread (fonts are only measured, not drawn).
 */
#include "stylos/core/plate/PlateSources.h"
#include "stylos/plate/PlatePainter.h"

namespace stylos::plate {

/** @p texts: the plate's words (translated by the workbench), kept in the plate and measured for the layout.
 *  @p failure, when given, receives why the plate does not fit its page (core::plate::layoutPlate). */
core::Result<PlateContent> composePlate(const core::plate::PlateSources& sources, const core::plate::PlateSpec& spec,
                                        const core::plate::PanelRenderOptions& options,
                                        core::ProgressSink* progress = nullptr,
                                        const PlateTexts& texts = PlateTexts::english(),
                                        core::plate::LayoutFailure* failure = nullptr);

} // namespace stylos::plate
