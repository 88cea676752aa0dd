#pragma once
/** @file
 * @brief Streaming binary little-endian PLY writer: positions (double by default), optional normals
 *        (float), colours (uchar) and named scalar properties. The point count need not be known in
 *        advance. The file is written to a temporary name beside the target and renamed on finish(), so
 *        a failure or a crash never leaves a half-written file. Not thread-safe.
 */
#include "stylos/core/io/PlyHeader.h"
#include "stylos/core/io/PointBatch.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace stylos::core::io {

/** The PLY value types, as the reader knows them. */
using PlyScalarType = PlyType;

struct PlyWriterOptions {
    PlyScalarType positionType = PlyScalarType::Float64; ///< Float32 or Float64
    std::vector<PlyScalarType> scalarTypes; ///< one per schema scalar; missing entries are Float32
    std::vector<std::string> comments;      ///< "comment" lines in the header (no newlines)
};

class PlyWriter {
public:
    /** Starts writing @p path (through a temporary file). Errors: WriteFailed, InvalidArgument. */
    static Result<PlyWriter> create(const std::filesystem::path& path, const PointSchema& schema,
                                    PlyWriterOptions options = {});
    PlyWriter(PlyWriter&&) noexcept;
    PlyWriter& operator=(PlyWriter&&) = delete;
    ~PlyWriter(); ///< removes the temporary file unless finish() succeeded

    /** Appends a batch shaped for the schema given to create(). */
    Status write(const PointBatch& batch);
    /** Writes the final count, flushes and renames the temporary file onto the target. */
    Status finish();

    std::uint64_t pointsWritten() const { return m_count; }

private:
    PlyWriter() = default;
    Status writeHeader();
    Error failure(const std::string& problem) const;

    struct Closer { void operator()(std::FILE* f) const { if (f) std::fclose(f); } };
    std::unique_ptr<std::FILE, Closer> m_file;
    std::filesystem::path m_target;
    std::filesystem::path m_temporary;
    PointSchema m_schema;
    PlyWriterOptions m_options;
    std::vector<unsigned char> m_record;   ///< one encoded point
    std::vector<unsigned char> m_buffer;   ///< encoded batch
    std::uint64_t m_count = 0;
    long m_countFieldOffset = 0;
    bool m_finished = false;
};

} // namespace stylos::core::io
