// Rendering a plate's panels and placing them with the legend and the caption.
#include "stylos/plate/PlateComposer.h"

#include "stylos/core/util/SubProgress.h"

namespace stylos::plate {

namespace cp = core::plate;

core::Result<PlateContent> composePlate(const cp::PlateSources& sources, const cp::PlateSpec& spec,
                                        const cp::PanelRenderOptions& options, core::ProgressSink* progress,
                                        const PlateTexts& texts, cp::LayoutFailure* failure)
{
    if (failure) *failure = {};
    if (auto s = spec.validate(sources.source); !s) return s.error();
    PlateContent plate;
    plate.spec = spec;
    plate.texts = texts;
    plate.legend = sources.legend;
    cp::PanelRenderOptions o = options;
    o.dpi = spec.dpi;
    std::vector<std::array<double, 2>> sizes;
    const double share = 1.0 / double(spec.panels.size());
    for (std::size_t i = 0; i < spec.panels.size(); ++i) {
        core::SubProgress part(progress, share * double(i), share * double(i + 1));
        auto panel = cp::renderPanel(sources, spec.panels[i], o, &part);
        if (!panel) return panel.error();
        sizes.push_back(panel->imageMm);
        plate.panels.push_back(std::move(panel).value());
    }
    const double width = spec.orientedPage().widthMm - 2 * spec.marginMm;
    const bool lettered = spec.panels.size() > 1;
    const cp::PanelLabelWidth labels = [&texts, lettered](std::size_t, const cp::PanelSpec& panel) {
        return panelLabelWidthMm(panel, lettered, texts);
    };
    auto layout = cp::layoutPlate(spec, sizes, legendRows(spec, plate.panels, plate.legend),
                                  captionHeightMm(QString::fromStdString(spec.caption), width), labels, failure);
    if (!layout) return layout.error();
    plate.layout = std::move(layout).value();
    for (std::size_t i = 0; i < plate.panels.size(); ++i) plate.layout.panels[i].rulerDegrees = plate.panels[i].arcDegrees;
    return plate;
}

} // namespace stylos::plate
