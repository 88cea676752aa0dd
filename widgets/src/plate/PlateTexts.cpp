// The words of a plate in the workbench's language.
#include "stylos/widgets/plate/PlateTexts.h"

#include "stylos/widgets/annotation/LegendText.h"


#include <map>
#include <memory>

namespace stylos::widgets {

plate::PlateTexts PlateTexts::translated(const core::annotation::Legend& legend)
{
    using core::annotation::AnnotationLayer;
    plate::PlateTexts t;
    t.views = {tr("développée"), tr("front view"), tr("back view"), tr("left view"), tr("right view"), tr("top view"),
               tr("bottom view"), tr("orthographic view")};
    t.shadings = {tr("skydome"), tr("light"), tr("height"), tr("headlight")};
    t.layerTitles = {LegendText::layerTitle(AnnotationLayer::Material), LegendText::layerTitle(AnnotationLayer::Toolmark)};
    t.axis = tr("axis");
    // The plate's language's, not the system's: "0,5 m" and "1:2,5" on a French plate whatever the machine.
    t.decimalPoint = tr(".", "the decimal point of the numbers on a plate");
    auto names = std::make_shared<std::map<std::pair<int, int>, QString>>();
    for (const AnnotationLayer layer : core::annotation::AllAnnotationLayers)
        for (const core::annotation::LegendClass& c : legend.classes(layer))
            (*names)[{int(layer), int(c.id)}] = LegendText::className(layer, c);
    t.className = [names](AnnotationLayer layer, const core::annotation::LegendClass& c) {
        const auto it = names->find({int(layer), int(c.id)});
        return it != names->end() ? it->second : QString::fromStdString(c.name);
    };
    return t;
}

} // namespace stylos::widgets
