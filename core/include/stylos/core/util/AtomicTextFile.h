#pragma once
/** @file
 * @brief Writes a small text file (a JSON sidecar) atomically: to PATH.part beside it, then renamed over
 *        PATH, so a reader sees the old file or the new one, never half of one. On any failure the
 *        temporary is removed and PATH is left as it was. Units: none. Thread-safety: reentrant (two
 *        writers of the same path race like any rename). Failure modes: WriteFailed naming PATH and the
 *        system's reason.
 */
#include "stylos/core/util/Result.h"

#include <filesystem>
#include <string_view>

namespace stylos::core {

/** @brief Writes @p text to @p path atomically (see the file comment); a file replaced keeps its mode. */
Status writeTextFileAtomically(const std::filesystem::path& path, std::string_view text);

/** @brief Gives @p temporary the permissions of @p target when @p target is an existing regular file: called before a
 *         finished temporary file is renamed over it, so that a file replaced keeps its mode (chmod 600, 640…);
 *         nothing when there is none. Failures are ignored (the write itself does not depend on them). */
void keepModeOf(const std::filesystem::path& target, const std::filesystem::path& temporary);

} // namespace stylos::core
