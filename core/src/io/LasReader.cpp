#include "stylos/core/io/LasReader.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

/** Records are decoded column by column over chunks of this size, which stay in the L1/L2 cache. */
constexpr std::size_t kChunkBytes = std::size_t(32) << 10;
/** Colour depth sampling: this many windows of this many bytes spread over the point data. */
constexpr std::uint64_t kSampleWindows = 16;
constexpr std::size_t kSampleWindowBytes = std::size_t(64) << 10;

std::string byteAt(std::uint64_t offset) { return "byte " + std::to_string(offset); }

} // namespace

LasReader::LasReader(fs::path path, BufferedFile file, LasHeader las, LasPointLayout layout,
                     std::vector<LasScalarField> extraBytes)
    : PointReader(std::move(path), file.size()),
      m_file(std::move(file)),
      m_las(std::move(las)),
      m_layout(layout),
      m_fields(lasScalarFields(layout)),
      m_recordsLeft(m_las.pointCount)
{
    // Each extra column's name once, and never a name the points' other properties take (a normal estimated for
    // them, "nx", would appear twice in the file it is written to).
    const auto taken = [this](const std::string& name) {
        static const char* kReserved[] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha"};
        for (const char* r : kReserved)
            if (name == r) return true;
        return std::any_of(m_fields.begin(), m_fields.end(), [&name](const LasScalarField& g) { return g.name == name; });
    };
    for (LasScalarField& f : extraBytes) {
        const std::string base = f.name;
        for (int n = 2; taken(f.name); ++n) f.name = base + "_" + std::to_string(n);
        m_fields.push_back(std::move(f));
    }
    m_header.format = m_las.formatName();
    m_header.declaredPoints = m_las.pointCount;
    m_header.declaredBounds = m_las.bounds;
    m_header.schema.hasColors = m_layout.rgb >= 0;
    for (const auto& field : m_fields) m_header.schema.scalarNames.push_back(field.name);
    // |int32 × scale + offset| ≤ 2^31 |scale| + |offset|; rounding is monotone, so a finite bound
    // means no point can overflow and the per-point check is skipped.
    for (std::size_t i = 0; i < 3; ++i)
        m_positionsAlwaysFinite = m_positionsAlwaysFinite &&
                                  std::isfinite(std::abs(m_las.scale[i]) * 2147483648.0 + std::abs(m_las.offset[i]));
    m_colors8Bit = sampleColorsAre8Bit();
}

Result<std::unique_ptr<PointReader>> LasReader::open(const fs::path& path)
{
    auto file = BufferedFile::open(path);
    if (!file) return file.error();
    if (file->size() == 0) return Error::at(ErrorCode::Empty, path.string(), "", "the file is empty (0 bytes)");
    const std::size_t n = file->fill(512);
    if (file->ioError())
        return Error::at(ErrorCode::Unreadable, path.string(), "byte 0", "read error in the LAS header");
    auto las = LasHeader::parse(file->data(), n, file->size(), path.string());
    if (!las) return las.error();
    const auto layout = LasPointLayout::forFormat(las->pointFormat);
    assert(layout && "LasReader::open(): LasHeader::parse() accepted an unknown point format");
    // The Extra Bytes VLR's descriptors, if any (the VLRs lie between the header and the point data).
    std::vector<LasScalarField> extra;
    if (las->recordLength > layout->standardLength && las->offsetToPointData > las->headerSize &&
        las->offsetToPointData - las->headerSize <= (std::uint32_t(1) << 20) && file->seek(las->headerSize)) {
        const std::size_t span = las->offsetToPointData - las->headerSize;
        if (file->fill(span) >= span) {
            const char* vlrs = file->data();
            constexpr std::size_t kVlrHeader = 54;
            for (std::size_t at = 0; at + kVlrHeader <= span;) {
                const char* v = vlrs + at;
                const std::string user(v + 2, std::find(v + 2, v + 18, '\0'));
                const auto record = loadLittleEndian<std::uint16_t>(v + 18);
                const std::size_t length = loadLittleEndian<std::uint16_t>(v + 20);
                if (at + kVlrHeader + length > span) break;
                if (user == "LASF_Spec" && record == 4)
                    extra = lasExtraBytesFields(v + kVlrHeader, length, layout->standardLength, las->recordLength);
                at += kVlrHeader + length;
            }
        }
    }
    // Skips the VLRs (and any user data after the header) in one move.
    if (!file->seek(las->offsetToPointData))
        return Error::at(ErrorCode::Unreadable, path.string(), byteAt(las->offsetToPointData),
                         "cannot seek to the point data");
    std::unique_ptr<PointReader> reader(
        new LasReader(path, std::move(file).value(), std::move(las).value(), *layout, std::move(extra)));
    return reader;
}

bool LasReader::sampleColorsAre8Bit() const
{
    if (m_layout.rgb < 0 || m_las.pointCount == 0) return false;
    auto sampler = BufferedFile::open(m_path, kSampleWindowBytes);
    if (!sampler) return false;
    const std::uint64_t count = m_las.pointCount;
    const std::size_t length = m_las.recordLength;
    const auto n = static_cast<std::size_t>(
        std::min<std::uint64_t>(std::max<std::size_t>(1, kSampleWindowBytes / length), count));
    // The first window starts the data, the last one ends it. count × length ≤ file size and
    // length ≥ 20, so (count - n) × kSampleWindows cannot overflow.
    for (std::uint64_t w = 0; w < kSampleWindows; ++w) {
        const std::uint64_t first = (count - n) * w / (kSampleWindows - 1);
        if (!sampler->seek(m_las.offsetToPointData + first * length)) return false;
        if (sampler->fill(n * length) < n * length) return false;
        const char* rgb = sampler->data() + m_layout.rgb;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < 3; ++k)
                if (loadLittleEndian<std::uint16_t>(rgb + i * length + 2 * k) > 255) return false;
        if (n == count) break; // one window held every record
    }
    return true;
}

Result<std::size_t> LasReader::read(PointBatch& batch, std::size_t maxPoints)
{
    assert(maxPoints > 0 && "LasReader::read(): maxPoints must be positive");
    const auto target = static_cast<std::size_t>(std::min<std::uint64_t>(std::max<std::size_t>(maxPoints, 1),
                                                                         m_recordsLeft));
    batch.reset(m_header.schema, target);
    batch.positions.resize(3 * target);
    if (m_header.schema.hasColors) batch.colors.resize(3 * target);
    for (auto& column : batch.scalars) column.resize(target);

    const std::size_t length = m_las.recordLength;
    const std::size_t perChunk = std::max<std::size_t>(1, kChunkBytes / length);
    std::size_t out = 0;
    while (out < target && m_recordsLeft > 0) {
        const auto m = static_cast<std::size_t>(
            std::min<std::uint64_t>(std::min(perChunk, target - out), m_recordsLeft));
        const std::size_t bytes = m * length;
        if (m_file.fill(bytes) < bytes) {
            const std::uint64_t end = m_file.offset() + m_file.available();
            if (m_file.ioError()) return fail(ErrorCode::Unreadable, byteAt(end), "read error in the point data");
            return fail(ErrorCode::Truncated, byteAt(end),
                        "the file ends inside the point data, before the " + std::to_string(m_las.pointCount) +
                            " points its header announces (was it changed while being read?)");
        }
        decode(m_file.data(), m, batch, out);
        m_file.consume(bytes);
        m_recordsLeft -= m;
        const std::size_t kept = m_positionsAlwaysFinite ? m : dropNonFinite(batch, out, m);
        m_pointsSkipped += m - kept;
        out += kept;
    }

    batch.positions.resize(3 * out);
    if (m_header.schema.hasColors) batch.colors.resize(3 * out);
    for (auto& column : batch.scalars) column.resize(out);
    m_pointsRead += out;
    return out;
}

void LasReader::decode(const char* records, std::size_t count, PointBatch& batch, std::size_t first) const
{
    const std::size_t length = m_las.recordLength;
    const auto [sx, sy, sz] = m_las.scale;
    const auto [ox, oy, oz] = m_las.offset;
    double* pos = batch.positions.data() + 3 * first;
    for (std::size_t i = 0; i < count; ++i) {
        const char* p = records + i * length;
        pos[3 * i + 0] = double(loadLittleEndian<std::int32_t>(p + 0)) * sx + ox;
        pos[3 * i + 1] = double(loadLittleEndian<std::int32_t>(p + 4)) * sy + oy;
        pos[3 * i + 2] = double(loadLittleEndian<std::int32_t>(p + 8)) * sz + oz;
    }

    if (m_layout.rgb >= 0) {
        std::uint8_t* rgb = batch.colors.data() + 3 * first;
        const char* in = records + m_layout.rgb;
        if (m_colors8Bit) {
            for (std::size_t i = 0; i < count; ++i)
                for (std::size_t k = 0; k < 3; ++k)
                    rgb[3 * i + k] = static_cast<std::uint8_t>(
                        std::min<std::uint16_t>(loadLittleEndian<std::uint16_t>(in + i * length + 2 * k), 255));
        } else {
            for (std::size_t i = 0; i < count; ++i)
                for (std::size_t k = 0; k < 3; ++k)
                    rgb[3 * i + k] =
                        static_cast<std::uint8_t>(loadLittleEndian<std::uint16_t>(in + i * length + 2 * k) >> 8);
        }
    }

    using K = LasScalarField::Kind;
    for (std::size_t f = 0; f < m_fields.size(); ++f) {
        const LasScalarField& field = m_fields[f];
        const char* in = records + field.offset;
        double* column = batch.scalars[f].data() + first;
        switch (field.kind) {
        case K::U8:
            for (std::size_t i = 0; i < count; ++i) column[i] = static_cast<std::uint8_t>(in[i * length]);
            break;
        case K::U16:
            for (std::size_t i = 0; i < count; ++i) column[i] = loadLittleEndian<std::uint16_t>(in + i * length);
            break;
        case K::Bits:
            for (std::size_t i = 0; i < count; ++i)
                column[i] = (static_cast<std::uint8_t>(in[i * length]) >> field.shift) & field.mask;
            break;
        case K::Angle8:
            for (std::size_t i = 0; i < count; ++i) column[i] = static_cast<std::int8_t>(in[i * length]);
            break;
        case K::Angle16:
            for (std::size_t i = 0; i < count; ++i)
                column[i] = loadLittleEndian<std::int16_t>(in + i * length) * 0.006;
            break;
        case K::F64:
            for (std::size_t i = 0; i < count; ++i) column[i] = loadLittleEndian<double>(in + i * length);
            break;
        case K::I8:
            for (std::size_t i = 0; i < count; ++i) column[i] = static_cast<std::int8_t>(in[i * length]);
            break;
        case K::I16:
            for (std::size_t i = 0; i < count; ++i) column[i] = loadLittleEndian<std::int16_t>(in + i * length);
            break;
        case K::U32:
            for (std::size_t i = 0; i < count; ++i) column[i] = loadLittleEndian<std::uint32_t>(in + i * length);
            break;
        case K::I32:
            for (std::size_t i = 0; i < count; ++i) column[i] = loadLittleEndian<std::int32_t>(in + i * length);
            break;
        case K::U64:
            for (std::size_t i = 0; i < count; ++i) column[i] = double(loadLittleEndian<std::uint64_t>(in + i * length));
            break;
        case K::I64:
            for (std::size_t i = 0; i < count; ++i) column[i] = double(loadLittleEndian<std::int64_t>(in + i * length));
            break;
        case K::F32:
            for (std::size_t i = 0; i < count; ++i) column[i] = loadLittleEndian<float>(in + i * length);
            break;
        }
        if (field.scale != 1.0 || field.add != 0.0)
            for (std::size_t i = 0; i < count; ++i) column[i] = column[i] * field.scale + field.add;
    }
}

std::size_t LasReader::dropNonFinite(PointBatch& batch, std::size_t first, std::size_t count)
{
    double* pos = batch.positions.data();
    std::size_t kept = first;
    for (std::size_t r = first; r < first + count; ++r) {
        if (!std::isfinite(pos[3 * r]) || !std::isfinite(pos[3 * r + 1]) || !std::isfinite(pos[3 * r + 2])) continue;
        if (kept != r) {
            std::copy_n(pos + 3 * r, 3, pos + 3 * kept);
            if (!batch.colors.empty()) std::copy_n(batch.colors.data() + 3 * r, 3, batch.colors.data() + 3 * kept);
            for (auto& column : batch.scalars) column[kept] = column[r];
        }
        ++kept;
    }
    return kept - first;
}

} // namespace stylos::core::io
