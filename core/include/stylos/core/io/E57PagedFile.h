#pragma once
/** @file
 * @brief An E57 file's physical pages (ASTM E2807 §7): 1024 bytes each, 1020 bytes of payload then the
 *        CRC-32C of those 1020 bytes, stored big-endian. Offsets in an E57 file are physical (they count
 *        the checksums); the data they point to is logical (the payloads run on across pages).
 *        Every page is checked as it is read; a page whose checksum fails is an error naming the page and
 *        its byte offset. Reads go through one window of pages (256 KiB): memory stays flat.
 *        Not thread-safe.
 */
#include "stylos/core/io/BufferedFile.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace stylos::core::io {

/** @brief CRC-32C (Castagnoli, reflected, initial and final XOR 0xFFFFFFFF) of @p n bytes. */
std::uint32_t crc32c(const void* data, std::size_t n);

class E57PagedFile {
public:
    static constexpr std::uint64_t PageBytes = 1024;
    static constexpr std::uint64_t PayloadBytes = 1020;

    /** Opens @p path. Errors: those of BufferedFile::open(). */
    static Result<E57PagedFile> open(const std::filesystem::path& path);

    std::uint64_t size() const { return m_file.size(); }
    const std::filesystem::path& path() const { return m_path; }

    /**
     * @brief Copies @p n logical bytes starting at physical offset @p physical into @p out, checking the
     *        checksum of every page it touches. Errors: Malformed for an offset inside a checksum or a
     *        page whose checksum fails ("page P (byte B): ..."), Truncated when the file ends first,
     *        Unreadable on an I/O error. @p what names the data for the message ("the XML section").
     */
    Status read(std::uint64_t physical, std::size_t n, void* out, const std::string& what);

    /** The physical offset @p logicalBytes of payload after @p physical (checksums skipped). */
    static std::uint64_t advance(std::uint64_t physical, std::uint64_t logicalBytes);
    /** Logical offset (payload bytes before) of physical offset @p physical, which must not be in a checksum. */
    static std::uint64_t toLogical(std::uint64_t physical) { return physical / PageBytes * PayloadBytes + physical % PageBytes; }
    /** Whether @p physical points into a page's payload (not its checksum). */
    static bool isPayload(std::uint64_t physical) { return physical % PageBytes < PayloadBytes; }

    /** Pages checked so far (a page read twice counts twice). */
    std::uint64_t pagesChecked() const { return m_pagesChecked; }

private:
    E57PagedFile(std::filesystem::path path, BufferedFile file) : m_path(std::move(path)), m_file(std::move(file)) {}
    /** Loads and checks the window holding page @p page. */
    Status loadWindow(std::uint64_t page, const std::string& what);
    Error fail(ErrorCode code, std::uint64_t byte, const std::string& problem) const;

    std::filesystem::path m_path;
    BufferedFile m_file;
    std::vector<char> m_window;       ///< whole checked pages
    std::uint64_t m_windowPage = 0;   ///< first page in m_window
    std::uint64_t m_windowPages = 0;  ///< pages in m_window
    std::uint64_t m_pagesChecked = 0;
};

} // namespace stylos::core::io
