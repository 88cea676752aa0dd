#pragma once
/** @file
 * @brief A read-only file with one fixed buffer (1 MiB by default): the readers parse straight out of
 *        the buffer, so memory stays flat whatever the file size. Tracks the file offset of every byte
 *        for error messages. Not thread-safe.
 */
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

namespace stylos::core::io {

class BufferedFile {
public:
    /** Opens @p path with a buffer of @p bufferBytes, or of the file's size when smaller (at least 4 KiB).
     *  Errors: NotFound, Unreadable (a directory, no permission, I/O error). */
    static Result<BufferedFile> open(const std::filesystem::path& path,
                                     std::size_t bufferBytes = std::size_t(1) << 20);

    std::uint64_t size() const { return m_size; }
    /** File offset of the next unconsumed byte. */
    std::uint64_t offset() const { return m_bufferOffset + m_pos; }
    bool atEnd() { return fill(1) == 0; }
    /** True once a read from the operating system failed (not merely the end of the file). */
    bool ioError() const { return m_ioError; }

    /** Makes at least @p n bytes contiguous from data(); returns how many are (fewer only at the end). */
    std::size_t fill(std::size_t n);
    const char* data() const { return m_buffer.data() + m_pos; }
    std::size_t available() const { return m_end - m_pos; }
    void consume(std::size_t n) { m_pos += n; }

    /** Copies exactly @p n bytes; false (and nothing consumed) if the file ends first. */
    bool readExact(void* destination, std::size_t n);
    /** Moves to absolute offset @p offset; false beyond the end of the file. */
    bool seek(std::uint64_t offset);
    /** Skips @p n bytes; false if the file ends first. */
    bool skip(std::uint64_t n) { return seek(offset() + n); }

    /**
     * @brief The next line without its "\n" or "\r\n"; false at the end of the file. The view stays
     *        valid until the next call. A line longer than the buffer grows the buffer (up to 64 MiB,
     *        beyond which the line is returned cut and lineTooLong() turns true).
     */
    bool readLine(std::string_view& line);
    bool lineTooLong() const { return m_lineTooLong; }
    /** False when the last line returned ended at the end of the file without a line break. */
    bool lineTerminated() const { return m_lineTerminated; }

private:
    struct Closer { void operator()(std::FILE* f) const { if (f) std::fclose(f); } };
    std::unique_ptr<std::FILE, Closer> m_file;
    std::vector<char> m_buffer;
    std::uint64_t m_size = 0;
    std::uint64_t m_bufferOffset = 0; ///< file offset of m_buffer[0]
    std::size_t m_pos = 0;
    std::size_t m_end = 0;
    bool m_ioError = false;
    bool m_lineTooLong = false;
    bool m_lineTerminated = true;
};

} // namespace stylos::core::io
