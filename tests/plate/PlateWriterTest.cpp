// Plates written to files and measured as a reader would: a plain generated drum (radius 0.2 m, the generator's
// truth) unrolled at 1:10 is 2π · 0.2 · 1000 / 10 mm wide on the PDF page rasterised by poppler at 1200 dpi
// (within 0.1 %); the scale bar's end ticks are its stated length apart (within 0.1 mm); the page is A4 within
// Qt's whole-point MediaBox (0.18 mm); no image is JPEG and each is at least the plate's dpi; every font is
// embedded; the same inputs give the same bytes (PDF, TIFF); the TIFF states its dpi, ZIP, and its size; the
// SVG's page is in mm; a panel too large for the page writes nothing.
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/plate/PlateSources.h"
#include "stylos/plate/PlateComposer.h"
#include "stylos/plate/PlateWriter.h"

#include <OpenImageIO/imageio.h>
#include <QGuiApplication>
#include <QImage>
#include <QXmlStreamReader>

#include <gtest/gtest.h>

#include <array>
#include <csignal>
#include <cstdio>
#include <cerrno>
#include <fstream>
#include <system_error>
#include <memory>
#include <numbers>
#include <sstream>

#include <sys/resource.h>

using namespace stylos;
namespace cp = core::plate;
namespace fs = std::filesystem;

namespace {

std::string run(const std::string& command)
{
    std::string out;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return out;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    pclose(pipe);
    return out;
}

std::string bytesOf(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Fixture {
    std::unique_ptr<test::TempDir> dir;
    fs::path octree;
    double radius = 0.2;
};

const Fixture& fixture()
{
    static Fixture f = [] {
        Fixture f;
        f.dir = std::make_unique<test::TempDir>();
        auto o = test::coarse(0.003, 5);
        o.radius = f.radius;
        o.height = 0.25;
        o.grooves = 0;
        o.writeNormals = true;
        const auto ply = *f.dir / "drum.ply";
        test::generate(core::synth::SyntheticKind::Drum, o, ply);
        core::octree::BuildOptions build;
        build.depth = 9;
        build.threads = 2;
        f.octree = *f.dir / "drum.poct";
        const auto built = core::octree::buildOctreeFile(ply, f.octree, build);
        EXPECT_TRUE(built.ok()) << (built.ok() ? "" : built.error().message);
        return f;
    }();
    return f;
}

cp::PlateSpec developpeeSpec()
{
    cp::PlateSpec spec;
    spec.dpi = 300;
    spec.caption = "A plain generated drum of radius 0.2 m, unrolled at 1:10.";
    cp::PanelSpec panel;
    panel.scale = 10;
    spec.panels = {panel};
    return spec;
}

core::Result<plate::PlateContent> compose(const cp::PlateSpec& spec)
{
    auto sources = cp::readPlateSources(fixture().octree);
    if (!sources) return sources.error();
    return plate::composePlate(*sources, spec, {});
}

/** Row @p yMm of page 1 of @p pdf rasterised at 1200 dpi by poppler, as grey values. */
std::vector<int> pdfRow(const fs::path& pdf, double yMm, const fs::path& scratch)
{
    const int y = int(std::lround(yMm / 25.4 * 1200));
    const fs::path out = scratch / "row";
    run("pdftoppm -r 1200 -gray -png -singlefile -y " + std::to_string(y) + " -H 1 -W 20000 '" + pdf.string() + "' '" +
        out.string() + "'");
    QImage image(QString::fromStdString(out.string() + ".png"));
    std::vector<int> row;
    if (image.isNull()) return row;
    image = image.convertToFormat(QImage::Format_Grayscale8);
    for (int x = 0; x < image.width(); ++x) row.push_back(image.constScanLine(0)[x]);
    return row;
}

} // namespace

TEST(PlateWriter, DeveloppeePdfIsAtExactScale)
{
    auto plate = compose(developpeeSpec());
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path pdf = *fixture().dir / "dev.pdf";
    ASSERT_TRUE(plate::writePlate(*plate, pdf).ok());

    // The page: A4 within Qt's whole points.
    const std::string info = run("pdfinfo '" + pdf.string() + "'");
    double w = 0, h = 0;
    const auto at = info.find("Page size:");
    ASSERT_NE(at, std::string::npos) << info;
    ASSERT_EQ(std::sscanf(info.c_str() + at, "Page size: %lf x %lf", &w, &h), 2);
    EXPECT_NEAR(w * 25.4 / 72, 210.0, 0.18);
    EXPECT_NEAR(h * 25.4 / 72, 297.0, 0.18);

    // Images lossless and at the plate's dpi; fonts embedded.
    const std::string images = run("pdfimages -list '" + pdf.string() + "'");
    EXPECT_EQ(images.find("jpeg"), std::string::npos) << images;
    std::istringstream lines(images);
    std::string line;
    int count = 0;
    while (std::getline(lines, line)) {
        int page, num, width, height, comp, bpc, object, generation, xppi, yppi;
        char type[16], colour[16], enc[16], interp[8];
        if (std::sscanf(line.c_str(), "%d %d %15s %d %d %15s %d %d %15s %7s %d %d %d %d", &page, &num, type, &width, &height,
                        colour, &comp, &bpc, enc, interp, &object, &generation, &xppi, &yppi) != 14)
            continue;
        ++count;
        EXPECT_GE(xppi, 299) << line;
        EXPECT_GE(yppi, 299) << line;
    }
    EXPECT_EQ(count, 1) << images;
    const std::string fonts = run("pdffonts '" + pdf.string() + "'");
    std::istringstream fontLines(fonts);
    int fontCount = 0;
    while (std::getline(fontLines, line)) {
        if (line.rfind("name", 0) == 0 || line.rfind("----", 0) == 0 || line.empty()) continue;
        ++fontCount;
        EXPECT_NE(line.find(" yes "), std::string::npos) << line; // emb
    }
    EXPECT_GE(fontCount, 1) << fonts;

    // The développée is 2πR/N wide: the covered columns across the image's middle row.
    const cp::PanelBox& box = plate->layout.panels[0];
    const double expectedMm = 2 * std::numbers::pi * fixture().radius * 1000.0 / 10.0;
    EXPECT_NEAR(box.image.w, expectedMm, 0.001 * expectedMm);
    const auto row = pdfRow(pdf, box.image.y + 0.5 * box.image.h, fixture().dir->path());
    ASSERT_FALSE(row.empty());
    int first = -1, last = -1;
    for (int x = 0; x < int(row.size()); ++x)
        if (row[std::size_t(x)] < 250) {
            if (first < 0) first = x;
            last = x;
        }
    const double coveredMm = (last - first + 1) * 25.4 / 1200;
    EXPECT_NEAR(coveredMm, expectedMm, 0.001 * expectedMm) << first << " " << last;

    // The scale bar: its end ticks (above the bar, where nothing else is drawn) are its length apart.
    const auto ticks = pdfRow(pdf, box.barRect.y - 0.4, fixture().dir->path());
    std::vector<double> centres;
    // Along the bar only: its "1:N" text stands to its right.
    const int from = int((box.barRect.x - 2) / 25.4 * 1200), to = std::min(int(ticks.size()), int((box.barRect.right() + 2) / 25.4 * 1200));
    for (int x = from; x < to;) {
        if (ticks[std::size_t(x)] >= 128) { ++x; continue; }
        int e = x;
        while (e < to && ticks[std::size_t(e)] < 128) ++e;
        centres.push_back(0.5 * (x + e - 1) * 25.4 / 1200);
        x = e;
    }
    std::string seen;
    for (const double c : centres) seen += std::to_string(c) + " ";
    ASSERT_EQ(int(centres.size()), box.bar.segments + 1) << seen << " bar x " << box.barRect.x;
    EXPECT_NEAR(centres.back() - centres.front(), box.bar.lengthMm, 0.1);
    EXPECT_NEAR(centres.front(), box.barRect.x, 0.1);
}

TEST(PlateWriter, SameInputsGiveTheSameBytes)
{
    auto plate = compose(developpeeSpec());
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path a = *fixture().dir / "a.pdf", b = *fixture().dir / "b.pdf";
    ASSERT_TRUE(plate::writePlate(*plate, a).ok());
    ASSERT_TRUE(plate::writePlate(*plate, b).ok());
    EXPECT_EQ(bytesOf(a), bytesOf(b));
    const fs::path ta = *fixture().dir / "a.tif", tb = *fixture().dir / "b.tif";
    ASSERT_TRUE(plate::writePlate(*plate, ta).ok());
    ASSERT_TRUE(plate::writePlate(*plate, tb).ok());
    EXPECT_EQ(bytesOf(ta), bytesOf(tb));
    // The TIFF's DateTime is the fixed one (OpenImageIO would stamp the second it writes: a test that straddled
    // a second failed 1 run in 6 before).
    EXPECT_NE(bytesOf(ta).find("2000:01:01 00:00:00"), std::string::npos);
}

TEST(PlateWriter, TiffStatesItsResolutionAndSvgItsMillimetres)
{
    auto spec = developpeeSpec();
    spec.bits = 16;
    auto plate = compose(spec);
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path tif = *fixture().dir / "page.tif";
    ASSERT_TRUE(plate::writePlate(*plate, tif).ok());
    auto in = OIIO::ImageInput::open(tif.string());
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& s = in->spec();
    EXPECT_EQ(s.width, 2480); // 210 mm at 300 dpi
    EXPECT_EQ(s.height, 3508);
    EXPECT_EQ(s.nchannels, 1); // nothing in colour: grey
    EXPECT_EQ(s.format, OIIO::TypeDesc::UINT16);
    EXPECT_FLOAT_EQ(s.get_float_attribute("XResolution"), 300.0f);
    EXPECT_FLOAT_EQ(s.get_float_attribute("YResolution"), 300.0f);
    EXPECT_EQ(s.get_string_attribute("ResolutionUnit"), "in");
    EXPECT_EQ(s.get_string_attribute("compression"), "zip");
    in->close();

    const fs::path svg = *fixture().dir / "page.svg";
    ASSERT_TRUE(plate::writePlate(*plate, svg).ok());
    const std::string text = bytesOf(svg);
    EXPECT_NE(text.find("width=\"210mm\""), std::string::npos) << text.substr(0, 400);
    EXPECT_NE(text.find("height=\"297mm\""), std::string::npos);
    EXPECT_NE(text.find("viewBox=\"0 0 2100 2970\""), std::string::npos);
}

TEST(PlateWriter, TooLargeAPanelWritesNothing)
{
    auto spec = developpeeSpec();
    spec.panels[0].scale = 2; // 628 mm wide
    auto plate = compose(spec);
    ASSERT_FALSE(plate.ok());
    EXPECT_NE(plate.error().message.find("use 1:"), std::string::npos) << plate.error().message;
    EXPECT_EQ(plate::plateFormatOf("x.jpg"), std::nullopt);
}

TEST(PlateWriter, AFolderThatCannotTakeTheFileIsNamedWithTheReason)
{
    auto plate = compose(developpeeSpec());
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path notAFolder = *fixture().dir / "afile";
    { std::ofstream(notAFolder) << "x"; }
    for (const char* name : {"plate.pdf", "plate.svg", "plate.png"}) {
        const fs::path output = notAFolder / name;
        const auto written = plate::writePlate(*plate, output);
        ASSERT_FALSE(written.ok()) << name;
        EXPECT_EQ(written.error().code, core::ErrorCode::WriteFailed) << name;
        EXPECT_NE(written.error().message.find(output.string()), std::string::npos) << written.error().message;
        EXPECT_NE(written.error().message.find(std::generic_category().message(ENOTDIR)), std::string::npos)
            << written.error().message;
    }
    EXPECT_EQ(bytesOf(notAFolder), "x");
}

namespace {

/** Asks to cancel from its (after + 1)-th question on: a user's Cancel at some point of the writing. */
class CancelAfter final : public core::ProgressSink {
public:
    explicit CancelAfter(int after) : m_after(after) {}
    void update(double) override {}
    bool isCancelRequested() const override { return ++m_asked > m_after; }

private:
    int m_after;
    mutable int m_asked = 0;
};

} // namespace

TEST(PlateWriter, ACancelLeavesTheExistingFileAsItWas)
{
    auto plate = compose(developpeeSpec());
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path dir = *fixture().dir / "cancel";
    fs::create_directories(dir);
    for (const char* name : {"plate.pdf", "plate.svg", "plate.png", "plate.tif"}) {
        const fs::path output = dir / name;
        int cancelled = 0;
        for (int after = 0; after < 4; ++after) {
            { std::ofstream(output) << "the plate of last week"; }
            CancelAfter progress(after);
            const auto written = plate::writePlate(*plate, output, &progress);
            if (!written.ok()) {
                ++cancelled;
                EXPECT_EQ(written.error().code, core::ErrorCode::Cancelled) << name << written.error().message;
                EXPECT_EQ(bytesOf(output), "the plate of last week") << name << " cancelled after " << after;
            } else {
                EXPECT_NE(bytesOf(output), "the plate of last week") << name;
            }
            std::vector<std::string> left;
            for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
            EXPECT_EQ(left, std::vector<std::string>{name}) << "no partial file left";
            fs::remove(output);
        }
        // Cancelled at the start and after the drawing (the second question), written once nothing asks any more.
        EXPECT_GE(cancelled, 2) << name;
    }
}

TEST(PlateWriter, ASmallPanelsLabelsKeepClearOfTheNext)
{
    // The drum's développée at 1:1000 (1.3 × 0.25 mm) beside its back view at 1:20: the small panel's title and its
    // bar with "1:1000" take more than its image; the back view starts after them, not over them.
    auto spec = developpeeSpec();
    spec.landscape = true;
    spec.panels[0].scale = 1000;
    cp::PanelSpec back;
    back.view = cp::PanelView::Back;
    back.shading = cp::PanelShading::Headlight;
    back.scale = 20;
    spec.panels.push_back(back);
    auto sources = cp::readPlateSources(fixture().octree);
    ASSERT_TRUE(sources.ok());
    plate::PlateTexts french = plate::PlateTexts::english();
    french.views[0] = QStringLiteral("développée d’un tambour très long à lire");
    french.decimalPoint = QStringLiteral(",");
    auto plate = plate::composePlate(*sources, spec, {}, nullptr, french);
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const auto& a = plate->layout.panels[0];
    const auto& b = plate->layout.panels[1];
    ASSERT_DOUBLE_EQ(a.image.y, b.image.y); // one row
    const double labels = plate::panelLabelWidthMm(spec.panels[0], true, french);
    EXPECT_GT(labels, a.barRect.w + 9.0);  // the bar (50 mm at 1:1000) and "1:1000" beyond its image
    EXPECT_GT(labels, a.image.w + 40.0);
    EXPECT_GE(b.image.x, a.image.x + labels + cp::kPanelGapMm - 1e-9);
    EXPECT_GT(plate::panelLabelWidthMm(spec.panels[0], true, french),
              plate::panelLabelWidthMm(spec.panels[0], true, plate::PlateTexts::english())); // the longer title
    EXPECT_EQ(plate->texts.decimalPoint, QStringLiteral(","));
    // The bar's labels with the plate's decimal point: at 1:20 the back view's 1 m bar reads 0 0,2 0,4 0,6 0,8 1 m
    // (written as SVG text).
    const fs::path svg = *fixture().dir / "french.svg";
    ASSERT_TRUE(plate::writePlate(*plate, svg).ok());
    const std::string text = bytesOf(svg);
    EXPECT_NE(text.find(">0,2<"), std::string::npos);
    EXPECT_EQ(text.find(">0.2<"), std::string::npos);
}

TEST(PlateWriter, ALongCaptionIsTheTitleCutAtAWord)
{
    auto spec = developpeeSpec();
    spec.caption.clear();
    for (int i = 0; i < 40; ++i) spec.caption += "Tambour à cannelures, Δελφοί ";
    auto plate = compose(spec);
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path pdf = *fixture().dir / "title.pdf";
    ASSERT_TRUE(plate::writePlate(*plate, pdf).ok());
    const std::string info = run("pdfinfo '" + pdf.string() + "'");
    const auto at = info.find("Title:");
    ASSERT_NE(at, std::string::npos) << info;
    std::string title = info.substr(at + 6, info.find('\n', at) - at - 6);
    title.erase(0, title.find_first_not_of(' '));
    // 200 characters at most before the ellipsis, ending on a whole word ("cannelures," or "Δελφοί").
    const QString t = QString::fromStdString(title);
    ASSERT_TRUE(t.endsWith(QStringLiteral("…"))) << title;
    EXPECT_LE(t.size(), 201) << title;
    EXPECT_GT(t.size(), 150) << title;
    EXPECT_TRUE(QString::fromStdString(spec.caption).startsWith(t.chopped(1) + QLatin1Char(' '))) << title;
}

namespace {

/** The files a process may write grow to @p bytes at most while it lives (RLIMIT_FSIZE): a write past it fails with
 *  EFBIG, as a full disk fails one with ENOSPC — without a disk to fill. SIGXFSZ is ignored meanwhile. */
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        getrlimit(RLIMIT_FSIZE, &m_old);
        m_signal = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = m_old;
        limit.rlim_cur = bytes;
        m_set = setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &m_old);
        std::signal(SIGXFSZ, m_signal);
    }
    bool set() const { return m_set; }

private:
    rlimit m_old{};
    void (*m_signal)(int) = nullptr;
    bool m_set = false;
};

} // namespace

// A disk that fills while a plate is written: an error naming the file and the reason, the plate written before left as
// it was, no partial file. Before, the PDF and SVG were reported written (Qt's writers say nothing of a failed write)
// and the PNG too (libpng ignores a short write): a truncated file replaced the good one.
TEST(PlateWriter, AFullDiskWritesNothingAndKeepsTheFileThatWasThere)
{
    auto plate = compose(developpeeSpec());
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path dir = *fixture().dir / "full";
    fs::create_directories(dir);
    for (const char* name : {"plate.pdf", "plate.svg", "plate.png", "plate.tif"}) {
        const fs::path output = dir / name;
        { std::ofstream(output) << "the plate of last week"; }
        core::Status written;
        {
            const FileSizeLimit limit(20000); // each of these plates is larger
            ASSERT_TRUE(limit.set());
            written = plate::writePlate(*plate, output);
        }
        ASSERT_FALSE(written.ok()) << name;
        EXPECT_EQ(written.error().code, core::ErrorCode::WriteFailed) << name;
        EXPECT_NE(written.error().message.find(output.string()), std::string::npos) << written.error().message;
        EXPECT_EQ(bytesOf(output), "the plate of last week") << name;
        std::vector<std::string> left;
        for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
        EXPECT_EQ(left, std::vector<std::string>{name}) << "no partial file left";
        // With room, it is written.
        ASSERT_TRUE(plate::writePlate(*plate, output).ok()) << name;
        EXPECT_GT(fs::file_size(output), 20000u) << name;
        fs::remove(output);
    }
}

// The SVG's <title> is the caption: escaped, so that "&" or "<" in it leave the file well-formed XML (it was not).
TEST(PlateWriter, ACaptionWithMarkupCharactersKeepsTheSvgWellFormed)
{
    auto spec = developpeeSpec();
    spec.caption = "Drums 1 & 2 <Delphi>";
    auto plate = compose(spec);
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path svg = *fixture().dir / "amp.svg";
    ASSERT_TRUE(plate::writePlate(*plate, svg).ok());
    const std::string text = bytesOf(svg);
    EXPECT_NE(text.find("<title>Drums 1 &amp; 2 &lt;Delphi&gt;</title>"), std::string::npos) << text.substr(0, 600);
    QXmlStreamReader xml(QByteArray::fromStdString(text));
    while (!xml.atEnd()) xml.readNext();
    EXPECT_FALSE(xml.hasError()) << xml.errorString().toStdString() << " at line " << xml.lineNumber();
}

// A caption word wider than the print area (a long URL, a run of characters without spaces) wraps inside the word and
// stays within the print area; before, it was cut at the print area's edge and the rest of it lost.
TEST(PlateWriter, AWordWiderThanThePageWrapsInsideThePrintArea)
{
    auto spec = developpeeSpec();
    spec.dpi = 72;
    spec.caption = "Drum 2 " + std::string(400, 'x') + " end";
    auto plate = compose(spec);
    ASSERT_TRUE(plate.ok()) << plate.error().message;
    const fs::path png = *fixture().dir / "longword.png";
    ASSERT_TRUE(plate::writePlate(*plate, png).ok());
    QImage image(QString::fromStdString(png.string()));
    ASSERT_FALSE(image.isNull());
    image = image.convertToFormat(QImage::Format_Grayscale8);
    const auto& c = plate->layout.caption;
    const double pxPerMm = 72 / 25.4;
    const int right = int(std::ceil((spec.orientedPage().widthMm - spec.marginMm) * pxPerMm)) + 1;
    const int top = int(c.y * pxPerMm), bottom = std::min(image.height() - 1, int((c.y + c.h) * pxPerMm));
    int ink = 0, inside = 0;
    for (int y = top; y <= bottom; ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (image.constScanLine(y)[x] > 128) continue;
            (x > right ? ink : inside) += 1;
        }
    EXPECT_GT(inside, 1000); // the caption is there, on several lines
    EXPECT_EQ(ink, 0) << "caption ink right of the print area";
    // 400 "x" of 9 pt (~1.7 mm each) on a 180 mm line: four lines of them, with "Drum 2" five at least (~3.7 mm
    // each). Before, the word was one line cut at the print area's edge, the rest of it lost: three lines, 13 mm.
    EXPECT_GT(c.h, 16.0);
}

int main(int argc, char** argv)
{
    int qtArgc = 3;
    char arg0[] = "stylos_plate_tests", arg1[] = "-platform", arg2[] = "offscreen";
    char* qtArgv[] = {arg0, arg1, arg2, nullptr};
    QGuiApplication app(qtArgc, qtArgv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

// A project's fragment is unrolled on a plate about its axis guide, as the workbench's Développée dock unrolls it
// (before, the plate fitted its own axis: its angles and cut differed from the dock's by ~115° on a docked drum).
// The guide here is the fitted axis turned end for end: the plate's développée is then the default one turned
// half a turn; and the options a fragment carries (here a pixel size) reach the computation.
TEST(PlateSources, AProjectsFragmentUnrollsAboutItsAxisGuide)
{
    core::developpee::DeveloppeeOptions fitted;
    fitted.threads = 2;
    const auto reference = core::developpee::computeDeveloppee(fixture().octree, fitted);
    ASSERT_TRUE(reference.ok()) << reference.error().message;
    const core::unroll::Axis axis = reference->map.surface().axis();

    core::scene::Scene scene;
    core::scene::Fragment drum;
    drum.name = "drum";
    drum.octreePath = fixture().octree;
    drum.guides.push_back({"axis", core::scene::GuideKind::Axis, core::scene::toArray(axis.point),
                           core::scene::toArray(-axis.direction)});
    scene.add(drum);
    const fs::path project = *fixture().dir / "guided.stylos";
    ASSERT_TRUE(core::scene::ProjectFile::save(scene, project).ok());
    auto sources = cp::readPlateSources(project);
    ASSERT_TRUE(sources.ok()) << sources.error().message;
    ASSERT_EQ(sources->fragments.size(), 1u);
    const auto& unrolling = sources->fragments[0].unrolling;
    ASSERT_TRUE(unrolling && unrolling->axis);
    EXPECT_NEAR((unrolling->axis->point - axis.point).norm(), 0.0, 1e-12);
    EXPECT_NEAR((unrolling->axis->direction + axis.direction).norm(), 0.0, 1e-12);

    cp::PanelSpec panel;
    panel.scale = 10;
    cp::PanelRenderOptions render;
    render.dpi = 100;
    render.threads = 2;
    auto unguided = *sources;
    unguided.fragments[0].unrolling.reset();
    const auto plain = cp::renderPanel(unguided, panel, render);
    const auto guided = cp::renderPanel(*sources, panel, render);
    ASSERT_TRUE(plain.ok() && guided.ok());
    ASSERT_EQ(guided->image.width, plain->image.width);
    ASSERT_EQ(guided->image.height, plain->image.height);
    // Turned end for end, the développée is upside down and reads right to left: the guided image turned half a
    // turn is the plain one (up to where the cut falls: rows compared as periodic sequences, at the best shift).
    const int w = plain->image.width, h = plain->image.height;
    double turned = 0, same = 0;
    for (int shift = 0; shift < w; ++shift) {
        double m = 0, s = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double p = plain->image.sample(x, y);
                m += std::abs(p - guided->image.sample((w - 1 - x + shift) % w, h - 1 - y));
                s += std::abs(p - guided->image.sample((x + shift) % w, y));
            }
        turned = shift == 0 ? m : std::min(turned, m);
        same = shift == 0 ? s : std::min(same, s);
    }
    EXPECT_LT(turned, 0.5 * same) << "turned " << turned << ", same way " << same;

    auto sized = *sources;
    sized.fragments[0].unrolling->pixelSize = 0.004;
    const auto coarse = cp::renderPanel(sized, panel, render);
    ASSERT_TRUE(coarse.ok()) << coarse.error().message;
    EXPECT_EQ(coarse->naturalPixelM, 0.004);
    EXPECT_NE(plain->naturalPixelM, 0.004);
}

// A fluted drum whose guides were fitted in the workbench (axis and flute lines in the project): a plate of its
// développée from the project is the dock's — unrolled about the axis guide at the drum guides' leading radius and
// taper (fitted as the dock fits them) — not one at a radius fitted about the axis (whose default cut, on a whole
// drum, fell elsewhere: the same painted patch at 20° in the dock and at 267° on the plate).
TEST(PlateSources, AFlutedDrumUnrollsAtItsGuidesRadius)
{
    test::TempDir dir;
    auto o = test::coarse(0.006, 3);
    o.writeNormals = true;
    const auto ply = dir / "fluted.ply";
    test::generate(core::synth::SyntheticKind::Drum, o, ply);
    core::octree::BuildOptions build;
    build.depth = 8;
    build.threads = 2;
    const fs::path octree = dir / "fluted.poct";
    ASSERT_TRUE(core::octree::buildOctreeFile(ply, octree, build).ok());
    core::cloud::CloudLoadOptions load;
    load.keepNormals = true;
    auto cloud = core::cloud::loadPointCloud(octree, load);
    ASSERT_TRUE(cloud.ok()) << cloud.error().message;
    const auto fitted = core::dock::fitDrumGuides(*cloud);
    ASSERT_TRUE(fitted.ok()) << fitted.error().message;

    core::scene::Scene scene;
    core::scene::Fragment drum;
    drum.name = "drum";
    drum.octreePath = octree;
    drum.guides.push_back({"axis", core::scene::GuideKind::Axis, core::scene::toArray(fitted->axis.point),
                           core::scene::toArray(fitted->axis.direction)});
    for (const auto& line : fitted->fluteLines)
        drum.guides.push_back({"flute", core::scene::GuideKind::Groove, core::scene::toArray(line.point),
                               core::scene::toArray(line.direction)});
    scene.add(drum);
    const fs::path project = dir / "fluted.stylos";
    ASSERT_TRUE(core::scene::ProjectFile::save(scene, project).ok());
    auto sources = cp::readPlateSources(project);
    ASSERT_TRUE(sources.ok()) << sources.error().message;
    ASSERT_TRUE(sources->fragments[0].drumGuides);
    EXPECT_EQ(sources->fragments[0].drumGuides->octree, octree);
    EXPECT_EQ(sources->fragments[0].drumGuides->options.flutes, int(fitted->fluteLines.size()));

    // What the dock computes: the axis guide, the guides' radius and taper fitted about it with its flute count.
    const auto options = core::dock::guideOptionsFor(scene.fragments()[0]);
    ASSERT_TRUE(options);
    const auto guides = core::dock::fitDrumGuides(*cloud, *options);
    ASSERT_TRUE(guides.ok()) << guides.error().message;
    auto dock = *sources;
    dock.fragments[0].drumGuides.reset();
    dock.fragments[0].unrolling->radius = guides->radius;
    dock.fragments[0].unrolling->radiusSlope = guides->slope;
    auto fittedRadius = *sources;
    fittedRadius.fragments[0].drumGuides.reset();

    cp::PanelSpec panel;
    panel.scale = 10;
    cp::PanelRenderOptions render;
    render.dpi = 100;
    render.threads = 2;
    const auto plate = cp::renderPanel(*sources, panel, render);
    const auto docked = cp::renderPanel(dock, panel, render);
    const auto unguided = cp::renderPanel(fittedRadius, panel, render);
    ASSERT_TRUE(plate.ok() && docked.ok() && unguided.ok());
    EXPECT_EQ(plate->imageMm, docked->imageMm);
    EXPECT_EQ(plate->image.samples, docked->image.samples);
    // 2π R at 1:10, R the guides' leading radius; not the radius fitted about the axis alone.
    EXPECT_NEAR(plate->imageMm[0], 2 * std::numbers::pi * guides->radius * 1000 / 10, 1e-6);
    EXPECT_NE(plate->imageMm[0], unguided->imageMm[0]);
}

// A piece docked against the drum without an assembly (Fragment › Dock against this drum, saved with the project):
// its plate unrolls it about the drum's axis guide at the drum guides' radius, as the dock does. Before, the saved
// project did not hold the docking drum and the piece's plate fitted an axis of its own.
TEST(PlateSources, APieceUnrollsAboutTheSavedDockingDrumsAxis)
{
    test::TempDir dir;
    auto o = test::coarse(0.02, 3);
    const auto ply = dir / "drum.ply";
    test::generate(core::synth::SyntheticKind::Drum, o, ply);
    core::octree::BuildOptions build;
    build.depth = 6;
    const fs::path octree = dir / "drum.poct";
    ASSERT_TRUE(core::octree::buildOctreeFile(ply, octree, build).ok());

    core::scene::Scene scene;
    core::scene::Fragment drum;
    drum.name = "drum";
    drum.octreePath = octree;
    drum.guides.push_back({"axis", core::scene::GuideKind::Axis, {0.1, 0.2, 0.3}, {0, 0, 1}});
    for (int k = 0; k < 3; ++k) // three flute lines at least: the dock fits the guides' radius with their count
        drum.guides.push_back({"flute", core::scene::GuideKind::Groove, {0.6, 0.2 + 0.1 * k, 0.3}, {0, 0, 1}});
    const auto drumId = scene.add(drum);
    core::scene::Fragment piece;
    piece.name = "piece";
    piece.octreePath = octree;
    piece.pose = core::scene::Pose::fromTranslationAngles({{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}});
    scene.add(piece);
    const fs::path project = dir / "docked.stylos";
    ASSERT_TRUE(core::scene::ProjectFile::save(scene, project).ok());
    auto alone = cp::readPlateSources(project);
    ASSERT_TRUE(alone.ok()) << alone.error().message;
    EXPECT_FALSE(alone->fragments[1].unrolling); // no drum: an axis of its own
    EXPECT_FALSE(alone->fragments[1].drumGuides);

    ASSERT_TRUE(scene.setDockingDrum(drumId));
    ASSERT_TRUE(core::scene::ProjectFile::save(scene, project).ok());
    auto docked = cp::readPlateSources(project);
    ASSERT_TRUE(docked.ok()) << docked.error().message;
    const auto& unrolling = docked->fragments[1].unrolling;
    ASSERT_TRUE(unrolling);
    // The drum's axis in the piece's frame: the piece sits 1 m along x from the drum.
    EXPECT_NEAR(unrolling->axis->point.x(), 0.1 - 1.0, 1e-12);
    EXPECT_NEAR(unrolling->axis->point.y(), 0.2, 1e-12);
    EXPECT_NEAR(unrolling->axis->direction.z(), 1.0, 1e-12);
    ASSERT_TRUE(docked->fragments[1].drumGuides);
    EXPECT_EQ(docked->fragments[1].drumGuides->octree, octree);
    EXPECT_EQ(docked->fragments[1].drumGuides->options.flutes, 3);
}
