#pragma once
/** @file
 * @brief A whole file mapped read-only into memory (POSIX mmap): its bytes are addressable without
 *        being read first; the operating system pages them in on access. RAII: the mapping ends with
 *        the object. Move-only.
 *        Failure modes (open): NotFound; Unreadable (a directory, no permission, mmap failure). A
 *        zero-byte file opens as an empty mapping (bytes() empty); callers decide whether that is
 *        an error. If the file is truncated by another process while mapped, access beyond the new end
 *        raises SIGBUS: files are written atomically (rename), so readers of Stylos files never see it.
 *        Thread-safety: the bytes are immutable; any number of threads may read them.
 */
#include "stylos/core/util/Result.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>

namespace stylos::core {

class MappedFile {
public:
    /**
     * @brief Maps @p path read-only. @p populate: read the whole file in at once (faster when every
     *        byte is going to be touched, e.g. to verify checksums).
     */
    static Result<MappedFile> open(const std::filesystem::path& path, bool populate = false);

    MappedFile() = default;
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&& other) noexcept;
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    ~MappedFile();

    /** @brief The file's bytes (empty for a zero-byte file). */
    std::span<const std::uint8_t> bytes() const { return {m_data, m_size}; }
    const std::uint8_t* data() const { return m_data; }
    std::size_t size() const { return m_size; }

private:
    const std::uint8_t* m_data = nullptr;
    std::size_t m_size = 0;
};

} // namespace stylos::core
