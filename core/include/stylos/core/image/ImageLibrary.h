#pragma once
/** @file
 * @brief The image files library (OpenImageIO), loaded the first time an image is read or written.
 *
 * OpenImageIO brings about 260 shared libraries with it; linking them into every program cost each start of
 * `stylos-cli` and of the workbench 0.3-0.4 s before main() (the dynamic loader's relocations), on every command,
 * most of which never touch an image. So Stylos's use of it lives in a module, libstylos_oiio.so, that
 * imageLibrary() loads once, on demand, and never unloads. The interface is plain data: a header (size, channels,
 * sample type, named attributes) and writers and readers that report errors as text.
 *
 * The module is looked for beside the program (../lib/stylos/ from its directory: the installed tree, wherever its
 * prefix, and the build tree's bin/), then, for a program inside the build tree that compiled this code (tests
 * elsewhere in it), in that tree's lib/stylos; the
 * environment variable STYLOS_IMAGE_MODULE, when set, names the one file to load instead.
 *
 * Thread-safe. Failure modes: imageLibrary() returns Unsupported naming each place tried and the loader's reason
 * when the module is missing or of another version; the call is cheap to repeat (the failure is kept).
 */
#include "stylos/core/util/Result.h"

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace stylos::core::image {

/** Sample type of an image file's channels. */
enum class ImageSample { UInt8, UInt16, Float32 };

/** Bytes per sample of @p sample. */
constexpr std::size_t sampleBytes(ImageSample sample)
{
    return sample == ImageSample::UInt8 ? 1 : sample == ImageSample::UInt16 ? 2 : 4;
}

/** What a file holds, or is to hold: its size, channels and named attributes (OpenImageIO's names). */
struct ImageHeader {
    int width = 0;
    int height = 0;
    int depth = 1;          ///< > 1 for volume images (read only)
    int channels = 0;
    ImageSample sample = ImageSample::UInt8;
    std::string sampleName; ///< read: the file's sample type as the library names it ("uint8", "half", …)
    bool sampleKnown = true;///< read: false when the file's samples are none of ImageSample
    std::vector<std::string> channelNames; ///< empty: the library's defaults
    int alphaChannel = -1;
    std::vector<std::pair<std::string, std::variant<int, float, std::string>>> attributes;

    void set(std::string name, std::variant<int, float, std::string> value)
    {
        attributes.emplace_back(std::move(name), std::move(value));
    }
};

/** One file being written (created by ImageLibrary::createWriter, then open()). */
class ImageFileWriter {
public:
    virtual ~ImageFileWriter() = default;
    virtual bool open(const std::string& path, const ImageHeader& header) = 0;
    /** One row of header.width × header.channels samples of @p sample. */
    virtual bool writeScanline(int y, ImageSample sample, const void* samples) = 0;
    /** The whole image, rows top first. */
    virtual bool writeImage(ImageSample sample, const void* samples) = 0;
    virtual bool close() = 0;
    /** The last failure's message, with the system's reason (errno) when the library leaves it out; cleared. */
    virtual std::string takeError() = 0;
};

/** One file being read (ImageLibrary::openReader). */
class ImageFileReader {
public:
    virtual ~ImageFileReader() = default;
    virtual const ImageHeader& header() const = 0;
    /** Channels [@p firstChannel, @p endChannel) of the first subimage, converted to @p sample, into @p samples. */
    virtual bool readImage(int firstChannel, int endChannel, ImageSample sample, void* samples) = 0;
    virtual std::string takeError() = 0;
};

/** The module's entry points. */
struct ImageLibrary {
    /** A writer for @p path's format (by its extension); null with @p error when the library has none. */
    std::unique_ptr<ImageFileWriter> (*createWriter)(const std::string& path, std::string* error);
    /** The file at @p path opened for reading; null with @p error. */
    std::unique_ptr<ImageFileReader> (*openReader)(const std::string& path, std::string* error);
    /** The library's format names, comma-separated ("png,tiff,openexr,…"). */
    std::string (*formatList)();
};

/** Bumped whenever ImageLibrary or the classes above change: a module of another version is refused. */
inline constexpr int ImageLibraryVersion = 1;

/** The loaded module (loaded on the first call), or Unsupported saying why it could not be loaded. */
Result<const ImageLibrary*> imageLibrary();

/**
 * @brief The module's writer for @p path (its format by the extension), opened with @p header: the first
 *        steps of every image write (load the module, create, open). WriteFailed naming @p shownName (the
 *        file the user asked for, where @p path is its temporary), with the library's reason.
 */
Result<std::unique_ptr<ImageFileWriter>> openImageWriter(const std::string& path, const ImageHeader& header,
                                                         const std::string& shownName);

/**
 * @brief Writes a whole image — @p header's size, channels and sample, rows top first — to @p path (its
 *        format by the extension) through the module: create, open, write, close. WriteFailed naming
 *        @p shownName (the file the user asked for, where @p path is its temporary), with the module's or
 *        the library's reason. What was written of @p path on failure is the caller's to remove.
 */
Status writeWholeImage(const std::string& path, const ImageHeader& header, const void* samples,
                       const std::string& shownName);

} // namespace stylos::core::image
