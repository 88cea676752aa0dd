#pragma once
// Internal: the temporary file an image is written to before it is renamed over its target.
#include "stylos/core/util/Result.h"

#include <filesystem>

namespace stylos::core::image {

/**
 * @brief A fresh temporary name ".NAME.tmp-XXXXXXXXXXXXXXXX.EXT" beside a target (same folder, same
 *        extension so that OpenImageIO picks the target's format). The file itself is created by
 *        whoever writes to path(); the destructor removes it unless commit() moved it into place.
 *
 * Thread-safety: one object per writer. Failure modes: beside() gives WriteFailed naming the target
 * when its folder is missing or not a folder, or the target is a folder; commit() gives WriteFailed
 * when the rename fails (the temporary is then removed, the target untouched).
 */
class TemporaryImageFile {
public:
    static Result<TemporaryImageFile> beside(const std::filesystem::path& target);

    TemporaryImageFile(TemporaryImageFile&& other) noexcept;
    TemporaryImageFile& operator=(TemporaryImageFile&&) = delete;
    TemporaryImageFile(const TemporaryImageFile&) = delete;
    TemporaryImageFile& operator=(const TemporaryImageFile&) = delete;
    ~TemporaryImageFile();

    const std::filesystem::path& path() const { return m_temporary; }
    const std::filesystem::path& target() const { return m_target; }

    /** Renames the temporary over the target (atomic on POSIX). */
    Status commit();

private:
    TemporaryImageFile(std::filesystem::path target, std::filesystem::path temporary);

    std::filesystem::path m_target;
    std::filesystem::path m_temporary;
    bool m_active = true; ///< false once committed or moved from
};

} // namespace stylos::core::image
