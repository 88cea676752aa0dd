#pragma once
/** @file
 * @brief A hidden folder beside an output for intermediate files (`stylos-cli ao`'s octree, the demo's
 *        scans), removed with all it holds when the object goes (on success, error or cancel alike).
 *        Thread-safety: a value owned by one thread. Failure: WriteFailed naming the parent folder.
 */
#include "stylos/core/util/Result.h"

#include <filesystem>

namespace stylos::core {

class ScratchFolder {
public:
    ScratchFolder() = default;
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    ~ScratchFolder();

    /** Creates ".NAME.TAG-XXXXXX" in @p output's folder (NAME its file name); WriteFailed naming that
     *  folder otherwise. */
    Status create(const std::filesystem::path& output, const std::string& tag);
    /** Empty until create() succeeded. */
    const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
};

} // namespace stylos::core
