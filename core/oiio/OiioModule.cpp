// libstylos_oiio.so: Stylos's one use of OpenImageIO, behind core/image/ImageLibrary.h's plain interface,
// loaded on demand so that programs which never touch an image do not load OpenImageIO's ~260 libraries.
#include "stylos/core/image/ImageLibrary.h"

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace stylos::core::image {

namespace {

OIIO::TypeDesc typeOf(ImageSample sample)
{
    switch (sample) {
    case ImageSample::UInt8: return OIIO::TypeDesc::UINT8;
    case ImageSample::UInt16: return OIIO::TypeDesc::UINT16;
    case ImageSample::Float32: return OIIO::TypeDesc::FLOAT;
    }
    return OIIO::TypeDesc::UNKNOWN;
}

/** @p message on one line (the library's lines joined by "; "), with the system's reason for @p savedErrno when it
 *  is not in it already. */
std::string withReason(std::string message, int savedErrno)
{
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    for (std::size_t at = message.find('\n'); at != std::string::npos; at = message.find('\n', at))
        message.replace(at, 1, "; ");
    if (message.empty()) message = "OpenImageIO reported an error";
    if (savedErrno != 0) {
        const std::string reason = std::strerror(savedErrno);
        if (message.find(reason) == std::string::npos) message += " (" + reason + ")";
    }
    return message;
}

OIIO::ImageSpec specOf(const ImageHeader& header)
{
    OIIO::ImageSpec spec(header.width, header.height, header.channels, typeOf(header.sample));
    if (!header.channelNames.empty()) spec.channelnames = header.channelNames;
    spec.alpha_channel = header.alphaChannel;
    for (const auto& [name, value] : header.attributes) {
        if (const int* i = std::get_if<int>(&value)) spec.attribute(name, *i);
        else if (const float* f = std::get_if<float>(&value)) spec.attribute(name, *f);
        else spec.attribute(name, std::get<std::string>(value));
    }
    return spec;
}

/** Whether the PNG file at @p path ends with its IEND chunk: libpng does not report a short write (a full disk), and
 *  the file it leaves then stops short of that last chunk. */
bool pngComplete(const std::string& path)
{
    static constexpr unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return false;
    unsigned char tail[12] = {};
    const bool read = std::fseek(file, -12, SEEK_END) == 0 && std::fread(tail, 1, sizeof tail, file) == sizeof tail;
    std::fclose(file);
    return read && std::memcmp(tail, iend, sizeof tail) == 0;
}

class Writer final : public ImageFileWriter {
public:
    explicit Writer(std::unique_ptr<OIIO::ImageOutput> out) : m_out(std::move(out)) {}
    ~Writer() override
    {
        if (m_open) m_out->close(); // an abandoned file: close it and drop the errors (OIIO prints unread ones)
        (void)m_out->geterror();
    }
    bool open(const std::string& path, const ImageHeader& header) override
    {
        const OIIO::ImageSpec spec = specOf(header);
        errno = 0; // so that the reason kept on failure is this call's
        m_path = path;
        m_problem.clear();
        return track(m_open = m_out->open(path, spec));
    }
    bool writeScanline(int y, ImageSample sample, const void* samples) override
    {
        errno = 0;
        return track(m_out->write_scanline(y, 0, typeOf(sample), samples));
    }
    bool writeImage(ImageSample sample, const void* samples) override
    {
        errno = 0;
        return track(m_out->write_image(typeOf(sample), samples));
    }
    bool close() override
    {
        m_open = false;
        errno = 0;
        if (!track(m_out->close())) return false;
        if (std::strcmp(m_out->format_name(), "png") == 0 && !pngComplete(m_path)) {
            m_problem = "the file was cut short (is the disk full?)";
            return false;
        }
        return true;
    }
    std::string takeError() override
    {
        if (!m_problem.empty()) return std::exchange(m_problem, std::string());
        std::string message = withReason(m_out->geterror(), m_errno);
        m_errno = 0;
        return message;
    }

private:
    bool track(bool ok)
    {
        if (!ok) m_errno = errno;
        return ok;
    }

    std::unique_ptr<OIIO::ImageOutput> m_out;
    std::string m_path;
    std::string m_problem; ///< a failure found after the library's close (a PNG cut short)
    bool m_open = false;
    int m_errno = 0;
};

class Reader final : public ImageFileReader {
public:
    explicit Reader(std::unique_ptr<OIIO::ImageInput> in) : m_in(std::move(in))
    {
        const OIIO::ImageSpec& spec = m_in->spec();
        m_header.width = spec.width;
        m_header.height = spec.height;
        m_header.depth = spec.depth;
        m_header.channels = spec.nchannels;
        m_header.sampleName = spec.format.c_str();
        m_header.sampleKnown = true;
        if (spec.format == OIIO::TypeDesc::UINT8) m_header.sample = ImageSample::UInt8;
        else if (spec.format == OIIO::TypeDesc::UINT16) m_header.sample = ImageSample::UInt16;
        else if (spec.format == OIIO::TypeDesc::FLOAT) m_header.sample = ImageSample::Float32;
        else m_header.sampleKnown = false;
        m_header.channelNames = spec.channelnames;
        m_header.alphaChannel = spec.alpha_channel;
    }
    ~Reader() override { (void)m_in->geterror(); }
    const ImageHeader& header() const override { return m_header; }
    bool readImage(int firstChannel, int endChannel, ImageSample sample, void* samples) override
    {
        return m_in->read_image(0, 0, firstChannel, endChannel, typeOf(sample), samples);
    }
    std::string takeError() override { return withReason(m_in->geterror(), 0); }

private:
    std::unique_ptr<OIIO::ImageInput> m_in;
    ImageHeader m_header;
};

std::unique_ptr<ImageFileWriter> createWriter(const std::string& path, std::string* error)
{
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        if (error) *error = withReason(OIIO::geterror(), 0);
        return nullptr;
    }
    return std::make_unique<Writer>(std::move(out));
}

std::unique_ptr<ImageFileReader> openReader(const std::string& path, std::string* error)
{
    // The system's reason only where the file itself cannot be read: the library's own attempts (plugin
    // folders, other formats) leave errno set to reasons that are not the file's.
    if (std::FILE* file = std::fopen(path.c_str(), "rb")) {
        std::fclose(file);
    } else {
        if (error) *error = "cannot open " + path + ": " + std::strerror(errno);
        return nullptr;
    }
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        if (error) *error = withReason(OIIO::geterror(), 0);
        return nullptr;
    }
    return std::make_unique<Reader>(std::move(in));
}

std::string formatList()
{
    std::string formats;
    OIIO::getattribute("format_list", formats);
    return formats;
}

const ImageLibrary Library{&createWriter, &openReader, &formatList};

} // namespace

} // namespace stylos::core::image

extern "C" __attribute__((visibility("default"))) const stylos::core::image::ImageLibrary* stylos_image_library(int version)
{
    return version == stylos::core::image::ImageLibraryVersion ? &stylos::core::image::Library : nullptr;
}
