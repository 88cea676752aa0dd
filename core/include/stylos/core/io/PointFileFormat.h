#pragma once
/** @file
 * @brief Recognising a point file's format (by its first bytes, then its extension) and opening the
 *        right streaming reader for it; the one list of point-file extensions that the readers, the
 *        workbench's file dialogs and drops, and stylos-cli use. Pure functions, thread-safe.
 */
#include "stylos/core/io/ImportFrame.h"
#include "stylos/core/io/PointReader.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::io {

enum class PointFormat { Ply, Las, Laz, E57, Ptx, Text, Obj, Unknown };

/** @brief A file name extension of point files (lower case, no dot) and the format it names. */
struct PointFileExtension {
    std::string_view extension;
    PointFormat format;
};

/**
 * @brief Every point-file extension Stylos knows, in the order the file dialogs list them: first those
 *        the readers open (ply las e57 ptx xyz xyzn asc csv pts txt neu obj), then laz, recognised so
 *        that openPointReader() can say how to convert it.
 */
std::span<const PointFileExtension> pointFileExtensions();

/** @brief Whether the readers open @p format (PLY, LAS, E57, PTX, text, OBJ). */
bool isReadable(PointFormat format);

/** @brief The extension of packed octree files (`.poct`), lower case, no dot. */
inline constexpr std::string_view PoctExtension = "poct";

/**
 * @brief What a user can import or give wherever a cloud is read: the readable point-file extensions,
 *        then "poct" (lower case, no dot).
 */
std::vector<std::string> importableExtensions();

/** @brief The format that @p path's extension names (any case), Unknown for any other (.poct included). */
PointFormat formatFromExtension(const std::filesystem::path& path);

/** @brief Whether @p path ends in .poct (any case). Says nothing of its content (see cloud::isPoctPath). */
bool hasPoctExtension(const std::filesystem::path& path);

/** @brief Whether @p path's extension is importable: a readable point format or .poct (any case). */
bool hasImportableExtension(const std::filesystem::path& path);

/** @brief Options that some readers take. */
struct ReadOptions {
    /**
     * Column layout of a text file, overriding detection: comma-separated names among
     * x y z nx ny nz r g b (or red green blue), i (intensity), or any other name for a scalar,
     * and "_" to skip a column. Example: "x,y,z,i,r,g,b". Empty: detected.
     */
    std::string columns;
    /**
     * Multi-scan files (E57, PTX): read only this scan (0-based, in file order, as `stylos-cli info`
     * numbers them). Absent: every scan, each with its pose applied, merged in the file's frame. A scan
     * number beyond the file's scans is ErrorCode::InvalidArgument (E57: at open; PTX: at the end of the file).
     */
    std::optional<std::size_t> scan;
    /**
     * The import frame (ImportFrame.h: offset, unit, up axis → Z up, metres), applied to every point and
     * normal as it is read, after the scan poses. The identity (the default) reads the file as it is.
     */
    ImportFrame frame;
};

/** Format from the magic bytes, then the extension. Does not validate the file. */
PointFormat detectPointFormat(const std::filesystem::path& path);

/**
 * @brief Opens a reader for @p path in whatever format it is. LAZ files are recognised and refused
 *        (ErrorCode::Unsupported) with a message saying what they are and how to convert them;
 *        an unrecognised file gives ErrorCode::UnknownFormat; an empty file ErrorCode::Empty.
 *        When @p options.frame is not the identity, the reader hands out its points in that frame (and
 *        its header's declared bounds too): every pipeline that reads points through here gets them so.
 */
Result<std::unique_ptr<PointReader>> openPointReader(const std::filesystem::path& path,
                                                     const ReadOptions& options = {});

} // namespace stylos::core::io
