#pragma once
/** @file
 * @brief Private to core/normals: the temporary tile files of the tiled normal estimation. Each tile has
 *        an "own" file (fixed-size raw records: x y z as doubles, then r g b bytes if any, then the
 *        scalar columns as doubles, native byte order) and a "halo" file (x y z doubles, then the point's scan
 *        id as a double when the estimation keeps scans apart). Appends are
 *        buffered in memory per tile and written by opening the file, appending and closing it, so any
 *        number of tiles uses one file descriptor at a time. The directory and everything in it are
 *        removed by the destructor, whatever happened. Not thread-safe.
 */
#include "stylos/core/util/Result.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

namespace stylos::core::normals::detail {

class TileSpool {
public:
    enum class Part { Own, Halo };

    /**
     * @brief Creates a fresh directory ".NAME.normals-XXXXXXXX" in @p parent (or, if that fails, in
     *        std::filesystem::temp_directory_path()). A halo record is @p haloValues doubles (3: x y z; 4:
     *        and the scan id). @p bufferBytes is the buffer per tile and part.
     *        Errors: WriteFailed naming the directory.
     */
    static Result<std::unique_ptr<TileSpool>> create(const std::filesystem::path& parent, const std::string& name,
                                                     std::size_t tiles, std::size_t ownRecordBytes,
                                                     std::size_t haloValues, std::size_t bufferBytes);
    ~TileSpool(); ///< removes the directory and its files
    TileSpool(const TileSpool&) = delete;
    TileSpool& operator=(const TileSpool&) = delete;

    const std::filesystem::path& directory() const { return m_directory; }

    /** Appends one own record (ownRecordBytes bytes) to @p tile. Errors: WriteFailed. */
    Status appendOwn(std::uint32_t tile, const unsigned char* record);
    /** Appends a halo record (haloValues doubles: x y z [scan]) to @p tile. Errors: WriteFailed. */
    Status appendHalo(std::uint32_t tile, const double* values);
    /** Writes every buffer out and frees the buffers. Errors: WriteFailed. */
    Status flush();

    std::uint64_t count(std::uint32_t tile, Part part) const;

    /**
     * @brief Reads a part back in chunks: @p consume gets (records, record count). Errors: Unreadable or
     *        Truncated naming the file (it changed under us).
     */
    Status read(std::uint32_t tile, Part part,
                const std::function<void(const unsigned char*, std::size_t)>& consume) const;
    /** Deletes a tile's files once used (frees disk early). */
    void discard(std::uint32_t tile);

private:
    TileSpool() = default;
    std::filesystem::path file(std::uint32_t tile, Part part) const;
    Status flushOne(std::uint32_t tile, Part part);

    std::filesystem::path m_directory;
    std::size_t m_ownRecordBytes = 0;
    std::size_t m_haloRecordBytes = 3 * sizeof(double);
    std::size_t m_bufferBytes = 0;
    std::vector<std::vector<unsigned char>> m_buffers; ///< 2 per tile: own, halo
    std::vector<std::uint64_t> m_counts;               ///< 2 per tile
};

} // namespace stylos::core::normals::detail
