#pragma once
// The reading options shared by the commands that read a point file: --columns LAYOUT (text files) and
// --scan N (one scan of an E57 or PTX file), gathered into core::io::ReadOptions.
#include "CommandLine.h"

#include "stylos/core/io/PointFileFormat.h"

#include <string>

namespace stylos::cli {

/** The --scan option spec, for a command's list (beside its --columns). */
OptionSpec scanOption();

/** Fills @p read from --columns and --scan; false with @p problem set when --scan is not a number ≥ 0. */
bool parseReadOptions(const CommandLine& cl, core::io::ReadOptions& read, std::string& problem);

} // namespace stylos::cli
