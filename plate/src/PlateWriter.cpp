// Writing a plate page as PDF, SVG, TIFF or PNG, atomically and reproducibly.
#include "stylos/plate/PlateWriter.h"
#include "stylos/core/util/AtomicTextFile.h"

#include <QBuffer>
#include <QHashSeed>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QRegularExpression>
#include <QSvgGenerator>

#include "stylos/core/image/ImageLibrary.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <system_error>

namespace stylos::plate {

namespace {

namespace fs = std::filesystem;
using core::Error;
using core::ErrorCode;
using core::Status;

constexpr int kPdfDpi = 1200;   // QPdfWriter's device units: 1/1200 inch
constexpr int kSvgPerMm = 10;   // SVG user units: 0.1 mm

fs::path partialPath(const fs::path& output)
{
    return output.parent_path() / ("." + output.filename().string() + ".partial");
}

/** Whether the writing was cancelled: then the partial file goes and the target is left as it was. */
bool cancelled(const core::ProgressSink* progress)
{
    return progress != nullptr && progress->isCancelRequested();
}

Error cancelledError(const fs::path& output)
{
    return Error::at(ErrorCode::Cancelled, output.string(), {}, "cancelled; the file was not written");
}

Status finish(const fs::path& partial, const fs::path& output, const core::ProgressSink* progress = nullptr)
{
    std::error_code error;
    if (cancelled(progress)) { // the last moment: an existing file is not replaced
        fs::remove(partial, error);
        return cancelledError(output);
    }
    core::keepModeOf(output, partial);
    fs::rename(partial, output, error);
    if (error) {
        const std::string why = error.message();
        fs::remove(partial, error);
        return Error::at(ErrorCode::WriteFailed, output.string(), {}, "cannot rename the finished file into place: " + why);
    }
    return {};
}

/** Removes @p partial and returns @p error. */
Status discard(const fs::path& partial, Error error)
{
    std::error_code ignored;
    fs::remove(partial, ignored);
    return error;
}

Status failed(const fs::path& partial, const fs::path& output, const std::string& why)
{
    return discard(partial, Error::at(ErrorCode::WriteFailed, output.string(), {}, why));
}

/** Creates @p partial empty, so that a folder that cannot take it is named with the system's reason (Qt's PDF and
 *  SVG writers only say that they could not start). */
Status createPartial(const fs::path& partial, const fs::path& output)
{
    std::FILE* file = std::fopen(partial.c_str(), "wb");
    if (!file) // the error code's message: strerror is not thread-safe, and plates are written on worker threads
        return Error::at(ErrorCode::WriteFailed, output.string(), {},
                         "cannot create the file: " + std::error_code(errno, std::generic_category()).message());
    std::fclose(file);
    return {};
}

/** Replaces the clock- and random-dependent parts of a Qt PDF (@p bytes) by fixed text of the same length. */
void makeReproducible(QByteArray& bytes)
{
    // Digits and letters become those of a fixed date (2000-01-01 00:00:00), then zeros: same length, same offsets.
    auto blank = [&](const QRegularExpression& re) {
        static const char fixed[] = "20000101000000";
        auto it = re.globalMatch(QString::fromLatin1(bytes));
        while (it.hasNext()) {
            const auto m = it.next();
            std::size_t k = 0;
            for (int i = int(m.capturedStart(1)); i < int(m.capturedEnd(1)); ++i)
                if (std::isalnum(static_cast<unsigned char>(bytes[i]))) bytes[i] = k < 14 ? fixed[k++] : '0';
        }
    };
    blank(QRegularExpression(QStringLiteral("/CreationDate \\(D:([^)]*)\\)")));
    blank(QRegularExpression(QStringLiteral("/ModDate \\(D:([^)]*)\\)")));
    blank(QRegularExpression(QStringLiteral("/ID \\[\\s*(<[0-9a-fA-F]*>\\s*<[0-9a-fA-F]*>)\\s*\\]")));
    blank(QRegularExpression(QStringLiteral("<xmp:CreateDate>([^<]*)<")));
    blank(QRegularExpression(QStringLiteral("<xmp:ModifyDate>([^<]*)<")));
    blank(QRegularExpression(QStringLiteral("<xmp:MetadataDate>([^<]*)<")));
    blank(QRegularExpression(QStringLiteral("uuid:([0-9a-fA-F-]*)")));
}

/** Writes @p bytes into @p partial (created by createPartial) and checks every step — the write, the flush, the
 *  close: a full disk shows at one of them, where Qt's PDF and SVG writers say nothing. */
Status writeBytes(const QByteArray& bytes, const fs::path& partial, const fs::path& output)
{
    std::FILE* file = std::fopen(partial.c_str(), "wb");
    if (!file)
        return failed(partial, output, "cannot create the file: " + std::error_code(errno, std::generic_category()).message());
    errno = 0;
    const bool written = std::fwrite(bytes.constData(), 1, std::size_t(bytes.size()), file) == std::size_t(bytes.size()) &&
                         std::fflush(file) == 0;
    int why = written ? 0 : (errno != 0 ? errno : EIO);
    if (std::fclose(file) != 0 && why == 0) why = errno != 0 ? errno : EIO;
    if (why != 0)
        return failed(partial, output, "cannot write the file: " + std::error_code(why, std::generic_category()).message() +
                                           " (" + std::to_string(bytes.size()) + " bytes to write)");
    return {};
}

/** The document title: the caption, cut at a word within 200 characters with an ellipsis (never inside a
 *  character: the caption is UTF-8). */
QString documentTitle(const std::string& caption)
{
    constexpr qsizetype most = 200;
    QString title = QString::fromStdString(caption).simplified();
    if (title.size() <= most) return title;
    qsizetype cut = title.lastIndexOf(QLatin1Char(' '), most - 1);
    if (cut < most / 2) cut = most - 1; // one long word: cut inside it
    if (cut > 0 && title.at(cut - 1).isHighSurrogate()) --cut;
    return title.left(cut).trimmed() + QStringLiteral("…");
}

Status writePdf(const PlateContent& plate, const fs::path& output, const core::ProgressSink* progress)
{
    const fs::path partial = partialPath(output);
    if (Status created = createPartial(partial, output); !created) return created;
    // Drawn in memory, then written with every step checked (a PDF of a plate is a few MB).
    QByteArray bytes;
    // Qt keeps the PDF's fonts in a QHash: with the per-process random seed their objects come out in a
    // different order from one run to the next. A fixed seed makes the bytes the same.
    QHashSeed::setDeterministicGlobalSeed();
    {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QPdfWriter writer(&buffer);
        const auto& page = plate.layout.page;
        writer.setPageLayout(QPageLayout(QPageSize(QSizeF(page.widthMm, page.heightMm), QPageSize::Millimeter,
                                                   QString(), QPageSize::ExactMatch),
                                         QPageLayout::Portrait, QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter));
        writer.setResolution(kPdfDpi);
        writer.setCreator(QStringLiteral("Stylos"));
        writer.setTitle(documentTitle(plate.spec.caption));
        QPainter painter;
        if (!painter.begin(&writer)) return failed(partial, output, "cannot start the PDF");
        painter.scale(kPdfDpi / 25.4, kPdfDpi / 25.4);
        paintPlate(painter, plate);
        if (!painter.end()) return failed(partial, output, "writing the PDF failed");
    }
    makeReproducible(bytes);
    if (Status written = writeBytes(bytes, partial, output); !written) return written;
    return finish(partial, output, progress);
}

Status writeSvg(const PlateContent& plate, const fs::path& output, const core::ProgressSink* progress)
{
    const fs::path partial = partialPath(output);
    if (Status created = createPartial(partial, output); !created) return created;
    const auto& page = plate.layout.page;
    QByteArray bytes;
    {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        const QSize size(int(std::lround(page.widthMm * kSvgPerMm)), int(std::lround(page.heightMm * kSvgPerMm)));
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setResolution(int(std::lround(25.4 * kSvgPerMm))); // 254 dpi: width and height come out in mm
        // Qt writes the title and description into the XML as given: escaped here ("Drums 1 & 2" broke the file).
        svg.setTitle(documentTitle(plate.spec.caption).toHtmlEscaped());
        svg.setDescription(QStringLiteral("Stylos plate"));
        QPainter painter;
        if (!painter.begin(&svg)) return failed(partial, output, "cannot start the SVG");
        painter.scale(kSvgPerMm, kSvgPerMm);
        paintPlate(painter, plate);
        if (!painter.end()) return failed(partial, output, "writing the SVG failed");
    }
    if (Status written = writeBytes(bytes, partial, output); !written) return written;
    return finish(partial, output, progress);
}

/** The TIFF DateTime of every image written: the PDF's fixed date, so that the same plate gives the same bytes. */
constexpr const char* ReproducibleDateTime = "2000:01:01 00:00:00";

/** Writes @p pixels (@p spec's size, channels and format) as TIFF or PNG by @p output's extension, through a
 *  partial file (the same extension, which chooses the format) renamed at the end. */
Status writeImageFile(const core::image::ImageHeader& spec, const void* pixels, const fs::path& output,
                      const core::ProgressSink* progress = nullptr)
{
    const fs::path partial = output.parent_path() / ("." + output.stem().string() + ".partial" + output.extension().string());
    if (auto written = core::image::writeWholeImage(partial.string(), spec, pixels, output.string()); !written)
        return discard(partial, written.error()); // names the output (and the partial file if it cannot be created)
    return finish(partial, output, progress);
}

/** A raster's header: its size, channels and depth, "Software" and the fixed DateTime. */
core::image::ImageHeader imageHeader(int width, int height, int channels, bool sixteen)
{
    core::image::ImageHeader header;
    header.width = width;
    header.height = height;
    header.channels = channels;
    header.sample = sixteen ? core::image::ImageSample::UInt16 : core::image::ImageSample::UInt8;
    header.set("Software", std::string("Stylos"));
    header.set("DateTime", std::string(ReproducibleDateTime)); // else OpenImageIO stamps the second it writes
    return header;
}

bool inColour(const PlateContent& plate)
{
    for (const auto& panel : plate.panels)
        if (panel.image.channels == 3) return true;
    if (plate.spec.legend)
        for (const auto& p : plate.spec.panels)
            if (p.layer && !p.hatches) return true;
    return false;
}

Status writeRaster(const PlateContent& plate, const fs::path& output, PlateFormat format,
                   const core::ProgressSink* progress)
{
    const QSize size = rasterPageSize(plate);
    const double pixels = double(size.width()) * double(size.height());
    if (pixels > 2.0e9)
        return Error::at(ErrorCode::InvalidArgument, output.string(), {},
                         "the page at " + std::to_string(plate.spec.dpi) + " dpi would be " + std::to_string(size.width()) +
                             " × " + std::to_string(size.height()) + " pixels, too large to write; lower the dpi");
    const bool colour = inColour(plate), sixteen = plate.spec.bits == 16;
    QImage page(size, sixteen ? QImage::Format_RGBX64 : QImage::Format_RGB888);
    page.fill(Qt::white);
    const int dpm = int(std::lround(plate.spec.dpi / 0.0254));
    page.setDotsPerMeterX(dpm);
    page.setDotsPerMeterY(dpm);
    {
        QPainter painter(&page);
        painter.scale(size.width() / plate.layout.page.widthMm, size.height() / plate.layout.page.heightMm);
        paintPlate(painter, plate);
    }
    const int channels = colour ? 3 : 1;
    core::image::ImageHeader spec = imageHeader(size.width(), size.height(), channels, sixteen);
    spec.set("XResolution", float(plate.spec.dpi));
    spec.set("YResolution", float(plate.spec.dpi));
    spec.set("ResolutionUnit", std::string("in"));
    if (format == PlateFormat::Tiff) spec.set("compression", std::string("zip"));
    std::vector<std::uint8_t> buffer(std::size_t(size.width()) * std::size_t(size.height()) * std::size_t(channels) *
                                     (sixteen ? 2u : 1u));
    for (int y = 0; y < size.height(); ++y) {
        const uchar* line = page.constScanLine(y);
        for (int x = 0; x < size.width(); ++x) {
            const std::size_t o = (std::size_t(y) * std::size_t(size.width()) + std::size_t(x)) * std::size_t(channels);
            if (sixteen) {
                const quint16* px = reinterpret_cast<const quint16*>(line) + 4 * x;
                auto* out = reinterpret_cast<std::uint16_t*>(buffer.data());
                if (colour) out[o] = px[0], out[o + 1] = px[1], out[o + 2] = px[2];
                else out[o] = std::uint16_t((std::uint32_t(px[0]) * 299 + std::uint32_t(px[1]) * 587 + std::uint32_t(px[2]) * 114 + 500) / 1000);
            } else {
                const uchar* px = line + 3 * x;
                if (colour) buffer[o] = px[0], buffer[o + 1] = px[1], buffer[o + 2] = px[2];
                else buffer[o] = std::uint8_t((int(px[0]) * 299 + int(px[1]) * 587 + int(px[2]) * 114 + 500) / 1000);
            }
        }
    }
    if (cancelled(progress)) return cancelledError(output);
    return writeImageFile(spec, buffer.data(), output, progress);
}

} // namespace

std::optional<PlateFormat> plateFormatOf(const fs::path& path)
{
    std::string e = path.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (e == ".pdf") return PlateFormat::Pdf;
    if (e == ".svg") return PlateFormat::Svg;
    if (e == ".tif" || e == ".tiff") return PlateFormat::Tiff;
    if (e == ".png") return PlateFormat::Png;
    return std::nullopt;
}

QSize rasterPageSize(const PlateContent& plate)
{
    const double dpi = plate.spec.dpi;
    return {int(std::lround(plate.layout.page.widthMm / 25.4 * dpi)), int(std::lround(plate.layout.page.heightMm / 25.4 * dpi))};
}

Status writePanelImage(const core::plate::PanelImage& image, const fs::path& output, int bits,
                       const core::ProgressSink* progress)
{
    const auto format = plateFormatOf(output);
    if (!format || (*format != PlateFormat::Png && *format != PlateFormat::Tiff))
        return Error::at(ErrorCode::InvalidArgument, output.string(), {}, "a view image is written as .png or .tif");
    const bool sixteen = bits == 16;
    core::image::ImageHeader spec = imageHeader(image.width, image.height, image.channels, sixteen);
    spec.set("stylos:pixel_size_m", float(image.pixelSizeM));
    if (*format == PlateFormat::Tiff) spec.set("compression", std::string("zip"));
    std::vector<std::uint8_t> bytes;
    if (!sixteen) {
        bytes.resize(image.samples.size());
        for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::uint8_t((image.samples[i] + 128) / 257);
    }
    return writeImageFile(spec, sixteen ? static_cast<const void*>(image.samples.data()) : bytes.data(), output, progress);
}

Status writePlate(const PlateContent& plate, const fs::path& output, const core::ProgressSink* progress)
{
    const auto format = plateFormatOf(output);
    if (!format)
        return Error::at(ErrorCode::InvalidArgument, output.string(), {}, "a plate is written as .pdf, .svg, .tif or .png");
    if (cancelled(progress)) return cancelledError(output);
    switch (*format) {
    case PlateFormat::Pdf: return writePdf(plate, output, progress);
    case PlateFormat::Svg: return writeSvg(plate, output, progress);
    case PlateFormat::Tiff:
    case PlateFormat::Png: return writeRaster(plate, output, *format, progress);
    }
    return {};
}

} // namespace stylos::plate
