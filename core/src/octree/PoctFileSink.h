#pragma once
// Internal: the output side of the `.poct` writer. A temporary file beside the target (removed unless
// committed), positioned writes, and buffered section streams that write at their own offsets
// so that all sections can be filled in one pass over the levels.
#include "stylos/core/util/Hash64.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace stylos::core::octree::poct {

class TempFile {
public:
    /** Creates a fresh temporary file in @p target's folder. WriteFailed naming @p target. */
    static Result<TempFile> create(const std::filesystem::path& target);

    TempFile(TempFile&& other) noexcept;
    TempFile& operator=(TempFile&&) = delete;
    TempFile(const TempFile&) = delete;
    ~TempFile();

    /** Writes @p size bytes at @p offset. */
    Status writeAt(std::uint64_t offset, const void* data, std::size_t size);
    /** XXH64 of @p size bytes at @p offset, read back from the file (WriteFailed if they cannot be read). */
    Result<std::uint64_t> hashRange(std::uint64_t offset, std::uint64_t size) const;
    /** Sets the file's length. */
    Status resize(std::uint64_t size);
    /** Closes the file and renames it to the target (replacing any file there). */
    Status commit();

    Error failure(const std::string& problem) const;
    const std::filesystem::path& target() const { return m_target; }

private:
    TempFile() = default;
    std::filesystem::path m_target;
    std::filesystem::path m_temporary;
    int m_fd = -1;
    bool m_committed = false;
};

/** Appends to one section (or a part of one) at its offset through a buffer; the section is hashed from the
 *  file once complete (TempFile::hashRange). */
class SectionStream {
public:
    SectionStream(TempFile& file, std::uint64_t offset, std::size_t bufferBytes = std::size_t(1) << 20);

    Status append(const void* data, std::size_t size);
    /** Writes what is buffered. */
    Status flush();

private:
    TempFile* m_file;
    std::uint64_t m_offset;         ///< file offset of m_buffer[0]
    std::vector<std::uint8_t> m_buffer;
    std::size_t m_used = 0;
};

} // namespace stylos::core::octree::poct
