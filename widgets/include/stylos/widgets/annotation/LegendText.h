#pragma once
/** @file
 * @brief The legend's words as shown: layer titles, hatch names, and class names — a class whose stored name is
 *        one of the default vocabulary's English names (Legend::defaults(), unchanged by the user) is shown in
 *        the interface's language; any other name is shown as stored. The stored names never change by
 *        translation (a project opened in Greek and saved keeps "preserved marble"). GUI thread only.
 */
#include "stylos/core/annotation/Legend.h"

#include <QCoreApplication>
#include <QString>

namespace stylos::widgets {

class LegendText {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::LegendText)

public:
    /** @brief "Material / condition" or "Tool marks". */
    static QString layerTitle(core::annotation::AnnotationLayer layer);
    static QString hatchTitle(core::annotation::Hatch hatch);
    /** @brief The name shown for @p cls: translated when it is a default name of @p layer. */
    static QString className(core::annotation::AnnotationLayer layer, const core::annotation::LegendClass& cls);
    /** @brief Whether @p text is what className() shows for a stored @p name (a rename to the same text is none). */
    static bool showsAs(core::annotation::AnnotationLayer layer, const std::string& name, const QString& text);
};

} // namespace stylos::widgets
