#include "stylos/core/io/PlyReader.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

template <typename T, bool Swap>
inline T loadAs(const char* p)
{
    T v;
    if constexpr (Swap && sizeof(T) > 1) {
        char tmp[sizeof(T)];
        for (std::size_t i = 0; i < sizeof(T); ++i) tmp[i] = p[sizeof(T) - 1 - i];
        std::memcpy(&v, tmp, sizeof(T));
    } else {
        std::memcpy(&v, p, sizeof(T));
    }
    return v;
}

template <bool Swap>
inline double loadValue(const char* p, PlyType type)
{
    switch (type) {
    case PlyType::Int8: return loadAs<std::int8_t, Swap>(p);
    case PlyType::UInt8: return loadAs<std::uint8_t, Swap>(p);
    case PlyType::Int16: return loadAs<std::int16_t, Swap>(p);
    case PlyType::UInt16: return loadAs<std::uint16_t, Swap>(p);
    case PlyType::Int32: return loadAs<std::int32_t, Swap>(p);
    case PlyType::UInt32: return loadAs<std::uint32_t, Swap>(p);
    case PlyType::Float32: return loadAs<float, Swap>(p);
    case PlyType::Float64: return loadAs<double, Swap>(p);
    }
    return 0.0;
}

template <bool Swap, typename T, typename Store>
void decodeColumnAs(const char* data, std::size_t records, std::size_t stride, Store&& store)
{
    for (std::size_t r = 0; r < records; ++r, data += stride) store(r, static_cast<double>(loadAs<T, Swap>(data)));
}

/** Decodes one property of @p records fixed-size records, handing each value to @p store(record, value). */
template <bool Swap, typename Store>
void decodeColumn(const char* data, PlyType type, std::size_t records, std::size_t stride, Store&& store)
{
    switch (type) {
    case PlyType::Int8: decodeColumnAs<Swap, std::int8_t>(data, records, stride, store); break;
    case PlyType::UInt8: decodeColumnAs<Swap, std::uint8_t>(data, records, stride, store); break;
    case PlyType::Int16: decodeColumnAs<Swap, std::int16_t>(data, records, stride, store); break;
    case PlyType::UInt16: decodeColumnAs<Swap, std::uint16_t>(data, records, stride, store); break;
    case PlyType::Int32: decodeColumnAs<Swap, std::int32_t>(data, records, stride, store); break;
    case PlyType::UInt32: decodeColumnAs<Swap, std::uint32_t>(data, records, stride, store); break;
    case PlyType::Float32: decodeColumnAs<Swap, float>(data, records, stride, store); break;
    case PlyType::Float64: decodeColumnAs<Swap, double>(data, records, stride, store); break;
    }
}

std::uint64_t loadCount(const char* p, PlyType type, bool swap)
{
    const double v = swap ? loadValue<true>(p, type) : loadValue<false>(p, type);
    return v < 0 ? ~std::uint64_t(0) : static_cast<std::uint64_t>(v);
}

constexpr bool hostIsLittle = std::endian::native == std::endian::little;

std::string_view nextToken(std::string_view& rest)
{
    std::size_t i = 0;
    while (i < rest.size() && (rest[i] == ' ' || rest[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < rest.size() && rest[j] != ' ' && rest[j] != '\t') ++j;
    const auto token = rest.substr(i, j - i);
    rest.remove_prefix(j);
    return token;
}

/** 0..255, rounded and clamped; NaN (a float colour can hold one) gives 0 as a negative value does. */
inline std::uint8_t toColor(double v)
{
    return v >= 0.0 ? static_cast<std::uint8_t>(std::min(v + 0.5, 255.0)) : std::uint8_t(0);
}

bool parseNumber(std::string_view token, double& value)
{
    if (token.empty()) return false;
    const char* begin = token.data();
    if (*begin == '+') ++begin;
    const auto [end, ec] = std::from_chars(begin, token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

} // namespace

PlyReader::PlyReader(fs::path path, BufferedFile file, PlyHeader ply)
    : PointReader(std::move(path), file.size()), m_file(std::move(file)), m_ply(std::move(ply))
{
}

Result<std::unique_ptr<PointReader>> PlyReader::open(const fs::path& path)
{
    auto file = BufferedFile::open(path);
    if (!file) return file.error();
    if (file->size() == 0) return Error::at(ErrorCode::Empty, path.string(), "", "the file is empty (0 bytes)");
    auto header = PlyHeader::parse(*file, path.string());
    if (!header) return header.error();

    std::unique_ptr<PlyReader> reader(new PlyReader(path, std::move(*file), std::move(*header)));
    const auto& ply = reader->m_ply;
    const auto& vertex = ply.elements[ply.vertexElement];
    reader->m_header.format = ply.encoding == PlyEncoding::Ascii              ? "ply-ascii"
                              : ply.encoding == PlyEncoding::BinaryLittleEndian ? "ply-binary-le"
                                                                                : "ply-binary-be";
    reader->m_header.declaredPoints = vertex.count;
    reader->planFields();

    // Fixed-size binary files: the header alone tells the exact file size.
    if (ply.encoding != PlyEncoding::Ascii) {
        bool fixed = true;
        std::uint64_t bytes = ply.dataOffset;
        for (const auto& e : ply.elements) {
            if (e.hasLists()) { fixed = false; break; }
            const auto rb = e.recordBytes();
            if (rb != 0 && e.count > (~std::uint64_t(0) - bytes) / rb)
                return reader->fail(ErrorCode::Malformed, "header", "element counts overflow a 64-bit size");
            bytes += e.count * rb;
        }
        if (fixed && bytes > reader->m_fileBytes)
            return reader->fail(ErrorCode::Truncated, "byte " + std::to_string(reader->m_fileBytes),
                                "the file ends early: the header announces " + std::to_string(vertex.count) +
                                    " vertices, " + std::to_string(bytes) + " bytes in all, but the file has " +
                                    std::to_string(reader->m_fileBytes));
        if (fixed && bytes < reader->m_fileBytes)
            return reader->fail(ErrorCode::Malformed, "byte " + std::to_string(bytes),
                                std::to_string(reader->m_fileBytes - bytes) +
                                    " bytes of data beyond the elements the header announces (counts disagree with the data)");
    }
    auto skipped = reader->skipElementsBefore(ply.vertexElement);
    if (!skipped) return skipped.error();
    return std::unique_ptr<PointReader>(std::move(reader));
}

void PlyReader::planFields()
{
    const auto& vertex = m_ply.elements[m_ply.vertexElement];
    auto colorScale = [](PlyType t) {
        if (t == PlyType::Float32 || t == PlyType::Float64) return 255.0f;
        if (t == PlyType::UInt16 || t == PlyType::Int16) return 1.0f / 257.0f;
        return 1.0f;
    };
    std::uint32_t offset = 0;
    int normals = 0, colors = 0;
    for (const auto& p : vertex.properties) {
        Field f{p.type, Target::None, 0, offset, 1.0f};
        offset += static_cast<std::uint32_t>(plyTypeSize(p.type));
        const std::string& n = p.name;
        if (p.isList) f.target = Target::None;
        else if (n == "x") f.target = Target::X;
        else if (n == "y") f.target = Target::Y;
        else if (n == "z") f.target = Target::Z;
        else if (n == "nx" || n == "normal_x") { f.target = Target::NX; ++normals; }
        else if (n == "ny" || n == "normal_y") { f.target = Target::NY; ++normals; }
        else if (n == "nz" || n == "normal_z") { f.target = Target::NZ; ++normals; }
        else if (n == "red" || n == "diffuse_red" || n == "r") { f.target = Target::R; ++colors; }
        else if (n == "green" || n == "diffuse_green" || n == "g") { f.target = Target::G; ++colors; }
        else if (n == "blue" || n == "diffuse_blue" || n == "b") { f.target = Target::B; ++colors; }
        else {
            f.target = Target::Scalar;
            f.scalar = static_cast<std::uint32_t>(m_header.schema.scalarNames.size());
            m_header.schema.scalarNames.push_back(n);
        }
        if (f.target == Target::R || f.target == Target::G || f.target == Target::B) f.colorScale = colorScale(p.type);
        m_fields.push_back(f);
    }
    // Only a complete triple counts; a lone "nx" or "red" stays a named scalar.
    auto demote = [&](Target a, Target b, Target c) {
        for (auto& f : m_fields)
            if (f.target == a || f.target == b || f.target == c) {
                f.target = Target::Scalar;
                f.scalar = static_cast<std::uint32_t>(m_header.schema.scalarNames.size());
                m_header.schema.scalarNames.push_back(vertex.properties[&f - m_fields.data()].name);
            }
    };
    m_header.schema.hasNormals = normals == 3;
    m_header.schema.hasColors = colors == 3;
    if (normals != 3 && normals != 0) demote(Target::NX, Target::NY, Target::NZ);
    if (colors != 3 && colors != 0) demote(Target::R, Target::G, Target::B);
    m_scalarValues.resize(m_header.schema.scalarNames.size());
}

std::string PlyReader::position() const
{
    if (m_ply.encoding == PlyEncoding::Ascii) return "line " + std::to_string(m_line);
    return "byte " + std::to_string(m_file.offset());
}

Status PlyReader::skipElement(const PlyElement& element)
{
    if (m_ply.encoding == PlyEncoding::Ascii) {
        std::string_view line;
        for (std::uint64_t i = 0; i < element.count; ++i) {
            if (!m_file.readLine(line))
                return fail(ErrorCode::Truncated, "line " + std::to_string(m_line),
                            "the file ends inside element \"" + element.name + "\" (" + std::to_string(i) + " of " +
                                std::to_string(element.count) + " records)");
            ++m_line;
        }
        return {};
    }
    const bool swap = (m_ply.encoding == PlyEncoding::BinaryBigEndian) == hostIsLittle;
    if (!element.hasLists()) {
        if (!m_file.skip(element.count * element.recordBytes()))
            return fail(ErrorCode::Truncated, "byte " + std::to_string(m_fileBytes),
                        "the file ends inside element \"" + element.name + "\"");
        return {};
    }
    for (std::uint64_t i = 0; i < element.count; ++i) {
        for (const auto& p : element.properties) {
            std::uint64_t bytes = plyTypeSize(p.type);
            if (p.isList) {
                const std::size_t cb = plyTypeSize(p.countType);
                if (m_file.fill(cb) < cb)
                    return fail(ErrorCode::Truncated, position(), "the file ends inside element \"" + element.name + "\"");
                const std::uint64_t items = loadCount(m_file.data(), p.countType, swap);
                m_file.consume(cb);
                bytes = items * bytes;
            }
            if (!m_file.skip(bytes))
                return fail(ErrorCode::Truncated, position(),
                            "the file ends inside element \"" + element.name + "\" (record " + std::to_string(i) +
                                " of " + std::to_string(element.count) + ")");
        }
    }
    return {};
}

Status PlyReader::skipElementsBefore(std::size_t elementIndex)
{
    m_line = m_ply.headerLines;
    for (std::size_t e = 0; e < elementIndex; ++e)
        if (auto s = skipElement(m_ply.elements[e]); !s) return s;
    return {};
}

Status PlyReader::finishFile()
{
    for (std::size_t e = m_ply.vertexElement + 1; e < m_ply.elements.size(); ++e)
        if (auto s = skipElement(m_ply.elements[e]); !s) return s;
    if (m_ply.encoding == PlyEncoding::Ascii) {
        std::string_view line;
        while (m_file.readLine(line)) {
            ++m_line;
            if (line.find_first_not_of(" \t") != std::string_view::npos)
                return fail(ErrorCode::Malformed, "line " + std::to_string(m_line),
                            "data beyond the elements the header announces (counts disagree with the data)");
        }
    } else if (m_file.offset() != m_fileBytes) {
        return fail(ErrorCode::Malformed, "byte " + std::to_string(m_file.offset()),
                    std::to_string(m_fileBytes - m_file.offset()) +
                        " bytes of data beyond the elements the header announces (counts disagree with the data)");
    }
    if (m_file.ioError()) return fail(ErrorCode::Unreadable, position(), "read error");
    return {};
}

void PlyReader::assign(const Field& f, double v, double* xyz, float* normal, double* color)
{
    switch (f.target) {
    case Target::X: xyz[0] = v; break;
    case Target::Y: xyz[1] = v; break;
    case Target::Z: xyz[2] = v; break;
    case Target::NX: normal[0] = static_cast<float>(v); break;
    case Target::NY: normal[1] = static_cast<float>(v); break;
    case Target::NZ: normal[2] = static_cast<float>(v); break;
    case Target::R: color[0] = v * f.colorScale; break;
    case Target::G: color[1] = v * f.colorScale; break;
    case Target::B: color[2] = v * f.colorScale; break;
    case Target::Scalar: m_scalarValues[f.scalar] = v; break;
    case Target::None: break;
    }
}

bool PlyReader::storePoint(const double* xyz, const float* normal, const double* color, PointBatch& batch)
{
    if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
        ++m_pointsSkipped;
        return false;
    }
    batch.positions.insert(batch.positions.end(), xyz, xyz + 3);
    if (m_header.schema.hasNormals) batch.normals.insert(batch.normals.end(), normal, normal + 3);
    if (m_header.schema.hasColors)
        for (int c = 0; c < 3; ++c)
            batch.colors.push_back(toColor(color[c]));
    for (std::size_t s = 0; s < m_scalarValues.size(); ++s) batch.scalars[s].push_back(m_scalarValues[s]);
    return true;
}

template <bool Swap>
std::size_t PlyReader::decodeFixedRecords(const char* data, std::size_t records, PointBatch& batch)
{
    // Column by column: the type and target switches run once per property and chunk, not per value,
    // and each inner loop is a plain typed load and store.
    const std::size_t rb = m_ply.elements[m_ply.vertexElement].recordBytes();
    const std::size_t base = batch.size();
    const bool hasNormals = m_header.schema.hasNormals, hasColors = m_header.schema.hasColors;
    batch.positions.resize(3 * (base + records));
    if (hasNormals) batch.normals.resize(3 * (base + records));
    if (hasColors) batch.colors.resize(3 * (base + records));
    for (auto& column : batch.scalars) column.resize(base + records);
    double* pos = batch.positions.data() + 3 * base;
    float* nrm = hasNormals ? batch.normals.data() + 3 * base : nullptr;
    std::uint8_t* col = hasColors ? batch.colors.data() + 3 * base : nullptr;

    for (const Field& f : m_fields) {
        const char* column = data + f.offset;
        const float scale = f.colorScale;
        switch (f.target) {
        case Target::X: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { pos[3 * r] = v; }); break;
        case Target::Y: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { pos[3 * r + 1] = v; }); break;
        case Target::Z: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { pos[3 * r + 2] = v; }); break;
        case Target::NX: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { nrm[3 * r] = float(v); }); break;
        case Target::NY: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { nrm[3 * r + 1] = float(v); }); break;
        case Target::NZ: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { nrm[3 * r + 2] = float(v); }); break;
        case Target::R: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { col[3 * r] = toColor(v * scale); }); break;
        case Target::G: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { col[3 * r + 1] = toColor(v * scale); }); break;
        case Target::B: decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { col[3 * r + 2] = toColor(v * scale); }); break;
        case Target::Scalar: {
            double* out = batch.scalars[f.scalar].data() + base;
            decodeColumn<Swap>(column, f.type, records, rb, [&](std::size_t r, double v) { out[r] = v; });
            break;
        }
        case Target::None: break;
        }
    }

    // Drop points with a non-finite coordinate (rare): compact every array in place.
    std::size_t out = 0;
    for (std::size_t r = 0; r < records; ++r) {
        const double* p = pos + 3 * r;
        if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
            ++m_pointsSkipped;
            continue;
        }
        if (out != r) {
            std::copy(p, p + 3, pos + 3 * out);
            if (nrm) std::copy(nrm + 3 * r, nrm + 3 * r + 3, nrm + 3 * out);
            if (col) std::copy(col + 3 * r, col + 3 * r + 3, col + 3 * out);
            for (auto& column : batch.scalars) column[base + out] = column[base + r];
        }
        ++out;
    }
    batch.positions.resize(3 * (base + out));
    if (hasNormals) batch.normals.resize(3 * (base + out));
    if (hasColors) batch.colors.resize(3 * (base + out));
    for (auto& column : batch.scalars) column.resize(base + out);
    return out;
}

Result<std::size_t> PlyReader::readBinary(PointBatch& batch, std::size_t n)
{
    const auto& vertex = m_ply.elements[m_ply.vertexElement];
    const bool swap = (m_ply.encoding == PlyEncoding::BinaryBigEndian) == hostIsLittle;
    auto truncated = [&] {
        return fail(ErrorCode::Truncated, "byte " + std::to_string(m_file.offset()),
                    "the file ends inside vertex " + std::to_string(m_verticesDone) + " of " +
                        std::to_string(vertex.count));
    };
    std::size_t stored = 0;
    if (!vertex.hasLists()) {
        const std::size_t rb = vertex.recordBytes();
        const std::size_t perFill = std::max<std::size_t>(1, (std::size_t(1) << 20) / std::max<std::size_t>(rb, 1));
        std::size_t left = n;
        while (left > 0) {
            const std::size_t want = std::min(left, perFill);
            const std::size_t have = m_file.fill(want * rb) / rb;
            if (have == 0) return truncated();
            const std::size_t k = std::min(want, have);
            stored += swap ? decodeFixedRecords<true>(m_file.data(), k, batch)
                           : decodeFixedRecords<false>(m_file.data(), k, batch);
            m_file.consume(k * rb);
            m_verticesDone += k;
            left -= k;
        }
        return stored;
    }
    // Vertex records with list properties: walk each record.
    for (std::size_t i = 0; i < n; ++i) {
        double xyz[3] = {0, 0, 0};
        float normal[3] = {0, 0, 0};
        double color[3] = {0, 0, 0};
        for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
            const auto& prop = vertex.properties[p];
            const Field& f = m_fields[p];
            if (prop.isList) {
                const std::size_t cb = plyTypeSize(prop.countType);
                if (m_file.fill(cb) < cb) return truncated();
                const std::uint64_t items = loadCount(m_file.data(), prop.countType, swap);
                m_file.consume(cb);
                if (!m_file.skip(items * plyTypeSize(prop.type))) return truncated();
                continue;
            }
            const std::size_t sz = plyTypeSize(prop.type);
            if (m_file.fill(sz) < sz) return truncated();
            const double v = swap ? loadValue<true>(m_file.data(), prop.type) : loadValue<false>(m_file.data(), prop.type);
            m_file.consume(sz);
            assign(f, v, xyz, normal, color);
        }
        ++m_verticesDone;
        stored += storePoint(xyz, normal, color, batch) ? 1 : 0;
    }
    return stored;
}

Result<std::size_t> PlyReader::readAscii(PointBatch& batch, std::size_t n)
{
    const auto& vertex = m_ply.elements[m_ply.vertexElement];
    std::size_t stored = 0;
    std::string_view line;
    for (std::size_t i = 0; i < n;) {
        if (!m_file.readLine(line))
            return fail(ErrorCode::Truncated, "line " + std::to_string(m_line),
                        "the file ends after vertex " + std::to_string(m_verticesDone) + " of " +
                            std::to_string(vertex.count));
        ++m_line;
        if (m_file.lineTooLong()) return fail(ErrorCode::Malformed, position(), "a line longer than 64 MiB");
        std::string_view rest = line;
        if (rest.find_first_not_of(" \t") == std::string_view::npos) continue; // blank line
        double xyz[3] = {0, 0, 0};
        float normal[3] = {0, 0, 0};
        double color[3] = {0, 0, 0};
        for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
            const auto& prop = vertex.properties[p];
            const Field& f = m_fields[p];
            const auto token = nextToken(rest);
            double v = 0;
            if (token.empty())
                return fail(ErrorCode::Malformed, position(),
                            "vertex " + std::to_string(m_verticesDone) + " has too few values (property \"" +
                                prop.name + "\" is missing)");
            if (!parseNumber(token, v))
                return fail(ErrorCode::Malformed, position(),
                            "\"" + std::string(token.substr(0, 40)) + "\" is not a number (property \"" + prop.name + "\")");
            if (prop.isList) {
                if (v < 0 || v > 1e9 || v != std::floor(v))
                    return fail(ErrorCode::Malformed, position(), "bad list count for property \"" + prop.name + "\"");
                for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(v); ++k)
                    if (nextToken(rest).empty())
                        return fail(ErrorCode::Malformed, position(), "list \"" + prop.name + "\" has too few items");
                continue;
            }
            assign(f, v, xyz, normal, color);
        }
        if (!nextToken(rest).empty())
            return fail(ErrorCode::Malformed, position(),
                        "vertex " + std::to_string(m_verticesDone) + " has more values than the header's " +
                            std::to_string(vertex.properties.size()) + " properties");
        ++m_verticesDone;
        ++i;
        stored += storePoint(xyz, normal, color, batch) ? 1 : 0;
    }
    return stored;
}

Result<std::size_t> PlyReader::read(PointBatch& batch, std::size_t maxPoints)
{
    maxPoints = std::max<std::size_t>(maxPoints, 1);
    batch.reset(m_header.schema, maxPoints);
    const auto& vertex = m_ply.elements[m_ply.vertexElement];
    while (!m_done) {
        const std::uint64_t remaining = vertex.count - m_verticesDone;
        if (remaining == 0) {
            if (auto s = finishFile(); !s) return s.error();
            m_done = true;
            break;
        }
        const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(remaining, maxPoints - batch.size()));
        auto got = m_ply.encoding == PlyEncoding::Ascii ? readAscii(batch, want) : readBinary(batch, want);
        if (!got) return got.error();
        m_pointsRead += *got;
        if (batch.size() >= maxPoints) break;
    }
    return batch.size();
}

} // namespace stylos::core::io
