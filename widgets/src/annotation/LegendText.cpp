// Translated words of the legend: layers, hatches, the default class names.
#include "stylos/widgets/annotation/LegendText.h"

namespace stylos::widgets {

namespace {

using core::annotation::AnnotationLayer;
using core::annotation::Hatch;

struct DefaultName {
    AnnotationLayer layer;
    const char* name;
};

// The default vocabulary's names (core::annotation::Legend::defaults()), for lupdate.
constexpr DefaultName DefaultNames[] = {
    {AnnotationLayer::Material, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "preserved marble")},
    {AnnotationLayer::Material, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "fractured marble")},
    {AnnotationLayer::Material, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "plaster/restoration")},
    {AnnotationLayer::Material, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "unknown")},
    {AnnotationLayer::Toolmark, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "point")},
    {AnnotationLayer::Toolmark, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "flat chisel")},
    {AnnotationLayer::Toolmark, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "claw chisel")},
    {AnnotationLayer::Toolmark, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "drill")},
    {AnnotationLayer::Toolmark, QT_TRANSLATE_NOOP("stylos::widgets::LegendText", "rasp")},
};

const char* defaultName(AnnotationLayer layer, const std::string& name)
{
    for (const DefaultName& d : DefaultNames)
        if (d.layer == layer && name == d.name) return d.name;
    return nullptr;
}

} // namespace

QString LegendText::layerTitle(AnnotationLayer layer)
{
    return layer == AnnotationLayer::Material ? tr("Material / condition") : tr("Tool marks");
}

QString LegendText::hatchTitle(Hatch hatch)
{
    switch (hatch) {
    case Hatch::None: return tr("None");
    case Hatch::Diagonal: return tr("Diagonal");
    case Hatch::BackDiagonal: return tr("Back diagonal");
    case Hatch::Cross: return tr("Cross");
    case Hatch::DiagonalCross: return tr("Diagonal cross");
    case Hatch::Dots: return tr("Dots");
    case Hatch::Horizontal: return tr("Horizontal");
    case Hatch::Vertical: return tr("Vertical");
    case Hatch::Solid: return tr("Solid");
    }
    return {};
}

QString LegendText::className(AnnotationLayer layer, const core::annotation::LegendClass& cls)
{
    if (const char* d = defaultName(layer, cls.name)) return tr(d);
    return QString::fromStdString(cls.name);
}

bool LegendText::showsAs(AnnotationLayer layer, const std::string& name, const QString& text)
{
    core::annotation::LegendClass cls;
    cls.name = name;
    return className(layer, cls) == text;
}

} // namespace stylos::widgets
