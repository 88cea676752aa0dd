#include "stylos/core/io/TextReader.h"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t sampleLines = 64;
constexpr std::size_t batchReserve = std::size_t(1) << 16;

bool isComment(std::string_view trimmed)
{
    return !trimmed.empty() && (trimmed[0] == '#' || (trimmed.size() > 1 && trimmed[0] == '/' && trimmed[1] == '/'));
}

std::string formatName(const fs::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".xyz" || ext == ".xyzn") return "xyz";
    if (ext == ".asc" || ext == ".csv" || ext == ".pts") return ext.substr(1);
    return "txt";
}

std::string columnsText(std::size_t n) { return std::to_string(n) + (n == 1 ? " column" : " columns"); }

/** The line without a UTF-8 byte order mark (spreadsheets write one before CSV data). */
std::string_view withoutBom(std::string_view line)
{
    return line.substr(0, 3) == "\xEF\xBB\xBF" ? line.substr(3) : line;
}

/** A comment line that names x, y and z among non-numeric fields ("//X Y Z Rf Gf Bf"). */
bool isCommentHeader(const std::vector<std::string_view>& fields)
{
    if (fields.size() < 3) return false;
    for (const std::string_view field : fields) {
        double v;
        if (parseFields(field, Separator::Whitespace, &v, 1).badField == 0) return false;
    }
    return layoutFromNames(fields).ok();
}

} // namespace

struct TextReader::Prescan {
    ColumnSample sample;
    std::uint64_t firstDataLine = 0; ///< 0: no data line at all
    std::uint64_t headerLine = 0;
    std::string headerText;
    Separator headerSeparator = Separator::Whitespace;
    std::string commentHeader;
    std::optional<std::uint64_t> firstCount;
    std::uint64_t firstCountLine = 0;
};

TextReader::TextReader(fs::path path, BufferedFile file)
    : PointReader(std::move(path), file.size()), m_file(std::move(file))
{
}

Error TextReader::lineError(ErrorCode code, std::uint64_t line, const std::string& problem) const
{
    return fail(code, "line " + std::to_string(line), problem);
}

Result<std::unique_ptr<PointReader>> TextReader::open(const fs::path& path, const ReadOptions& options)
{
    auto file = BufferedFile::open(path);
    if (!file) return file.error();
    std::unique_ptr<TextReader> reader(new TextReader(path, std::move(file).value()));
    if (reader->m_fileBytes == 0) return reader->fail(ErrorCode::Empty, "", "the file is empty (0 bytes)");

    auto scan = reader->prescan();
    if (!scan) return scan.error();
    if (scan->firstDataLine == 0) {
        if (scan->headerLine != 0 && options.columns.empty()) // a header that is no layout says more
            if (auto status = reader->settleLayout(scan.value(), options); !status) return status.error();
        if (scan->firstCount.value_or(0) > 0)
            return reader->lineError(ErrorCode::Truncated, reader->m_line,
                                     "the file ends after 0 of the " + std::to_string(*scan->firstCount) +
                                         " points announced at line " + std::to_string(scan->firstCountLine));
        return reader->fail(ErrorCode::Empty, "", "no points: the file holds no data line");
    }
    if (auto status = reader->settleLayout(scan.value(), options); !status) return status.error();

    reader->m_header.format = formatName(path);
    reader->m_header.declaredPoints = scan->firstCount;
    reader->m_header.schema = reader->m_layout.schema();
    reader->m_headerLine = scan->headerLine;
    reader->m_firstCountLine = scan->firstCountLine;
    if (!reader->m_file.seek(0)) return reader->fail(ErrorCode::Unreadable, "", "cannot go back to its start");
    reader->m_line = 0;
    return std::unique_ptr<PointReader>(std::move(reader));
}

Result<TextReader::Prescan> TextReader::prescan()
{
    Prescan scan;
    ColumnSample& sample = scan.sample;
    std::vector<double> row;
    std::size_t dataLines = 0;
    std::string_view line;
    while (dataLines < sampleLines && m_file.readLine(line)) {
        ++m_line;
        if (m_file.lineTooLong()) return lineError(ErrorCode::Malformed, m_line, "the line is longer than 64 MiB");
        if (m_line == 1) line = withoutBom(line);
        std::string_view text = trimSpaces(line);
        if (text.empty()) continue;
        if (isComment(text)) {
            if (scan.firstDataLine == 0 && scan.commentHeader.empty()) {
                text = trimSpaces(text.substr(text[0] == '#' ? 1 : 2));
                if (isCommentHeader(splitFields(text, detectSeparator(text)))) scan.commentHeader = text;
            }
            continue;
        }
        std::uint64_t count = 0;
        if (parseCountLine(text, count)) {
            if (scan.firstDataLine == 0 && !scan.firstCount) {
                scan.firstCount = count;
                scan.firstCountLine = m_line;
            }
            continue;
        }
        if (scan.firstDataLine == 0) {
            const Separator separator = detectSeparator(text);
            double first = 0.0;
            const FieldScan firstField = parseFields(text, separator, &first, 1);
            const bool named = std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_' ||
                               text[0] == '"' || text[0] == '\'';
            if (firstField.badField == 1 && named && scan.headerLine == 0) { // a header line of column names
                scan.headerLine = m_line;
                scan.headerText = text;
                scan.headerSeparator = separator;
                continue;
            }
            if (firstField.badField != 0) return lineError(ErrorCode::Malformed, m_line, fieldProblem(firstField));
            scan.firstDataLine = m_line;
            m_separator = separator;
            sample.columns = firstField.count;
            sample.fractional.assign(sample.columns, 0);
            row.resize(sample.columns);
        }
        ++dataLines;
        const FieldScan fields = parseFields(text, m_separator, row.data(), row.size());
        if (fields.count != sample.columns || fields.badField != 0) break; // read() reports it
        if (!std::all_of(row.begin(), row.end(), [](double v) { return std::isfinite(v); })) continue;
        sample.values.insert(sample.values.end(), row.begin(), row.end());
        const auto tokens = splitFields(text, m_separator);
        for (std::size_t c = 0; c < tokens.size() && c < sample.columns; ++c)
            if (tokens[c].find_first_of(".eE") != std::string_view::npos) sample.fractional[c] = 1;
    }
    if (m_file.ioError()) return fail(ErrorCode::Unreadable, "", "a read failed");
    return scan;
}

Status TextReader::settleLayout(const Prescan& scan, const ReadOptions& options)
{
    if (!options.columns.empty()) {
        auto layout = layoutFromOverride(options.columns);
        if (!layout) return fail(ErrorCode::InvalidArgument, "", layout.error().message);
        m_layout = std::move(layout).value();
    } else if (scan.headerLine != 0) {
        auto layout = layoutFromNames(splitFields(scan.headerText, scan.headerSeparator));
        if (!layout)
            return lineError(ErrorCode::Malformed, scan.headerLine,
                             "a header line that is not a column layout (" + layout.error().message + ")");
        m_layout = std::move(layout).value();
    } else {
        if (!scan.commentHeader.empty()) {
            auto layout = layoutFromNames(splitFields(scan.commentHeader, detectSeparator(scan.commentHeader)));
            if (layout && layout->columnCount() == scan.sample.columns) m_layout = std::move(layout).value();
        }
        if (m_layout.roles.empty()) {
            if (scan.sample.columns < 3)
                return lineError(ErrorCode::Malformed, scan.firstDataLine,
                                 columnsText(scan.sample.columns) + ", but a point needs at least x, y and z");
            m_layout = detectLayout(scan.sample);
        }
    }
    m_unitColors = detectColorScale(m_layout, scan.sample) == ColorScale::Unit;

    std::size_t normal = 0, color = 0;
    for (std::size_t c = 0; c < m_layout.columnCount(); ++c) {
        switch (m_layout.roles[c]) {
        case ColumnRole::X: m_position[0] = c; break;
        case ColumnRole::Y: m_position[1] = c; break;
        case ColumnRole::Z: m_position[2] = c; break;
        case ColumnRole::NormalX: m_normal[0] = c; ++normal; break;
        case ColumnRole::NormalY: m_normal[1] = c; ++normal; break;
        case ColumnRole::NormalZ: m_normal[2] = c; ++normal; break;
        case ColumnRole::Red: m_color[0] = c; ++color; break;
        case ColumnRole::Green: m_color[1] = c; ++color; break;
        case ColumnRole::Blue: m_color[2] = c; ++color; break;
        case ColumnRole::Scalar: m_scalarColumns.push_back(c); break;
        case ColumnRole::Skip: break;
        }
    }
    assert((normal == 0 || normal == 3) && (color == 0 || color == 3));
    m_values.assign(m_layout.columnCount(), 0.0);
    return {};
}

Status TextReader::startBlock(std::uint64_t count)
{
    if (m_blockCount && m_blockPoints < *m_blockCount)
        return lineError(ErrorCode::Truncated, m_line,
                         "a new block starts after only " + std::to_string(m_blockPoints) + " of the " +
                             std::to_string(*m_blockCount) + " points announced at line " +
                             std::to_string(m_blockLine));
    if (m_line != m_firstCountLine) m_header.declaredPoints = m_header.declaredPoints.value_or(0) + count;
    m_blockCount = count;
    m_blockLine = m_line;
    m_blockPoints = 0;
    return {};
}

Status TextReader::finish()
{
    m_finished = true;
    if (m_file.ioError()) return fail(ErrorCode::Unreadable, "byte " + std::to_string(m_file.offset()), "a read failed");
    if (m_blockCount && m_blockPoints < *m_blockCount)
        return lineError(ErrorCode::Truncated, m_line,
                         "the file ends after " + std::to_string(m_blockPoints) + " of the " +
                             std::to_string(*m_blockCount) + " points announced at line " +
                             std::to_string(m_blockLine));
    return {};
}

Result<std::size_t> TextReader::read(PointBatch& batch, std::size_t maxPoints)
{
    assert(maxPoints > 0 && "TextReader::read(): maxPoints must be positive");
    const PointSchema& schema = m_header.schema;
    batch.reset(schema, std::min(maxPoints, batchReserve));
    if (m_finished) return std::size_t(0);

    const std::size_t columns = m_values.size();
    double* const values = m_values.data();
    std::size_t n = 0;
    std::string_view line;
    while (n < maxPoints) {
        if (!m_file.readLine(line)) {
            if (auto status = finish(); !status) return status.error();
            break;
        }
        ++m_line;
        if (m_file.lineTooLong()) return lineError(ErrorCode::Malformed, m_line, "the line is longer than 64 MiB");
        if (m_line == 1) line = withoutBom(line);
        const char* p = line.data();
        const char* const end = p + line.size();
        while (p < end && (*p == ' ' || *p == '\t')) ++p;
        if (p == end || *p == '#' || (*p == '/' && p + 1 < end && p[1] == '/') || m_line == m_headerLine) continue;

        const FieldScan scan = parseFields(std::string_view(p, std::size_t(end - p)), m_separator, values, columns);
        if (scan.count != columns) {
            std::uint64_t count = 0;
            if (scan.count == 1 && parseCountLine(line, count)) {
                if (auto status = startBlock(count); !status) return status.error();
                continue;
            }
            return lineError(ErrorCode::Malformed, m_line,
                             columnsText(scan.count) + " where " + std::to_string(columns) + " are expected (" + m_layout.describe() + ")");
        }
        if (scan.badField != 0) return lineError(ErrorCode::Malformed, m_line, fieldProblem(scan));
        if (m_blockCount) {
            if (m_blockPoints == *m_blockCount)
                return lineError(ErrorCode::Malformed, m_line,
                                 "more points than the " + std::to_string(*m_blockCount) + " announced at line " +
                                     std::to_string(m_blockLine));
            ++m_blockPoints;
        }

        const double x = values[m_position[0]], y = values[m_position[1]], z = values[m_position[2]];
        if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z))) {
            ++m_pointsSkipped;
            continue;
        }
        batch.positions.push_back(x);
        batch.positions.push_back(y);
        batch.positions.push_back(z);
        if (schema.hasNormals)
            for (const std::size_t c : m_normal) batch.normals.push_back(static_cast<float>(values[c]));
        if (schema.hasColors)
            for (const std::size_t c : m_color) batch.colors.push_back(colorToByte(values[c], m_unitColors));
        for (std::size_t s = 0; s < m_scalarColumns.size(); ++s) batch.scalars[s].push_back(values[m_scalarColumns[s]]);
        ++n;
    }
    m_pointsRead += n;
    return n;
}

} // namespace stylos::core::io
