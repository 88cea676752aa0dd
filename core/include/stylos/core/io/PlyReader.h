#pragma once
/** @file
 * @brief Streaming PLY reader: ascii, binary little- and big-endian; any element order (a `camera` or
 *        `range_grid` element before or after `vertex` is skipped); every scalar type; x y z, nx ny nz,
 *        red green blue (uchar, ushort or float) and every other vertex property kept as a named scalar;
 *        list properties skipped correctly. Counts are checked against the data: a short file is
 *        Truncated, extra data in a binary file Malformed.
 */
#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/io/PlyHeader.h"
#include "stylos/core/io/PointReader.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace stylos::core::io {

class PlyReader final : public PointReader {
public:
    static Result<std::unique_ptr<PointReader>> open(const std::filesystem::path& path);
    Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) override;
    std::uint64_t bytesConsumed() const override { return m_file.offset(); }

    const PlyHeader& plyHeader() const { return m_ply; }

private:
    PlyReader(std::filesystem::path path, BufferedFile file, PlyHeader ply);
    Status skipElement(const PlyElement& element);
    Status skipElementsBefore(std::size_t elementIndex);
    Status finishFile();
    Result<std::size_t> readBinary(PointBatch& batch, std::size_t n);
    Result<std::size_t> readAscii(PointBatch& batch, std::size_t n);
    std::string position() const;

    /** Where one vertex property goes. */
    enum class Target : std::uint8_t { None, X, Y, Z, NX, NY, NZ, R, G, B, Scalar };
    struct Field {
        PlyType type;
        Target target;
        std::uint32_t scalar;   ///< column for Target::Scalar
        std::uint32_t offset;   ///< byte offset in a binary record (fixed-size records only)
        float colorScale;       ///< to 0..255 for colour channels
    };
    void planFields();
    template <bool Swap> std::size_t decodeFixedRecords(const char* data, std::size_t records, PointBatch& batch);
    /** Record-by-record paths (ascii, vertex lists): puts one decoded value where @p f says. */
    void assign(const Field& f, double v, double* xyz, float* normal, double* color);
    bool storePoint(const double* xyz, const float* normal, const double* color, PointBatch& batch);

    BufferedFile m_file;
    PlyHeader m_ply;
    std::vector<Field> m_fields;     ///< one per vertex property, in order
    std::vector<double> m_scalarValues;
    std::uint64_t m_verticesDone = 0;
    std::uint64_t m_line = 0;        ///< ascii: number of the last line read
    bool m_atVertices = false;
    bool m_done = false;
};

} // namespace stylos::core::io
