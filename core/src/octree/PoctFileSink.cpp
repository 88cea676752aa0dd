#include "PoctFileSink.h"

#include "stylos/core/util/AtomicTextFile.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <random>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace stylos::core::octree::poct {

namespace fs = std::filesystem;

namespace {

std::string systemError(int e)
{
    return std::strerror(e);
}

} // namespace

Result<TempFile> TempFile::create(const fs::path& target)
{
    TempFile f;
    f.m_target = target;
    std::random_device rd;
    std::mt19937_64 rng((std::uint64_t(rd()) << 32) ^ rd());
    for (int attempt = 0; attempt < 16; ++attempt) {
        f.m_temporary = target;
        f.m_temporary += ".tmp-" + std::to_string(rng() % 1000000000000ull);
        f.m_fd = ::open(f.m_temporary.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (f.m_fd >= 0) return f;
        if (errno != EEXIST) break;
    }
    return f.failure("cannot create the file: " + systemError(errno));
}

TempFile::TempFile(TempFile&& other) noexcept
    : m_target(std::move(other.m_target)), m_temporary(std::move(other.m_temporary)), m_fd(other.m_fd),
      m_committed(other.m_committed)
{
    other.m_fd = -1;
    other.m_committed = true; // the moved-from object owns nothing
}

TempFile::~TempFile()
{
    if (m_fd >= 0) ::close(m_fd);
    if (!m_committed) {
        std::error_code ec;
        fs::remove(m_temporary, ec);
    }
}

Error TempFile::failure(const std::string& problem) const
{
    return Error::at(ErrorCode::WriteFailed, m_target.string(), "", problem);
}

Status TempFile::writeAt(std::uint64_t offset, const void* data, std::size_t size)
{
    const auto* p = static_cast<const std::uint8_t*>(data);
    while (size > 0) {
        const ssize_t n = ::pwrite(m_fd, p, size, static_cast<off_t>(offset));
        if (n < 0) {
            if (errno == EINTR) continue;
            return failure("write error: " + systemError(errno));
        }
        if (n == 0) return failure("write error: no progress (disk full?)");
        p += n;
        size -= static_cast<std::size_t>(n);
        offset += static_cast<std::uint64_t>(n);
    }
    return {};
}

Result<std::uint64_t> TempFile::hashRange(std::uint64_t offset, std::uint64_t size) const
{
    Hash64 hash;
    std::vector<std::uint8_t> buffer(std::size_t(1) << 20);
    while (size > 0) {
        const std::size_t want = std::size_t(std::min<std::uint64_t>(size, buffer.size()));
        const ssize_t n = ::pread(m_fd, buffer.data(), want, static_cast<off_t>(offset));
        if (n < 0) {
            if (errno == EINTR) continue;
            return failure("cannot read back what was written: " + systemError(errno));
        }
        if (n == 0) return failure("cannot read back what was written: the file is shorter than written");
        hash.update(buffer.data(), std::size_t(n));
        offset += std::uint64_t(n);
        size -= std::uint64_t(n);
    }
    return hash.digest();
}

Status TempFile::resize(std::uint64_t size)
{
    if (::ftruncate(m_fd, static_cast<off_t>(size)) != 0)
        return failure("cannot set the file size: " + systemError(errno));
    return {};
}

Status TempFile::commit()
{
    const int fd = m_fd;
    m_fd = -1;
    if (::close(fd) != 0) return failure("write error on close: " + systemError(errno));
    keepModeOf(m_target, m_temporary); // a file replaced keeps its mode (the temporary file has the default one)
    std::error_code ec;
    fs::rename(m_temporary, m_target, ec);
    if (ec) return failure("cannot move the finished file into place: " + ec.message());
    m_committed = true;
    return {};
}

SectionStream::SectionStream(TempFile& file, std::uint64_t offset, std::size_t bufferBytes)
    : m_file(&file), m_offset(offset), m_buffer(bufferBytes)
{
}

Status SectionStream::append(const void* data, std::size_t size)
{
    const auto* p = static_cast<const std::uint8_t*>(data);
    while (size > 0) {
        if (m_used == 0 && size >= m_buffer.size()) {
            if (auto s = m_file->writeAt(m_offset, p, size); !s) return s;
            m_offset += size;
            return {};
        }
        const std::size_t take = std::min(size, m_buffer.size() - m_used);
        std::memcpy(m_buffer.data() + m_used, p, take);
        m_used += take;
        p += take;
        size -= take;
        if (m_used == m_buffer.size())
            if (auto s = flush(); !s) return s;
    }
    return {};
}

Status SectionStream::flush()
{
    if (m_used == 0) return {};
    if (auto s = m_file->writeAt(m_offset, m_buffer.data(), m_used); !s) return s;
    m_offset += m_used;
    m_used = 0;
    return {};
}

} // namespace stylos::core::octree::poct
