#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/util/TextCase.h"

#include "FramedReader.h"

#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/io/E57Reader.h"
#include "stylos/core/io/LasReader.h"
#include "stylos/core/io/ObjReader.h"
#include "stylos/core/io/PlyReader.h"
#include "stylos/core/io/PtxReader.h"
#include "stylos/core/io/TextReader.h"
#include "stylos/core/octree/PackedOctree.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

constexpr PointFileExtension Extensions[] = {
    {"ply", PointFormat::Ply},  {"las", PointFormat::Las},  {"e57", PointFormat::E57},  {"ptx", PointFormat::Ptx},
    {"xyz", PointFormat::Text}, {"xyzn", PointFormat::Text}, {"asc", PointFormat::Text}, {"csv", PointFormat::Text},
    {"pts", PointFormat::Text}, {"txt", PointFormat::Text}, {"neu", PointFormat::Text}, {"obj", PointFormat::Obj},
    {"laz", PointFormat::Laz},
};


/** The readable formats' names for a message: "ply, las, ..., neu or obj". */
std::string readableExtensionsText()
{
    std::vector<std::string> names;
    for (const auto& e : Extensions)
        if (isReadable(e.format)) names.emplace_back(e.extension);
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("." + names[i]);
    return text;
}

PointFormat formatFromMagic(const char* bytes, std::size_t n, PointFormat byExtension)
{
    auto startsWith = [&](const char* magic) {
        const std::size_t m = std::strlen(magic);
        return n >= m && std::memcmp(bytes, magic, m) == 0;
    };
    if (startsWith("ply\n") || startsWith("ply\r\n")) return PointFormat::Ply;
    if (startsWith("ASTM-E57")) return PointFormat::E57;
    if (startsWith("LASF")) {
        // LAZ keeps the LAS header but sets bit 7 (or 6) of the point data format byte (offset 104).
        if (byExtension == PointFormat::Laz) return PointFormat::Laz;
        if (n > 104 && (static_cast<unsigned char>(bytes[104]) & 0xC0) != 0) return PointFormat::Laz;
        return PointFormat::Las;
    }
    return PointFormat::Unknown;
}

} // namespace

std::span<const PointFileExtension> pointFileExtensions()
{
    return Extensions;
}

bool isReadable(PointFormat format)
{
    return format == PointFormat::Ply || format == PointFormat::Las || format == PointFormat::E57 ||
           format == PointFormat::Ptx || format == PointFormat::Text || format == PointFormat::Obj;
}

std::vector<std::string> importableExtensions()
{
    std::vector<std::string> out;
    for (const auto& e : Extensions)
        if (isReadable(e.format)) out.emplace_back(e.extension);
    out.emplace_back(PoctExtension);
    return out;
}

PointFormat formatFromExtension(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    for (const auto& e : Extensions)
        if (ext.size() == e.extension.size() + 1 && std::string_view(ext).substr(1) == e.extension) return e.format;
    return PointFormat::Unknown;
}

bool hasPoctExtension(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    return ext.size() == PoctExtension.size() + 1 && std::string_view(ext).substr(1) == PoctExtension;
}

bool hasImportableExtension(const fs::path& path)
{
    return hasPoctExtension(path) || isReadable(formatFromExtension(path));
}

PointFormat detectPointFormat(const fs::path& path)
{
    const PointFormat byExtension = formatFromExtension(path);
    auto file = BufferedFile::open(path, 4096);
    if (file) {
        const std::size_t n = file->fill(128);
        const PointFormat byMagic = formatFromMagic(file->data(), n, byExtension);
        if (byMagic != PointFormat::Unknown) return byMagic;
    }
    return byExtension;
}

namespace {

Error poctIsNoPointFile(const fs::path& path)
{
    return Error::at(ErrorCode::UnknownFormat, path.string(), "",
                     "this is a packed octree (.poct), not a point file: it is already built. Open it in the "
                     "workbench, describe it with `stylos-cli info`, or give the scan it was built from");
}

Result<std::unique_ptr<PointReader>> openInFileFrame(const fs::path& path, const ReadOptions& options)
{
    auto file = BufferedFile::open(path, 4096);
    if (!file) return file.error();
    if (file->size() == 0) return Error::at(ErrorCode::Empty, path.string(), "", "the file is empty (0 bytes)");

    const PointFormat byExtension = formatFromExtension(path);
    const std::size_t n = file->fill(128);
    PointFormat format = formatFromMagic(file->data(), n, byExtension);
    if (format == PointFormat::Unknown &&
        octree::isPoctSignature(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(file->data()), n)))
        return poctIsNoPointFile(path); // whatever its extension
    if (format == PointFormat::Unknown) {
        format = byExtension;
        // A file named .ply/.las that lacks the magic is corrupt, not another format.
        if (format == PointFormat::Ply)
            return Error::at(ErrorCode::Malformed, path.string(), "byte 0",
                             "not a PLY file: it does not start with the line \"ply\"");
        if (format == PointFormat::Las)
            return Error::at(ErrorCode::Malformed, path.string(), "byte 0",
                             "not a LAS file: it does not start with the signature \"LASF\"");
        if (format == PointFormat::E57)
            return Error::at(ErrorCode::Malformed, path.string(), "byte 0",
                             "not an E57 file: it does not start with the signature \"ASTM-E57\"");
    }

    // Options that only some of the readable formats take are refused elsewhere rather than quietly ignored.
    const bool readable = format != PointFormat::Laz && format != PointFormat::Unknown;
    if (readable && options.scan && format != PointFormat::E57 && format != PointFormat::Ptx)
        return Error::at(ErrorCode::InvalidArgument, path.string(), "",
                         "a scan number applies to E57 and PTX files (several scans); this file has one");
    if (readable && !options.columns.empty() && format != PointFormat::Text)
        return Error::at(ErrorCode::InvalidArgument, path.string(), "",
                         "a column layout applies to text files (XYZ, PTS, TXT); this file names its own fields");
    switch (format) {
    case PointFormat::Ply: return PlyReader::open(path);
    case PointFormat::Las: return LasReader::open(path);
    case PointFormat::Text: return TextReader::open(path, options);
    case PointFormat::Obj: return ObjReader::open(path);
    case PointFormat::Laz:
        return Error::at(ErrorCode::Unsupported, path.string(), "",
                         "LAZ (compressed LAS) is not read by Stylos; decompress it first, e.g. "
                         "`laszip -i IN.laz -o OUT.las` or `pdal translate IN.laz OUT.las`");
    case PointFormat::E57: return E57Reader::open(path, options);
    case PointFormat::Ptx: return PtxReader::open(path, options);
    case PointFormat::Unknown: break;
    }
    if (hasPoctExtension(path)) return poctIsNoPointFile(path);
    return Error::at(ErrorCode::UnknownFormat, path.string(), "",
                     "unknown point file format (Stylos reads PLY, LAS, E57, PTX, text and OBJ files: " +
                         readableExtensionsText() + ")");
}

} // namespace

Result<std::unique_ptr<PointReader>> openPointReader(const fs::path& path, const ReadOptions& options)
{
    auto opened = openInFileFrame(path, options);
    if (!opened || options.frame.isIdentity()) return opened;
    return std::unique_ptr<PointReader>(std::make_unique<FramedReader>(std::move(opened).value(), options.frame));
}

} // namespace stylos::core::io
