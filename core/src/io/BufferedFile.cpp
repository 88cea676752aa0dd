#include "stylos/core/io/BufferedFile.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

namespace stylos::core::io {

namespace fs = std::filesystem;

Result<BufferedFile> BufferedFile::open(const fs::path& path, std::size_t bufferBytes)
{
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
        if (ec && ec != std::errc::no_such_file_or_directory)
            return Error::at(ErrorCode::Unreadable, path.string(), "", "cannot be read: " + ec.message());
        return Error::at(ErrorCode::NotFound, path.string(), "", "no such file");
    }
    if (fs::is_directory(status))
        return Error::at(ErrorCode::Unreadable, path.string(), "", "is a directory, not a file");

    BufferedFile f;
    errno = 0;
    f.m_file.reset(std::fopen(path.c_str(), "rb"));
    if (!f.m_file)
        return Error::at(ErrorCode::Unreadable, path.string(), "",
                         std::string("cannot be opened: ") + std::strerror(errno));
    const auto size = fs::file_size(path, ec);
    if (ec)
        return Error::at(ErrorCode::Unreadable, path.string(), "", "cannot get its size: " + ec.message());
    f.m_size = size;
    // No bigger than the file (a small file does not cost a 1 MiB buffer); fill() grows it when asked for more.
    f.m_buffer.resize(std::max<std::size_t>(std::min<std::uint64_t>(bufferBytes, size), 4096));
    return f;
}

std::size_t BufferedFile::fill(std::size_t n)
{
    if (m_end - m_pos >= n) return m_end - m_pos;
    // Move the unconsumed tail to the front, growing the buffer if one request needs more.
    const std::size_t tail = m_end - m_pos;
    if (m_pos > 0) {
        std::memmove(m_buffer.data(), m_buffer.data() + m_pos, tail);
        m_bufferOffset += m_pos;
        m_pos = 0;
        m_end = tail;
    }
    if (n > m_buffer.size()) m_buffer.resize(n);
    while (m_end < n) {
        const std::size_t got = std::fread(m_buffer.data() + m_end, 1, m_buffer.size() - m_end, m_file.get());
        if (got == 0) {
            if (std::ferror(m_file.get())) m_ioError = true;
            break;
        }
        m_end += got;
    }
    return m_end - m_pos;
}

bool BufferedFile::readExact(void* destination, std::size_t n)
{
    if (n <= m_buffer.size()) {
        if (fill(n) < n) return false;
        std::memcpy(destination, data(), n);
        consume(n);
        return true;
    }
    // Large reads bypass the buffer.
    if (offset() + n > m_size) return false;
    const std::size_t have = available();
    std::memcpy(destination, data(), have);
    consume(have);
    const std::size_t got = std::fread(static_cast<char*>(destination) + have, 1, n - have, m_file.get());
    m_bufferOffset += m_pos + got;
    m_pos = m_end = 0;
    if (got != n - have) {
        m_ioError = std::ferror(m_file.get()) != 0;
        return false;
    }
    return true;
}

bool BufferedFile::seek(std::uint64_t target)
{
    if (target > m_size) return false;
    if (target >= m_bufferOffset && target <= m_bufferOffset + m_end) {
        m_pos = static_cast<std::size_t>(target - m_bufferOffset);
        return true;
    }
    if (std::fseek(m_file.get(), static_cast<long>(target), SEEK_SET) != 0) {
        m_ioError = true;
        return false;
    }
    m_bufferOffset = target;
    m_pos = m_end = 0;
    return true;
}

bool BufferedFile::readLine(std::string_view& line)
{
    constexpr std::size_t maxLine = std::size_t(64) << 20;
    std::size_t scanned = 0;
    for (;;) {
        const char* begin = data();
        const std::size_t have = available();
        const void* nl = std::memchr(begin + scanned, '\n', have - scanned);
        if (nl) {
            std::size_t len = static_cast<const char*>(nl) - begin;
            consume(len + 1);
            m_lineTerminated = true;
            if (len > 0 && begin[len - 1] == '\r') --len;
            line = std::string_view(begin, len);
            return true;
        }
        scanned = have;
        if (have >= maxLine) {
            m_lineTooLong = true;
            consume(have);
            line = std::string_view(begin, have);
            return true;
        }
        const std::size_t want = have < m_buffer.size() ? m_buffer.size() : have * 2;
        const std::size_t got = fill(want);
        if (got == have) { // end of file
            if (have == 0) return false;
            begin = data(); // fill() may have moved the bytes
            consume(have);
            m_lineTerminated = false;
            std::size_t len = have;
            if (begin[len - 1] == '\r') --len;
            line = std::string_view(begin, len);
            return true;
        }
    }
}

} // namespace stylos::core::io
