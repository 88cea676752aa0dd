#pragma once
/** @file
 * @brief Streaming reader for uncompressed LAS 1.0–1.4, point data formats 0–10.
 *
 *        Positions: X × scale + offset in double, in the file's world units (usually metres).
 *        Colours (formats 2, 3, 5, 7, 8, 10): the spec stores 16-bit values, made 8-bit by `value >> 8`;
 *        but many writers store 8-bit values (0–255) in the 16-bit fields. The rule, fixed at open so
 *        that every batch of a file is decoded alike: up to 1 MiB of records, taken as 16 windows
 *        spread evenly over the point data (the whole data when smaller), is sampled; if every
 *        sampled component is ≤ 255 the file is taken as 8-bit and values pass unchanged (a later
 *        value above 255 is clamped to 255), otherwise as 16-bit (`>> 8`). A genuinely 16-bit file
 *        would only be misjudged if all its sampled colours were darker than 1/256 of full scale.
 *        Scalars (double columns, see lasScalarFields()): intensity, return_number, number_of_returns,
 *        classification, scan_angle (degrees: the rank for formats 0–5, 0.006° units for 6–10),
 *        user_data, point_source_id, gps_time (formats 1, 3–10), nir (formats 8, 10), then the extra bytes
 *        that an Extra Bytes VLR describes (lasExtraBytesFields; names made unique, never x y z nx ny nz or a
 *        colour's). Other VLRs, undescribed extra bytes, wave packet descriptors (formats 4, 5, 9, 10),
 *        waveform data and EVLRs are skipped. Points whose position overflows to infinity (an absurd
 *        scale) are skipped and counted.
 *
 *        Failures: open() returns the errors of LasHeader::parse() (Malformed, Truncated, Unsupported
 *        for another version, an unknown point format or LAZ) and those of BufferedFile::open()
 *        (NotFound, Unreadable), or Empty for a 0-byte file; every header field is validated and the data size checked against
 *        count × record length at open, so read() fails only when the file shrinks or an I/O error
 *        occurs (Truncated, Unreadable). Messages are "FILE: byte N: problem".
 *        Decodes straight out of a 1 MiB buffer: flat memory, no per-point allocation. Not thread-safe.
 */
#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/io/LasHeader.h"
#include "stylos/core/io/PointReader.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace stylos::core::io {

class LasReader final : public PointReader {
public:
    static Result<std::unique_ptr<PointReader>> open(const std::filesystem::path& path);
    Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) override;
    std::uint64_t bytesConsumed() const override { return m_file.offset(); }

    const LasHeader& lasHeader() const { return m_las; }
    /** True when the colours were judged 8-bit (passed as is), false when 16-bit (`>> 8`). */
    bool colorsStored8Bit() const { return m_colors8Bit; }

private:
    LasReader(std::filesystem::path path, BufferedFile file, LasHeader las, LasPointLayout layout,
              std::vector<LasScalarField> extraBytes);
    bool sampleColorsAre8Bit() const;
    /** Decodes @p count records at @p records into the batch's points [first, first + count). */
    void decode(const char* records, std::size_t count, PointBatch& batch, std::size_t first) const;
    /** Moves the points with a finite position among [first, first + count) to the front; returns how many. */
    static std::size_t dropNonFinite(PointBatch& batch, std::size_t first, std::size_t count);

    BufferedFile m_file;
    LasHeader m_las;
    LasPointLayout m_layout;
    std::vector<LasScalarField> m_fields;
    std::uint64_t m_recordsLeft = 0;
    bool m_colors8Bit = false;
    bool m_positionsAlwaysFinite = true; ///< no int32 × scale + offset can overflow
};

} // namespace stylos::core::io
