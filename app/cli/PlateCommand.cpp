// stylos-cli plate IN -o OUT.pdf|svg|tif|png --view developpee|front|back|left|right|top|bottom --scale N
//                   [--dpi D] [--page A4|A3|letter|WxH] [--landscape] [--shading skydome|light|height|headlight]
//                   [--layer material|toolmark] [--hatches] [--caption TEXT] [--fragment NAME] [--json]
// stylos-cli plate PROJECT.stylos --layout PLATE.json -o OUT…
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"

#include "stylos/core/annotation/Legend.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/plate/PlateSources.h"
#include "stylos/core/util/ScratchFolder.h"
#include "stylos/core/util/Stopwatch.h"
#include "stylos/plate/PlateComposer.h"
#include "stylos/plate/PlateWriter.h"

#include <QGuiApplication>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>

namespace stylos::cli {

namespace {

namespace cp = core::plate;

/** Qt's messages on stderr, less the note that XDG_RUNTIME_DIR is unset (normal on a server). */
void quietQtMessages(QtMsgType, const QMessageLogContext&, const QString& message)
{
    if (message.startsWith(QLatin1String("QStandardPaths:"))) return;
    std::cerr << message.toStdString() << "\n";
}

int fail(const core::Error& error)
{
    std::cerr << "stylos-cli: " << error.message << "\n";
    return ExitFailure;
}

/** Skydome when every octree shown has its "ambient" layer, else headlight (3D panels without --shading). */
core::Result<cp::PanelShading> defaultShading3d(const cp::PlateSources& sources, const std::string& fragment)
{
    for (const cp::PlateFragment& f : sources.fragments) {
        if ((!fragment.empty() && f.name != fragment) || (fragment.empty() && !f.visible)) continue;
        if (f.missing) return cp::PanelShading::Skydome; // the composer names the missing octree
        if (!f.isOctree) return cp::PanelShading::Headlight;
        auto octree = core::octree::PackedOctree::open(f.path);
        if (!octree) return octree.error(); // what is wrong with it, not a note on its shading
        if (!octree->attribute("ambient")) return cp::PanelShading::Headlight;
    }
    return cp::PanelShading::Skydome;
}

/** Whether some fragment that @p panel draws holds the annotation layer it draws (a point file holds none). */
bool panelLayerHeld(const cp::PlateSources& sources, const cp::PanelSpec& panel)
{
    for (const cp::PlateFragment& f : sources.fragments) {
        if ((!panel.fragment.empty() && f.name != panel.fragment) || !f.isOctree || f.missing) continue;
        auto octree = core::octree::PackedOctree::open(f.path);
        if (octree && octree->attribute(core::annotation::layerName(*panel.layer))) return true;
    }
    return false;
}

/**
 * A statement's problem in the words of the options that made it: PlateSpec::validate names the layout file's keys
 * ("the command line: margin_mm: must be 0..70 mm"), which a plate stated by options has not written.
 */
std::string inOptionWords(std::string message)
{
    static const std::pair<const char*, const char*> kKeys[] = {
        {"page: ", "--page: "},       {"margin_mm: ", "--margin: "}, {"dpi: ", "--dpi: "},
        {"bits: ", "--bits: "},       {"panels[0].scale: ", "--scale: "}, {"panels[0].shading: ", "--shading: "},
        {"panels[0].layer: ", "--layer: "}, {"panels[0].fragment: ", "--fragment: "}, {"panels[0].view: ", "--view: "}};
    const std::string prefix = "the command line: ";
    if (message.rfind(prefix, 0) != 0) return message;
    message.erase(0, prefix.size());
    for (const auto& [key, option] : kKeys)
        if (message.rfind(key, 0) == 0) return option + message.substr(std::string(key).size());
    return prefix + message; // a key no option states: the message as it was
}

/** The one-panel plate of the command line; false with @p problem on a usage error. */
bool parseOnePanel(CommandLine& cl, cp::PlateSpec& spec, std::string& problem)
{
    cp::PanelSpec panel;
    const auto view = cp::panelViewFromName(cl.value("view").value_or("developpee"));
    if (!view) return problem = "unknown view \"" + *cl.value("view") + "\" (developpee, front, back, left, right, top or bottom)", false;
    panel.view = *view;
    if (!cl.value("scale")) return problem = "plate needs --scale N (the panel at 1:N)", false;
    if (!cl.number("scale", panel.scale)) return problem = cl.error(), false;
    if (!(panel.scale >= 1 && panel.scale <= 1e6)) return problem = "--scale must be a number in 1..1000000 (the panel at 1:N)", false;
    panel.shadingStated = cl.value("shading").has_value() || panel.view == cp::PanelView::Developpee;
    if (cl.value("shading")) {
        const auto s = cp::panelShadingFromName(*cl.value("shading"));
        if (!s) return problem = "unknown shading \"" + *cl.value("shading") + "\" (skydome, light, height or headlight)", false;
        panel.shading = *s;
    }
    if (const auto layer = cl.value("layer")) {
        const auto l = core::annotation::layerFromName(*layer);
        if (!l) return problem = "unknown layer \"" + *layer + "\" (material or toolmark)", false;
        panel.layer = *l;
    }
    panel.hatches = cl.flag("hatches");
    panel.fragment = cl.value("fragment").value_or("");
    spec.panels = {panel};
    spec.caption = cl.value("caption").value_or("");
    return true;
}

bool parsePage(CommandLine& cl, cp::PlateSpec& spec, std::string& problem)
{
    if (const auto page = cl.value("page")) {
        const auto size = cp::pageFromName(*page);
        if (!size && page->find_first_of("xX") != std::string::npos)
            return problem = "--page WxH: each side must be a number of millimetres in 10..2000, not \"" + *page + "\"", false;
        if (!size) return problem = "unknown page \"" + *page + "\" (A4, A3, letter, 170x105, 205x135 or WxH in mm)", false;
        spec.pageName = *page;
        spec.page = *size;
        if (page->find_first_of("xX") != std::string::npos && !cl.value("margin")) spec.marginMm = 0;
    }
    // --landscape: the longer side across. A WxH page already so stays as stated (its spec turns it otherwise).
    if (cl.flag("landscape")) {
        const bool custom = spec.pageName.find_first_of("xX") != std::string::npos;
        spec.landscape = !custom || spec.page.widthMm < spec.page.heightMm;
    }
    long long dpi = spec.dpi, bits = spec.bits;
    double margin = spec.marginMm;
    if (!cl.integer("dpi", dpi) || !cl.integer("bits", bits) || !cl.number("margin", margin)) return problem = cl.error(), false;
    if (dpi < 72 || dpi > 2400) return problem = "--dpi must be 72..2400", false;
    if (bits != 8 && bits != 16) return problem = "--bits must be 8 or 16", false;
    spec.dpi = int(dpi);
    spec.bits = int(bits);
    spec.marginMm = margin;
    if (cl.flag("no-legend")) spec.legend = false;
    return true;
}

nlohmann::json reportJson(const plate::PlateContent& plate, const std::string& output, double seconds)
{
    nlohmann::json panels = nlohmann::json::array();
    for (std::size_t i = 0; i < plate.panels.size(); ++i) {
        const auto& p = plate.panels[i];
        const auto& box = plate.layout.panels[i];
        panels.push_back({{"view", cp::panelViewName(plate.spec.panels[i].view)},
                          {"scale", plate.spec.panels[i].scale},
                          {"image_mm", {box.image.w, box.image.h}},
                          {"image_px", {p.image.width, p.image.height}},
                          {"pixel_size_m", p.pixelSizeM},
                          {"scale_bar_mm", box.bar.lengthMm},
                          {"scale_bar_m", box.bar.lengthM}});
    }
    return {{"output", output},
            {"page_mm", {plate.layout.page.widthMm, plate.layout.page.heightMm}},
            {"dpi", plate.spec.dpi},
            {"panels", panels},
            {"seconds", seconds}};
}

} // namespace

int runPlate(const std::vector<std::string>& args)
{
    CommandLine cl("plate", "IN -o OUT.pdf|svg|tif|png --view V --scale N [options] | PROJECT --layout PLATE.json -o OUT",
                   {{"output", "OUT", "the plate: .pdf, .svg, .tif or .png (by extension)", "o"},
                    {"view", "V", "developpee (default), front, back, left, right, top or bottom"},
                    {"scale", "N", "the panel at 1:N"},
                    {"dpi", "D", "print resolution of images and raster pages, 72..2400 (default 600)"},
                    {"page", "P", "A4 (default), A3, letter, 170x105, 205x135 or WxH in mm"},
                    {"landscape", "", "turn the page"},
                    {"margin", "MM", "page margins (default 15 mm; 0 for the journal print areas)"},
                    {"shading", "S", "développée: skydome (default), light or height; 3D: skydome (when the octree has "
                                     "it, the default) or headlight"},
                    {"layer", "L", "draw this annotation layer: material or toolmark"},
                    {"hatches", "", "draw the classes as black-and-white hatches instead of colours"},
                    {"fragment", "NAME", "a project's fragment to draw (default: the first for a développée, every "
                                         "visible one for a 3D view)"},
                    {"caption", "TEXT", "the caption under the plate"},
                    {"no-legend", "", "leave the legend out"},
                    {"bits", "N", "TIFF / PNG: 8 (default) or 16 bits per sample"},
                    {"layout", "PLATE.json", "a composed plate (see docs/plates.md); replaces the panel options"},
                    {"threads", "N", "worker threads (default: all cores)"},
                    {"json", "", "print one JSON object on stdout"}});
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Draws a publication plate at an exact scale: a développée or an orthographic view of a scan, an\n"
                     "octree or a project at 1:N, with a graphic scale bar, the legend of its annotation classes and a\n"
                     "caption, as PDF or SVG (vectors, images lossless, fonts embedded) or TIFF / PNG at D dpi. Needs no\n"
                     "display.\n"
                  << cl.usage();
        return ExitOk;
    }
    if (cl.positionals().size() != 1) return usageError(cl, "plate takes exactly one input file");
    const std::string input = cl.positionals()[0];
    const std::string output = cl.value("output").value_or("");
    if (output.empty()) return usageError(cl, "plate needs -o OUT.pdf|svg|tif|png");
    if (!plate::plateFormatOf(output)) return usageError(cl, "the output " + output + " must end in .pdf, .svg, .tif or .png");
    if (const auto format = plate::plateFormatOf(output);
        cl.value("bits") && (*format == plate::PlateFormat::Pdf || *format == plate::PlateFormat::Svg))
        return usageError(cl, "--bits applies to TIFF and PNG plates; a PDF or SVG keeps its images as they are drawn");
    long long threads = 0;
    if (!cl.integer("threads", threads) || threads < 0 || threads > 1024) return usageError(cl, "--threads must be 0..1024");

    cp::PlateSpec spec;
    std::string problem;
    const auto layoutFile = cl.value("layout");
    if (layoutFile) {
        for (const char* k : {"view", "scale", "shading", "layer", "hatches", "fragment"})
            if (cl.value(k) || cl.flag(k)) return usageError(cl, std::string("--") + k + " does not go with --layout (the layout file states its panels)");
        auto read = cp::PlateSpec::read(*layoutFile);
        if (!read) return fail(read.error());
        spec = std::move(read).value();
        if (cl.value("caption")) spec.caption = *cl.value("caption");
    } else if (!parseOnePanel(cl, spec, problem)) {
        return usageError(cl, problem);
    }
    if (!layoutFile || cl.value("page") || cl.value("dpi") || cl.flag("landscape") || cl.value("bits") || cl.value("margin"))
        if (!parsePage(cl, spec, problem)) return usageError(cl, problem);

    // Check what can be checked before reading anything (a 3D view's default shading waits for its octrees).
    if (auto s = spec.validate(layoutFile ? *layoutFile : std::string("the command line")); !s)
        return usageError(cl, inOptionWords(s.error().message));
    // Usage checked: an output that cannot be written is found before the work.
    if (const std::string problem = outputProblem(output); !problem.empty()) return failure(problem);
    const auto start = core::Clock::now();
    auto sources = cp::readPlateSources(input);
    if (!sources) return fail(sources.error());
    // Notes on what the plate will show, said once it is drawn (an input that then fails to read gets its error alone).
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < spec.panels.size(); ++i) { // a 3D panel that states no shading: skydome where there is one
        cp::PanelSpec& panel = spec.panels[i];
        if (panel.shadingStated || panel.view == cp::PanelView::Developpee) continue;
        auto shading = defaultShading3d(*sources, panel.fragment);
        if (!shading) return fail(shading.error());
        panel.shading = *shading;
        panel.shadingStated = true;
        if (panel.shading == cp::PanelShading::Headlight)
            notes.push_back(input + " has no skydome layer: " +
                            (spec.panels.size() > 1 ? "panel " + std::to_string(i + 1) + "'s" : std::string("the")) +
                            " 3D view is lit from the viewer (headlight)");
    }
    if (auto s = spec.validate(layoutFile ? *layoutFile : std::string("the command line")); !s)
        return usageError(cl, inOptionWords(s.error().message));
    for (std::size_t i = 0; i < spec.panels.size() && !sources->isProject; ++i)
        if (spec.panels[i].layer && !panelLayerHeld(*sources, spec.panels[i]))
            notes.push_back(input + " has no " + core::annotation::layerName(*spec.panels[i].layer) + " layer: " +
                            (spec.panels.size() > 1 ? "panel " + std::to_string(i + 1) : std::string("the plate")) +
                            " shows no classes (label it with `stylos-cli annotate` or in the workbench)");

    // Qt draws the page; the offscreen platform needs no display.
    int qtArgc = 3;
    char arg0[] = "stylos-cli", arg1[] = "-platform", arg2[] = "offscreen";
    char* qtArgv[] = {arg0, arg1, arg2, nullptr};
    qInstallMessageHandler(quietQtMessages);
    QGuiApplication app(qtArgc, qtArgv);

    core::ScratchFolder scratch;
    cp::PanelRenderOptions options;
    options.threads = unsigned(threads);
    if (!sources->isProject && !sources->fragments.front().isOctree) {
        if (auto s = scratch.create(output, "plate"); !s) return fail(s.error());
        options.scratch = scratch.path();
    }
    ConsoleProgress progress("drawing the plate of " + input);
    auto composed = plate::composePlate(*sources, spec, options, &progress);
    if (!composed) return fail(composed.error());
    for (const std::string& note : notes) std::cerr << "stylos-cli: " << note << "\n";
    if (auto s = plate::writePlate(*composed, output); !s) return fail(s.error());
    const double seconds = core::secondsSince(start);
    if (cl.flag("json")) std::cout << reportJson(*composed, output, seconds).dump() << "\n";
    else std::cerr << "stylos-cli: wrote " << output << "\n";
    return ExitOk;
}

} // namespace stylos::cli
