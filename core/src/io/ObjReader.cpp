#include "stylos/core/io/ObjReader.h"

#include "stylos/core/io/TextColumns.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t colorSampleLines = 64;
constexpr std::size_t batchReserve = std::size_t(1) << 16;

inline bool isSpace(char c) { return c == ' ' || c == '\t'; }

} // namespace

ObjReader::ObjReader(fs::path path, BufferedFile file) : PointReader(std::move(path), file.size())
{
    m_vertices.file = std::move(file);
}

Error ObjReader::lineError(std::uint64_t line, const std::string& problem) const
{
    return fail(ErrorCode::Malformed, "line " + std::to_string(line), problem);
}

Result<std::unique_ptr<PointReader>> ObjReader::open(const fs::path& path)
{
    auto file = BufferedFile::open(path);
    if (!file) return file.error();
    std::unique_ptr<ObjReader> reader(new ObjReader(path, std::move(file).value()));
    if (reader->m_fileBytes == 0) return reader->fail(ErrorCode::Empty, "", "the file is empty (0 bytes)");
    if (auto status = reader->countLines(); !status) return status.error();
    if (reader->m_vertexCount == 0) return reader->fail(ErrorCode::Empty, "", "no points: the file has no vertex (\"v\" line)");

    PointSchema& schema = reader->m_header.schema;
    schema.hasColors = reader->m_vertexFields == 6;
    schema.hasNormals = reader->m_normalCount == reader->m_vertexCount;
    if (schema.hasNormals) {
        auto normals = BufferedFile::open(path);
        if (!normals) return normals.error();
        reader->m_normals.file = std::move(normals).value();
        if (!reader->m_normals.file.seek(reader->m_firstNormalOffset))
            return reader->fail(ErrorCode::Unreadable, "byte " + std::to_string(reader->m_firstNormalOffset),
                                "cannot move to the first normal");
        reader->m_normals.line = reader->m_firstNormalLine;
    }
    reader->m_header.format = "obj";
    reader->m_header.declaredPoints = reader->m_vertexCount;
    return std::unique_ptr<PointReader>(std::move(reader));
}

Status ObjReader::countLines()
{
    BufferedFile& file = m_vertices.file;
    std::uint64_t line = 0;
    std::size_t sampled = 0;
    bool aboveOne = false;
    std::string_view text;
    for (;;) {
        const std::uint64_t start = file.offset();
        if (!file.readLine(text)) break;
        ++line;
        if (file.lineTooLong()) return lineError(line, "the line is longer than 64 MiB");
        std::size_t i = 0;
        while (i < text.size() && isSpace(text[i])) ++i;
        if (i == text.size() || text[i] != 'v') continue;
        if (i + 1 == text.size() || isSpace(text[i + 1])) {
            ++m_vertexCount;
            if (m_vertexCount > 1 && (m_vertexFields != 6 || sampled >= colorSampleLines)) continue;
            double values[7];
            const FieldScan scan = parseFields(text.substr(i + 1), Separator::Whitespace, values, 7);
            if (m_vertexCount == 1) {
                if (scan.count != 3 && scan.count != 4 && scan.count != 6)
                    return lineError(line, "a vertex with " + std::to_string(scan.count) +
                                               " numbers; expected x y z [w] or x y z r g b");
                m_vertexFields = scan.count == 6 ? 6 : 3;
            }
            if (m_vertexFields == 6 && scan.count == 6 && scan.badField == 0) {
                ++sampled;
                aboveOne = aboveOne || values[3] > 1.0 || values[4] > 1.0 || values[5] > 1.0;
            }
        } else if (text[i + 1] == 'n' && (i + 2 == text.size() || isSpace(text[i + 2]))) {
            if (++m_normalCount == 1) {
                m_firstNormalOffset = start;
                m_firstNormalLine = line - 1;
            }
        }
    }
    if (file.ioError()) return fail(ErrorCode::Unreadable, "byte " + std::to_string(file.offset()), "a read failed");
    m_unitColors = !aboveOne;
    if (!file.seek(0)) return fail(ErrorCode::Unreadable, "", "cannot go back to its start");
    return {};
}

Result<bool> ObjReader::next(Cursor& cursor, LineKind kind, std::string_view& fields) const
{
    std::string_view text;
    while (cursor.file.readLine(text)) {
        ++cursor.line;
        if (cursor.file.lineTooLong()) return lineError(cursor.line, "the line is longer than 64 MiB");
        std::size_t i = 0;
        while (i < text.size() && isSpace(text[i])) ++i;
        if (i == text.size() || text[i] != 'v') continue;
        if (kind == LineKind::Vertex && (i + 1 == text.size() || isSpace(text[i + 1]))) {
            fields = text.substr(i + 1);
            return true;
        }
        if (kind == LineKind::Normal && i + 1 < text.size() && text[i + 1] == 'n' &&
            (i + 2 == text.size() || isSpace(text[i + 2]))) {
            fields = text.substr(i + 2);
            return true;
        }
    }
    if (cursor.file.ioError())
        return fail(ErrorCode::Unreadable, "byte " + std::to_string(cursor.file.offset()), "a read failed");
    return false;
}

Result<std::size_t> ObjReader::read(PointBatch& batch, std::size_t maxPoints)
{
    assert(maxPoints > 0 && "ObjReader::read(): maxPoints must be positive");
    const PointSchema& schema = m_header.schema;
    batch.reset(schema, std::min(maxPoints, batchReserve));
    double v[7];
    double nrm[3];
    std::size_t n = 0;
    while (n < maxPoints) {
        std::string_view fields;
        auto got = next(m_vertices, LineKind::Vertex, fields);
        if (!got) return got.error();
        if (!got.value()) break;
        const FieldScan scan = parseFields(fields, Separator::Whitespace, v, 7);
        const bool countOk = schema.hasColors ? scan.count == 6 : (scan.count == 3 || scan.count == 4);
        if (!countOk)
            return lineError(m_vertices.line, "a vertex with " + std::to_string(scan.count) + " numbers where " +
                                                  (schema.hasColors ? "6 (x y z r g b)" : "3 (x y z) or 4 (x y z w)") +
                                                  " are expected");
        if (scan.badField != 0) return lineError(m_vertices.line, "vertex " + fieldProblem(scan));

        if (schema.hasNormals) {
            auto gotNormal = next(m_normals, LineKind::Normal, fields);
            if (!gotNormal) return gotNormal.error();
            if (!gotNormal.value()) return lineError(m_normals.line, "fewer normals than counted: the file changed");
            const FieldScan normalScan = parseFields(fields, Separator::Whitespace, nrm, 3);
            if (normalScan.count != 3)
                return lineError(m_normals.line, "a normal with " + std::to_string(normalScan.count) +
                                                     " numbers where 3 (nx ny nz) are expected");
            if (normalScan.badField != 0) return lineError(m_normals.line, "normal " + fieldProblem(normalScan));
        }

        if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]))) {
            ++m_pointsSkipped;
            continue;
        }
        batch.positions.insert(batch.positions.end(), v, v + 3);
        if (schema.hasNormals)
            for (const double c : nrm) batch.normals.push_back(static_cast<float>(c));
        if (schema.hasColors)
            for (int c = 3; c < 6; ++c) batch.colors.push_back(colorToByte(v[c], m_unitColors));
        ++n;
    }
    m_pointsRead += n;
    return n;
}

} // namespace stylos::core::io
