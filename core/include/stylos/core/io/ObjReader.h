#pragma once
/** @file
 * @brief Streaming reader of the vertices of a Wavefront OBJ file, as a point cloud.
 *
 * Reads `v x y z [w]` and `v x y z r g b` (vertex colours, floats in [0, 1] scaled to 0–255, or
 * 0–255 integers when the first vertices show values above 1) and `vn nx ny nz`. Everything else (f,
 * vt, o, g, s, usemtl, mtllib, comments...) is skipped. Normals are used when the file has exactly as
 * many `vn` as `v` lines, the i-th normal going with the i-th vertex; otherwise they are ignored.
 *
 * open() makes one quick pass over the lines to count `v` and `vn`; read() then walks the vertices and
 * the normals in step with two cursors (two 1 MiB buffers), so memory stays flat whatever the file size.
 * Positions are double in the file's units. Vertices with a NaN or infinite coordinate are skipped and
 * counted in pointsSkipped().
 *
 * Failures (naming the file and "line N"): Malformed for a `v`/`vn` line with a field that is not a
 * number or the wrong number of fields, or a line over 64 MiB; Empty when there is no `v` line.
 * Not thread-safe: one reader per thread.
 */
#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/io/PointReader.h"

#include <filesystem>
#include <memory>
#include <string_view>

namespace stylos::core::io {

class ObjReader final : public PointReader {
public:
    /**
     * @brief Opens @p path and counts its vertices and normals. header().format is "obj";
     *        declaredPoints is the number of `v` lines (known from the counting pass).
     */
    static Result<std::unique_ptr<PointReader>> open(const std::filesystem::path& path);

    Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) override;
    std::uint64_t bytesConsumed() const override { return m_vertices.file.offset(); }

private:
    /** A file cursor that yields the lines of one kind ("v" or "vn"), with their line numbers. */
    struct Cursor {
        BufferedFile file;
        std::uint64_t line = 0;
    };
    enum class LineKind { Vertex, Normal, Other };

    ObjReader(std::filesystem::path path, BufferedFile file);
    Status countLines();
    /** Next line of @p kind from @p cursor, past its keyword; false at the end of the file. */
    Result<bool> next(Cursor& cursor, LineKind kind, std::string_view& fields) const;
    Error lineError(std::uint64_t line, const std::string& problem) const;

    Cursor m_vertices;
    Cursor m_normals; ///< used only when the file has as many normals as vertices
    std::uint64_t m_vertexCount = 0;
    std::uint64_t m_normalCount = 0;
    std::uint64_t m_firstNormalOffset = 0;
    std::uint64_t m_firstNormalLine = 0;
    std::size_t m_vertexFields = 3; ///< 3 (or 4 with w) without colours, 6 with colours
    bool m_unitColors = true;
};

} // namespace stylos::core::io
