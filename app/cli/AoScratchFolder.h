#pragma once
// A hidden folder beside an output file for `stylos-cli ao`'s intermediate octree, removed with all it
// holds when the object goes (on success, error or cancel alike).
#include "stylos/core/util/Result.h"

#include <filesystem>

namespace stylos::cli {

class AoScratchFolder {
public:
    AoScratchFolder() = default;
    AoScratchFolder(const AoScratchFolder&) = delete;
    AoScratchFolder& operator=(const AoScratchFolder&) = delete;
    ~AoScratchFolder();

    /** Creates ".NAME.ao-XXXXXX" in @p output's folder; WriteFailed naming that folder otherwise. */
    core::Status create(const std::filesystem::path& output);
    /** Empty until create() succeeded. */
    const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
};

} // namespace stylos::cli
