#pragma once
// The reading options shared by the commands that read a point file: --columns LAYOUT (text files),
// --scan N (one scan of an E57 or PTX file) and the import frame --up AXIS, --unit UNIT, --offset X,Y,Z
// (core/io/ImportFrame.h), gathered into core::io::ReadOptions.
#include "CommandLine.h"

#include "stylos/core/io/PointFileFormat.h"

#include <string>
#include <vector>

namespace stylos::cli {

/** The --scan option spec, for a command's list (beside its --columns). */
OptionSpec scanOption();
/** The --up, --unit and --offset option specs, to append to a command's list. */
std::vector<OptionSpec> frameOptions();
/** @p options with frameOptions() appended. */
std::vector<OptionSpec> withFrameOptions(std::vector<OptionSpec> options);

/**
 * Fills @p read from --columns, --scan, --up, --unit and --offset; false with @p problem set when --scan
 * is not a number ≥ 0, --up not one of +X -X +Y -Y +Z -Z (or x, y, z), --unit not mm, cm or m, or
 * --offset not three finite numbers. Each message names the option and the value given.
 */
bool parseReadOptions(const CommandLine& cl, core::io::ReadOptions& read, std::string& problem);

/** Whether any of --up, --unit, --offset was given (they apply to point files, not to a .poct). */
bool hasFrameOptions(const CommandLine& cl);

} // namespace stylos::cli
