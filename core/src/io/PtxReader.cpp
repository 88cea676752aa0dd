#include "stylos/core/io/PtxReader.h"

#include "stylos/core/io/TextColumns.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

namespace stylos::core::io {

namespace fs = std::filesystem;

PtxReader::PtxReader(fs::path path, BufferedFile file, std::optional<std::size_t> scan)
    : PointReader(std::move(path), file.size()), m_file(std::move(file)), m_wanted(scan)
{
    m_header.format = "ptx";
    m_header.schema.scalarNames = {"intensity"};
    if (!scan) m_header.schema.scalarNames.push_back(kScanIndexColumn); // column 1
}

Error PtxReader::lineError(ErrorCode code, const std::string& problem) const
{
    return fail(code, "line " + std::to_string(m_line), problem);
}

bool PtxReader::nextLine(std::string_view& line)
{
    if (!m_file.readLine(line)) return false;
    ++m_line;
    return true;
}

Result<std::unique_ptr<PointReader>> PtxReader::open(const fs::path& path, const ReadOptions& options)
{
    auto file = BufferedFile::open(path);
    if (!file) return file.error();
    if (file->size() == 0) return Error::at(ErrorCode::Empty, path.string(), "", "the file is empty (0 bytes)");
    std::unique_ptr<PtxReader> reader(new PtxReader(path, std::move(file).value(), options.scan));
    auto first = reader->readScanHeader();
    if (!first) return first.error();
    if (!*first) return Error::at(ErrorCode::Empty, path.string(), "", "the file holds no scan (only blank lines)");
    // The first point line fixes the schema: 4 values (x y z intensity) or 7 (… r g b).
    BufferedFile& f = reader->m_file;
    const std::size_t n = f.fill(std::size_t(64) << 10);
    const char* end = static_cast<const char*>(std::memchr(f.data(), '\n', n));
    const std::string_view peek(f.data(), end ? std::size_t(end - f.data()) : n);
    double values[8];
    const FieldScan scan = parseFields(peek, Separator::Whitespace, values, 8);
    reader->m_values = scan.count >= 7 ? 7 : 4;
    reader->m_header.schema.hasColors = reader->m_values == 7;
    return std::unique_ptr<PointReader>(std::move(reader));
}

Result<bool> PtxReader::readScanHeader()
{
    std::string_view line;
    do {
        if (!nextLine(line)) return false;
    } while (trimSpaces(line).empty());

    std::uint64_t columns = 0, rows = 0;
    if (!parseCountLine(line, columns))
        return lineError(ErrorCode::Malformed, "expected the column count of a scan header, found \"" +
                                                   std::string(trimSpaces(line).substr(0, 40)) + "\"");
    if (!nextLine(line)) return lineError(ErrorCode::Truncated, "the file ends inside a scan header, after its column count");
    if (!parseCountLine(line, rows))
        return lineError(ErrorCode::Malformed, "expected the row count of a scan header, found \"" +
                                                   std::string(trimSpaces(line).substr(0, 40)) + "\"");
    // Scanner position and axes (3 values each, not used), then the 4 × 4 transform.
    double values[4];
    for (int k = 0; k < 8; ++k) {
        const std::size_t want = k < 4 ? 3 : 4;
        if (!nextLine(line))
            return lineError(ErrorCode::Truncated, "the file ends inside a scan header (line " + std::to_string(k + 3) +
                                                       " of its 10)");
        const FieldScan scan = parseFields(line, Separator::Whitespace, values, 4);
        if (scan.badField != 0) return lineError(ErrorCode::Malformed, fieldProblem(scan));
        if (scan.count != want)
            return lineError(ErrorCode::Malformed,
                             std::string(k == 0 ? "the scanner position" : k < 4 ? "a scanner axis" : "a transform row") +
                                 " needs " + std::to_string(want) + " numbers, the line has " + std::to_string(scan.count));
        if (k >= 4) std::copy_n(values, 4, m_matrix.begin() + 4 * (k - 4));
    }
    const std::uint64_t points = columns * rows;
    if (rows != 0 && points / rows != columns) return lineError(ErrorCode::Malformed, "the scan's size overflows");

    ScanInfo info;
    info.name = "scan " + std::to_string(m_scans.size());
    info.points = points;
    // Row-vector convention: p' = p · M, i.e. R = Mᵀ (upper 3 × 3) and t = M's last row.
    const auto& m = m_matrix;
    info.pose = {m[0], m[4], m[8], m[12], m[1], m[5], m[9], m[13], m[2], m[6], m[10], m[14]};
    m_keepScan = !m_wanted || *m_wanted == m_scans.size();
    m_scans.push_back(info);
    m_pointsLeft = points;
    if (m_keepScan) m_declared += points;
    return true;
}

Result<std::size_t> PtxReader::read(PointBatch& batch, std::size_t maxPoints)
{
    assert(maxPoints > 0 && "PtxReader::read(): maxPoints must be positive");
    maxPoints = std::max<std::size_t>(maxPoints, 1);
    batch.reset(m_header.schema, std::min<std::size_t>(maxPoints, std::size_t(1) << 16));
    std::string_view line;
    double v[8];
    while (batch.size() < maxPoints && !m_done) {
        if (m_pointsLeft == 0) {
            auto more = readScanHeader();
            if (!more) return more.error();
            if (!*more) {
                m_done = true;
                if (m_wanted && *m_wanted >= m_scans.size())
                    return fail(ErrorCode::InvalidArgument, "",
                                "scan " + std::to_string(*m_wanted) + " does not exist: the file has " +
                                    std::to_string(m_scans.size()) + " scan(s), numbered from 0");
                m_header.declaredPoints = m_declared;
            }
            continue;
        }
        if (!nextLine(line)) {
            const ScanInfo& s = m_scans.back();
            ++m_line;
            return lineError(ErrorCode::Truncated, "the file ends inside " + s.name + " after " +
                                                       std::to_string(s.points - m_pointsLeft) + " of its " +
                                                       std::to_string(s.points) + " points");
        }
        --m_pointsLeft;
        if (!m_keepScan) continue;
        const FieldScan scan = parseFields(line, Separator::Whitespace, v, 8);
        if (scan.badField != 0) return lineError(ErrorCode::Malformed, fieldProblem(scan));
        if (scan.count != m_values)
            return lineError(ErrorCode::Malformed, "a point line has " + std::to_string(scan.count) +
                                                       " values, the file's first has " + std::to_string(m_values));
        if (v[0] == 0 && v[1] == 0 && v[2] == 0) {
            ++m_pointsMissing;
            continue;
        }
        const auto& m = m_matrix;
        const double x = v[0] * m[0] + v[1] * m[4] + v[2] * m[8] + m[12];
        const double y = v[0] * m[1] + v[1] * m[5] + v[2] * m[9] + m[13];
        const double z = v[0] * m[2] + v[1] * m[6] + v[2] * m[10] + m[14];
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
            ++m_pointsSkipped;
            continue;
        }
        if (m_values == 7) {
            for (int k = 4; k < 7; ++k)
                if (!(v[k] >= 0 && v[k] <= 255))
                    return lineError(ErrorCode::Malformed, "colour value " + std::to_string(v[k]) + " is outside 0–255");
            batch.colors.insert(batch.colors.end(), {static_cast<std::uint8_t>(std::lround(v[4])),
                                                     static_cast<std::uint8_t>(std::lround(v[5])),
                                                     static_cast<std::uint8_t>(std::lround(v[6]))});
        }
        batch.positions.insert(batch.positions.end(), {x, y, z});
        batch.scalars[0].push_back(v[3]);
        if (!m_wanted) batch.scalars[1].push_back(double(m_scans.size() - 1));
    }
    m_pointsRead += batch.size();
    return batch.size();
}

} // namespace stylos::core::io
