#pragma once
/** @file
 * @brief Recognising a point file's format (by its first bytes, then its extension) and opening the
 *        right streaming reader for it.
 */
#include "stylos/core/io/PointReader.h"

#include <filesystem>
#include <memory>
#include <string>

namespace stylos::core::io {

enum class PointFormat { Ply, Las, Laz, E57, Text, Obj, Unknown };

/** @brief Options that some readers take. */
struct ReadOptions {
    /**
     * Column layout of a text file, overriding detection: comma-separated names among
     * x y z nx ny nz r g b (or red green blue), i (intensity), or any other name for a scalar,
     * and "_" to skip a column. Example: "x,y,z,i,r,g,b". Empty: detected.
     */
    std::string columns;
};

/** Format from the magic bytes, then the extension. Does not validate the file. */
PointFormat detectPointFormat(const std::filesystem::path& path);

/**
 * @brief Opens a reader for @p path in whatever format it is. LAZ and E57 files are recognised and
 *        refused (ErrorCode::Unsupported) with a message saying what they are and how to convert them;
 *        an unrecognised file gives ErrorCode::UnknownFormat; an empty file ErrorCode::Empty.
 */
Result<std::unique_ptr<PointReader>> openPointReader(const std::filesystem::path& path,
                                                     const ReadOptions& options = {});

} // namespace stylos::core::io
