#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/util/AtomicTextFile.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <system_error>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

template <typename T>
unsigned char* put(unsigned char* out, T value)
{
    std::memcpy(out, &value, sizeof(T));
    return out + sizeof(T);
}

template <typename T>
T clampTo(double v)
{
    if (std::isnan(v)) return T(0);
    const double lo = static_cast<double>(std::numeric_limits<T>::lowest());
    const double hi = static_cast<double>(std::numeric_limits<T>::max());
    return static_cast<T>(std::clamp(std::round(v), lo, hi));
}

unsigned char* putScalar(unsigned char* out, PlyScalarType t, double v)
{
    switch (t) {
    case PlyScalarType::Int8: return put(out, clampTo<std::int8_t>(v));
    case PlyScalarType::UInt8: return put(out, clampTo<std::uint8_t>(v));
    case PlyScalarType::Int16: return put(out, clampTo<std::int16_t>(v));
    case PlyScalarType::UInt16: return put(out, clampTo<std::uint16_t>(v));
    case PlyScalarType::Int32: return put(out, clampTo<std::int32_t>(v));
    case PlyScalarType::UInt32: return put(out, clampTo<std::uint32_t>(v));
    case PlyScalarType::Float32: return put(out, static_cast<float>(v));
    case PlyScalarType::Float64: return put(out, v);
    }
    return out;
}

constexpr int countFieldWidth = 20; // room for any 64-bit count, patched on finish()

} // namespace

PlyWriter::PlyWriter(PlyWriter&&) noexcept = default;

PlyWriter::~PlyWriter()
{
    if (m_file) {
        m_file.reset();
        std::error_code ec;
        if (!m_finished) fs::remove(m_temporary, ec);
    }
}

Error PlyWriter::failure(const std::string& problem) const
{
    return Error::at(ErrorCode::WriteFailed, m_target.string(), "", problem);
}

Result<PlyWriter> PlyWriter::create(const fs::path& path, const PointSchema& schema, PlyWriterOptions options)
{
    if (options.positionType != PlyScalarType::Float32 && options.positionType != PlyScalarType::Float64)
        return Error::at(ErrorCode::InvalidArgument, path.string(), "", "positions must be float or double");
    for (const auto& c : options.comments)
        if (c.find_first_of("\r\n") != std::string::npos)
            return Error::at(ErrorCode::InvalidArgument, path.string(), "", "a PLY comment cannot hold a line break");
    for (const auto& name : schema.scalarNames)
        if (name.empty() || name.find_first_of(" \t\r\n") != std::string::npos)
            return Error::at(ErrorCode::InvalidArgument, path.string(), "",
                             "scalar name \"" + name + "\" is not a valid PLY property name");
    options.scalarTypes.resize(schema.scalarNames.size(), PlyScalarType::Float32);

    PlyWriter w;
    w.m_target = path;
    std::random_device rd;
    w.m_temporary = path;
    w.m_temporary += ".tmp-" + std::to_string(rd());
    w.m_schema = schema;
    w.m_options = std::move(options);
    errno = 0;
    w.m_file.reset(std::fopen(w.m_temporary.c_str(), "wb"));
    if (!w.m_file) return w.failure(std::string("cannot create the file: ") + std::strerror(errno));
    if (auto s = w.writeHeader(); !s) return s.error();
    return w;
}

Status PlyWriter::writeHeader()
{
    std::string h = "ply\nformat binary_little_endian 1.0\n";
    for (const auto& c : m_options.comments) h += "comment " + c + "\n";
    h += "element vertex ";
    m_countFieldOffset = static_cast<long>(h.size());
    h += std::string(countFieldWidth, ' ') + "\n"; // count patched later; PLY readers split on whitespace
    const char* pos = plyTypeName(m_options.positionType);
    for (const char* axis : {"x", "y", "z"}) h += std::string("property ") + pos + " " + axis + "\n";
    if (m_schema.hasNormals) h += "property float nx\nproperty float ny\nproperty float nz\n";
    if (m_schema.hasColors) h += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    for (std::size_t i = 0; i < m_schema.scalarNames.size(); ++i)
        h += std::string("property ") + plyTypeName(m_options.scalarTypes[i]) + " " + m_schema.scalarNames[i] + "\n";
    h += "end_header\n";
    if (std::fwrite(h.data(), 1, h.size(), m_file.get()) != h.size())
        return failure(std::string("write error: ") + std::strerror(errno));

    std::size_t record = 3 * plyTypeSize(m_options.positionType);
    if (m_schema.hasNormals) record += 12;
    if (m_schema.hasColors) record += 3;
    for (auto t : m_options.scalarTypes) record += plyTypeSize(t);
    m_record.resize(record);
    return {};
}

Status PlyWriter::write(const PointBatch& batch)
{
    const std::size_t n = batch.size();
    if (n == 0) return {};
    if ((m_schema.hasNormals && batch.normals.size() != 3 * n) || (m_schema.hasColors && batch.colors.size() != 3 * n) ||
        batch.scalars.size() < m_schema.scalarNames.size())
        return Error::at(ErrorCode::InvalidArgument, m_target.string(), "", "the batch does not match the schema");
    for (std::size_t s = 0; s < m_schema.scalarNames.size(); ++s)
        if (batch.scalars[s].size() != n)
            return Error::at(ErrorCode::InvalidArgument, m_target.string(), "", "a scalar column has the wrong length");

    const std::size_t rb = m_record.size();
    m_buffer.resize(n * rb);
    unsigned char* out = m_buffer.data();
    const bool doublePos = m_options.positionType == PlyScalarType::Float64;
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c)
            out = doublePos ? put(out, batch.positions[3 * i + c]) : put(out, static_cast<float>(batch.positions[3 * i + c]));
        if (m_schema.hasNormals)
            for (int c = 0; c < 3; ++c) out = put(out, batch.normals[3 * i + c]);
        if (m_schema.hasColors)
            for (int c = 0; c < 3; ++c) out = put(out, batch.colors[3 * i + c]);
        for (std::size_t s = 0; s < m_schema.scalarNames.size(); ++s)
            out = putScalar(out, m_options.scalarTypes[s], batch.scalars[s][i]);
    }
    if (std::fwrite(m_buffer.data(), 1, m_buffer.size(), m_file.get()) != m_buffer.size())
        return failure(std::string("write error: ") + std::strerror(errno));
    m_count += n;
    return {};
}

Status PlyWriter::finish()
{
    if (!m_file || m_finished) return failure("PlyWriter::finish(): already finished");
    const std::string count = std::to_string(m_count);
    if (std::fseek(m_file.get(), m_countFieldOffset, SEEK_SET) != 0 ||
        std::fwrite(count.data(), 1, count.size(), m_file.get()) != count.size() || std::fflush(m_file.get()) != 0)
        return failure(std::string("write error: ") + std::strerror(errno));
    if (std::fclose(m_file.release()) != 0) {
        std::error_code ec;
        fs::remove(m_temporary, ec);
        return failure(std::string("write error on close: ") + std::strerror(errno));
    }
    keepModeOf(m_target, m_temporary);
    std::error_code ec;
    fs::rename(m_temporary, m_target, ec);
    if (ec) {
        std::error_code ignored; // the rename's reason is the one to report
        fs::remove(m_temporary, ignored);
        return failure("cannot move the finished file into place: " + ec.message());
    }
    m_finished = true;
    return {};
}

} // namespace stylos::core::io
