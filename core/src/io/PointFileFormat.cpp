#include "stylos/core/io/PointFileFormat.h"

#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/io/LasReader.h"
#include "stylos/core/io/ObjReader.h"
#include "stylos/core/io/PlyReader.h"
#include "stylos/core/io/TextReader.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

PointFormat formatFromMagic(const char* bytes, std::size_t n, const std::string& ext)
{
    auto startsWith = [&](const char* magic) {
        const std::size_t m = std::strlen(magic);
        return n >= m && std::memcmp(bytes, magic, m) == 0;
    };
    if (startsWith("ply\n") || startsWith("ply\r\n")) return PointFormat::Ply;
    if (startsWith("ASTM-E57")) return PointFormat::E57;
    if (startsWith("LASF")) {
        // LAZ keeps the LAS header but sets bit 7 (or 6) of the point data format byte (offset 104).
        if (ext == ".laz") return PointFormat::Laz;
        if (n > 104 && (static_cast<unsigned char>(bytes[104]) & 0xC0) != 0) return PointFormat::Laz;
        return PointFormat::Las;
    }
    return PointFormat::Unknown;
}

PointFormat formatFromExtension(const std::string& ext)
{
    if (ext == ".ply") return PointFormat::Ply;
    if (ext == ".las") return PointFormat::Las;
    if (ext == ".laz") return PointFormat::Laz;
    if (ext == ".e57") return PointFormat::E57;
    if (ext == ".obj") return PointFormat::Obj;
    if (ext == ".xyz" || ext == ".asc" || ext == ".csv" || ext == ".pts" || ext == ".txt" || ext == ".xyzn" ||
        ext == ".neu")
        return PointFormat::Text;
    return PointFormat::Unknown;
}

} // namespace

PointFormat detectPointFormat(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    auto file = BufferedFile::open(path, 4096);
    if (file) {
        const std::size_t n = file->fill(128);
        const PointFormat byMagic = formatFromMagic(file->data(), n, ext);
        if (byMagic != PointFormat::Unknown) return byMagic;
    }
    return formatFromExtension(ext);
}

Result<std::unique_ptr<PointReader>> openPointReader(const fs::path& path, const ReadOptions& options)
{
    auto file = BufferedFile::open(path, 4096);
    if (!file) return file.error();
    if (file->size() == 0) return Error::at(ErrorCode::Empty, path.string(), "", "the file is empty (0 bytes)");

    const std::string ext = lowerExtension(path);
    const std::size_t n = file->fill(128);
    PointFormat format = formatFromMagic(file->data(), n, ext);
    if (format == PointFormat::Unknown) {
        format = formatFromExtension(ext);
        // A file named .ply/.las that lacks the magic is corrupt, not another format.
        if (format == PointFormat::Ply)
            return Error::at(ErrorCode::Malformed, path.string(), "byte 0",
                             "not a PLY file: it does not start with the line \"ply\"");
        if (format == PointFormat::Las)
            return Error::at(ErrorCode::Malformed, path.string(), "byte 0",
                             "not a LAS file: it does not start with the signature \"LASF\"");
    }

    switch (format) {
    case PointFormat::Ply: return PlyReader::open(path);
    case PointFormat::Las: return LasReader::open(path);
    case PointFormat::Text: return TextReader::open(path, options);
    case PointFormat::Obj: return ObjReader::open(path);
    case PointFormat::Laz:
        return Error::at(ErrorCode::Unsupported, path.string(), "",
                         "LAZ (compressed LAS) is not read by Stylos; decompress it first, e.g. "
                         "`laszip -i IN.laz -o OUT.las` or `pdal translate IN.laz OUT.las`");
    case PointFormat::E57:
        return Error::at(ErrorCode::Unsupported, path.string(), "",
                         "E57 (ASTM scanner exchange format) is not read by Stylos; export the scans as PLY or "
                         "LAS, e.g. with CloudCompare (`CloudCompare -SILENT -O IN.e57 -C_EXPORT_FMT PLY "
                         "-SAVE_CLOUDS`) or `pdal translate IN.e57 OUT.las`");
    case PointFormat::Unknown: break;
    }
    return Error::at(ErrorCode::UnknownFormat, path.string(), "",
                     "unknown point file format (Stylos reads PLY, LAS, XYZ/ASC/CSV/PTS/TXT text and OBJ)");
}

} // namespace stylos::core::io
