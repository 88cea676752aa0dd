#pragma once
// The `.poct` side of stylos-cli: recognising an octree file, summarising it for `info`, and the names
// the command line gives to normal codes.
#include "stylos/core/octree/NormalCode.h"

#include <filesystem>
#include <optional>
#include <string>

namespace stylos::cli {

/** "octahedral16" or "paper15" (as `--normal-code` and the JSON spell them). */
const char* normalCodeName(core::octree::NormalCodeKind kind);
/** The inverse of normalCodeName(); nullopt for anything else. */
std::optional<core::octree::NormalCodeKind> normalCodeFromName(const std::string& name);

/** True when @p path ends in ".poct" (any case) or starts with the `.poct` signature. */
bool isPoctFile(const std::filesystem::path& path);

/**
 * `stylos-cli info FILE.poct`: opens and verifies the octree, prints its summary (text, or one JSON
 * object with @p json) on stdout. A file that does not open (bad signature, truncated, checksum) → the
 * reader's one-line message on stderr and exit 1.
 */
int runPoctInfo(const std::string& file, bool json);

} // namespace stylos::cli
