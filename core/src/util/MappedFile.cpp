#include "stylos/core/util/MappedFile.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stylos::core {

namespace fs = std::filesystem;

namespace {

/** Closes a file descriptor when leaving scope. */
struct FdGuard {
    int fd = -1;
    ~FdGuard()
    {
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

Result<MappedFile> MappedFile::open(const fs::path& path, bool populate)
{
    const std::string name = path.string();
    FdGuard fd;
    do {
        fd.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    } while (fd.fd < 0 && errno == EINTR);
    if (fd.fd < 0) {
        const int e = errno;
        if (e == ENOENT || e == ENOTDIR) return Error::at(ErrorCode::NotFound, name, "", "no such file");
        return Error::at(ErrorCode::Unreadable, name, "", std::string("cannot be opened: ") + std::strerror(e));
    }
    struct stat st {};
    if (::fstat(fd.fd, &st) != 0)
        return Error::at(ErrorCode::Unreadable, name, "", std::string("cannot get its size: ") + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) return Error::at(ErrorCode::Unreadable, name, "", "is a directory, not a file");
    if (!S_ISREG(st.st_mode)) return Error::at(ErrorCode::Unreadable, name, "", "is not a regular file");

    MappedFile file;
    if (st.st_size == 0) return file;
    if (static_cast<std::uint64_t>(st.st_size) > SIZE_MAX)
        return Error::at(ErrorCode::Unreadable, name, "", "is too large to map");
    const auto size = static_cast<std::size_t>(st.st_size);
    int flags = MAP_PRIVATE;
#ifdef MAP_POPULATE
    if (populate) flags |= MAP_POPULATE;
#endif
    void* p = ::mmap(nullptr, size, PROT_READ, flags, fd.fd, 0);
    if (p == MAP_FAILED)
        return Error::at(ErrorCode::Unreadable, name, "", std::string("cannot be mapped: ") + std::strerror(errno));
    file.m_data = static_cast<const std::uint8_t*>(p);
    file.m_size = size;
    return file;
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : m_data(std::exchange(other.m_data, nullptr)), m_size(std::exchange(other.m_size, 0))
{
}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept
{
    if (this != &other) {
        if (m_data) ::munmap(const_cast<std::uint8_t*>(m_data), m_size);
        m_data = std::exchange(other.m_data, nullptr);
        m_size = std::exchange(other.m_size, 0);
    }
    return *this;
}

MappedFile::~MappedFile()
{
    if (m_data) ::munmap(const_cast<std::uint8_t*>(m_data), m_size);
}

} // namespace stylos::core
