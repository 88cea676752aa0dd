#include "stylos/core/io/E57PagedFile.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

/** Pages read and checked at once. */
constexpr std::uint64_t kWindowPages = 256;

/** Slicing-by-8 tables for the reflected Castagnoli polynomial 0x82F63B78. */
struct Crc32cTables {
    std::array<std::array<std::uint32_t, 256>, 8> t{};
    Crc32cTables()
    {
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k) c = (c >> 1) ^ ((c & 1u) ? 0x82F63B78u : 0u);
            t[0][i] = c;
        }
        for (std::uint32_t i = 0; i < 256; ++i)
            for (std::size_t s = 1; s < 8; ++s) t[s][i] = (t[s - 1][i] >> 8) ^ t[0][t[s - 1][i] & 0xFFu];
    }
};

const Crc32cTables& tables()
{
    static const Crc32cTables instance;
    return instance;
}

std::string hex32(std::uint32_t v)
{
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", v);
    return text;
}

} // namespace

std::uint32_t crc32c(const void* data, std::size_t n)
{
    const auto& t = tables().t;
    const auto* p = static_cast<const unsigned char*>(data);
    std::uint32_t c = 0xFFFFFFFFu;
    while (n >= 8) {
        std::uint32_t lo, hi;
        std::memcpy(&lo, p, 4); // little-endian host (the readers assume it, see BufferedFile)
        std::memcpy(&hi, p + 4, 4);
        lo ^= c;
        c = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^
            t[3][hi & 0xFF] ^ t[2][(hi >> 8) & 0xFF] ^ t[1][(hi >> 16) & 0xFF] ^ t[0][hi >> 24];
        p += 8;
        n -= 8;
    }
    while (n-- > 0) c = (c >> 8) ^ t[0][(c ^ *p++) & 0xFFu];
    return c ^ 0xFFFFFFFFu;
}

Result<E57PagedFile> E57PagedFile::open(const fs::path& path)
{
    auto file = BufferedFile::open(path, kWindowPages * PageBytes);
    if (!file) return file.error();
    return E57PagedFile(path, std::move(file).value());
}

Error E57PagedFile::fail(ErrorCode code, std::uint64_t byte, const std::string& problem) const
{
    return Error::at(code, m_path.string(), "byte " + std::to_string(byte), problem);
}

std::uint64_t E57PagedFile::advance(std::uint64_t physical, std::uint64_t logicalBytes)
{
    const std::uint64_t logical = toLogical(physical) + logicalBytes;
    return logical / PayloadBytes * PageBytes + logical % PayloadBytes;
}

Status E57PagedFile::loadWindow(std::uint64_t page, const std::string& what)
{
    const std::uint64_t pagesInFile = size() / PageBytes;
    if (page >= pagesInFile)
        return fail(ErrorCode::Truncated, page * PageBytes,
                    "the file ends inside " + what + " (it has " + std::to_string(pagesInFile) + " whole pages)");
    const std::uint64_t count = std::min(kWindowPages, pagesInFile - page);
    const std::size_t bytes = count * PageBytes;
    m_windowPages = 0;
    if (!m_file.seek(page * PageBytes) || m_file.fill(bytes) < bytes) {
        if (m_file.ioError()) return fail(ErrorCode::Unreadable, page * PageBytes, "read error in " + what);
        return fail(ErrorCode::Truncated, page * PageBytes, "the file ends inside " + what);
    }
    m_window.assign(m_file.data(), m_file.data() + bytes);
    for (std::uint64_t k = 0; k < count; ++k) {
        const unsigned char* p = reinterpret_cast<const unsigned char*>(m_window.data()) + k * PageBytes;
        const std::uint32_t stored = (std::uint32_t(p[1020]) << 24) | (std::uint32_t(p[1021]) << 16) |
                                     (std::uint32_t(p[1022]) << 8) | std::uint32_t(p[1023]);
        const std::uint32_t computed = crc32c(p, PayloadBytes);
        ++m_pagesChecked;
        if (stored != computed)
            return Error::at(ErrorCode::Malformed, m_path.string(),
                             "page " + std::to_string(page + k) + " (byte " + std::to_string((page + k) * PageBytes) + ")",
                             "checksum mismatch (stored " + hex32(stored) + ", computed " + hex32(computed) +
                                 "): the page is damaged");
    }
    m_windowPage = page;
    m_windowPages = count;
    return {};
}

Status E57PagedFile::read(std::uint64_t physical, std::size_t n, void* out, const std::string& what)
{
    if (!isPayload(physical))
        return fail(ErrorCode::Malformed, physical, "the offset of " + what + " points into a page checksum");
    auto* dest = static_cast<char*>(out);
    while (n > 0) {
        const std::uint64_t page = physical / PageBytes;
        const std::uint64_t inPage = physical % PageBytes;
        if (page < m_windowPage || page >= m_windowPage + m_windowPages)
            if (auto s = loadWindow(page, what); !s) return s;
        const std::size_t take = static_cast<std::size_t>(std::min<std::uint64_t>(n, PayloadBytes - inPage));
        std::memcpy(dest, m_window.data() + (page - m_windowPage) * PageBytes + inPage, take);
        dest += take;
        n -= take;
        physical = (page + 1) * PageBytes;
    }
    return {};
}

} // namespace stylos::core::io
