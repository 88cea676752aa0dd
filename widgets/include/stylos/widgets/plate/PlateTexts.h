#pragma once
/** @file
 * @brief The words of a plate (view and shading names, legend titles, "axis", the class names as the Legend dock
 *        shows them: the default vocabulary translated, the user's own names kept) in the workbench's language,
 *        for plates drawn from the workbench. Call on the GUI thread; the result holds plain strings and may go
 *        to a worker thread.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/plate/PlatePainter.h"

#include <QCoreApplication>

namespace stylos::widgets {

class PlateTexts {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::PlateTexts)

public:
    static plate::PlateTexts translated(const core::annotation::Legend& legend);
};

} // namespace stylos::widgets
