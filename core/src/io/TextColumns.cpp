#include "stylos/core/io/TextColumns.h"
#include "stylos/core/util/TextCase.h"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace stylos::core::io {

namespace {

inline bool isSpace(char c) { return c == ' ' || c == '\t'; }

/**
 * Exact fast path for plain decimals ("-12.345"): with at most 19 digits, a mantissa up to 2^53 and at
 * most 22 decimals, mantissa and power of ten are exact doubles and one division rounds correctly
 * (Clinger), so the result is the one from_chars gives. Anything else returns nullptr.
 */
inline const char* parsePlainDecimal(const char* p, const char* end, double& out)
{
    static constexpr double powersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const bool negative = p < end && *p == '-';
    if (p < end && (*p == '-' || *p == '+')) ++p;
    std::uint64_t mantissa = 0;
    int digits = 0;
    while (p < end && static_cast<unsigned>(*p - '0') < 10) {
        mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
        ++p, ++digits;
    }
    int decimals = 0;
    if (p < end && *p == '.') {
        ++p;
        while (p < end && static_cast<unsigned>(*p - '0') < 10) {
            mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
            ++p, ++decimals;
        }
    }
    digits += decimals;
    if (digits == 0 || digits > 19 || decimals > 22 || mantissa > (std::uint64_t(1) << 53)) return nullptr;
    if (p < end && (*p == 'e' || *p == 'E')) return nullptr; // exponents: from_chars
    const double value = static_cast<double>(mantissa) / powersOfTen[decimals];
    out = negative ? -value : value;
    return p;
}

/** One number at [p, end): past its last character, or nullptr when it is not one. */
const char* parseNumber(const char* p, const char* end, double& out)
{
    if (const char* q = parsePlainDecimal(p, end, out)) return q;
    const char* s = p;
    if (s < end && *s == '+') {
        ++s;
        if (s < end && *s == '-') return nullptr;
    }
    const auto [q, ec] = std::from_chars(s, end, out);
    if (ec == std::errc()) return q;
    if (ec == std::errc::result_out_of_range) { // 1e999 → inf, 1e-999 → 0, as strtod does
        const std::string text(s, q);
        out = std::strtod(text.c_str(), nullptr);
        return q;
    }
    return nullptr;
}

FieldScan parseWhitespace(const char* p, const char* end, double* out, std::size_t capacity)
{
    FieldScan scan;
    for (;;) {
        while (p < end && isSpace(*p)) ++p;
        if (p == end) break;
        if (scan.count < capacity && scan.badField == 0) {
            const char* q = parseNumber(p, end, out[scan.count]);
            if (q && (q == end || isSpace(*q))) {
                ++scan.count;
                p = q;
                continue;
            }
        }
        const char* q = p;
        while (q < end && !isSpace(*q)) ++q;
        if (scan.count < capacity && scan.badField == 0) {
            scan.badField = scan.count + 1;
            scan.badToken = std::string_view(p, static_cast<std::size_t>(q - p));
        }
        ++scan.count;
        p = q;
    }
    return scan;
}

FieldScan parseSeparated(const char* p, const char* end, char sep, double* out, std::size_t capacity)
{
    FieldScan scan;
    for (;;) {
        while (p < end && isSpace(*p)) ++p;
        if (p == end) break; // end of line, or one trailing separator
        const bool parse = scan.count < capacity && scan.badField == 0;
        if (parse && *p != sep) {
            const char* q = parseNumber(p, end, out[scan.count]);
            if (q) {
                const char* r = q;
                while (r < end && isSpace(*r)) ++r;
                if (r == end || *r == sep) {
                    ++scan.count;
                    if (r == end) break;
                    p = r + 1;
                    continue;
                }
            }
        }
        const char* fieldEnd = static_cast<const char*>(std::memchr(p, sep, static_cast<std::size_t>(end - p)));
        if (!fieldEnd) fieldEnd = end;
        if (parse) {
            scan.badField = scan.count + 1;
            scan.badToken = trimSpaces(std::string_view(p, static_cast<std::size_t>(fieldEnd - p)));
        }
        ++scan.count;
        if (fieldEnd == end) break;
        p = fieldEnd + 1;
    }
    return scan;
}

std::string lower(std::string_view text) { return lowerCase(text); }

Error layoutError(const std::string& problem)
{
    return Error{ErrorCode::InvalidArgument, "column layout: " + problem};
}

bool isInteger(double v) { return v == std::floor(v); }

bool isUnit(double x, double y, double z) { return std::abs(std::sqrt(x * x + y * y + z * z) - 1.0) < 0.02; }

/** Every sampled triple at @p c is a unit vector (or zero, for "no normal"), and one at least is unit. */
bool normalLike(const ColumnSample& s, std::size_t c)
{
    bool anyUnit = false;
    for (std::size_t r = 0; r < s.rows(); ++r) {
        const double x = s.at(r, c), y = s.at(r, c + 1), z = s.at(r, c + 2);
        if (isUnit(x, y, z)) anyUnit = true;
        else if (x != 0.0 || y != 0.0 || z != 0.0) return false;
    }
    return anyUnit;
}

bool allSampled(const ColumnSample& s, std::size_t c, bool (*test)(double))
{
    if (s.rows() == 0) return false;
    for (std::size_t r = 0; r < s.rows(); ++r)
        for (std::size_t k = c; k < c + 3; ++k)
            if (!test(s.at(r, k))) return false;
    return true;
}

bool isByte(double v) { return v >= 0.0 && v <= 255.0 && isInteger(v); }
bool inUnitRange(double v) { return v >= 0.0 && v <= 1.0; }

using R = ColumnRole;

} // namespace

bool ColumnLayout::has(ColumnRole role) const { return indexOf(role) >= 0; }

int ColumnLayout::indexOf(ColumnRole role) const
{
    const auto it = std::find(roles.begin(), roles.end(), role);
    return it == roles.end() ? -1 : static_cast<int>(it - roles.begin());
}

PointSchema ColumnLayout::schema() const
{
    PointSchema schema;
    schema.hasNormals = has(R::NormalX);
    schema.hasColors = has(R::Red);
    schema.scalarNames = scalarNames;
    return schema;
}

std::string ColumnLayout::describe() const
{
    static const char* const names[] = {"_", "x", "y", "z", "nx", "ny", "nz", "r", "g", "b"};
    std::string text;
    std::size_t scalar = 0;
    for (const ColumnRole role : roles) {
        if (!text.empty()) text += ' ';
        text += role == R::Scalar ? scalarNames[scalar++] : names[static_cast<int>(role)];
    }
    return text;
}

Separator detectSeparator(std::string_view line)
{
    if (line.find(';') != std::string_view::npos) return Separator::Semicolon;
    if (line.find(',') != std::string_view::npos) return Separator::Comma;
    return Separator::Whitespace;
}

FieldScan parseFields(std::string_view line, Separator separator, double* out, std::size_t capacity)
{
    const char* p = line.data();
    const char* end = p + line.size();
    switch (separator) {
    case Separator::Comma: return parseSeparated(p, end, ',', out, capacity);
    case Separator::Semicolon: return parseSeparated(p, end, ';', out, capacity);
    case Separator::Whitespace: break;
    }
    return parseWhitespace(p, end, out, capacity);
}

std::string fieldProblem(const FieldScan& scan)
{
    const std::string column = "column " + std::to_string(scan.badField);
    if (scan.badToken.empty()) return column + " is empty";
    std::string token(scan.badToken.substr(0, 40));
    if (scan.badToken.size() > 40) token += "...";
    return column + " is not a number: \"" + token + "\"";
}

std::string_view trimSpaces(std::string_view text)
{
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

std::vector<std::string_view> splitFields(std::string_view line, Separator separator)
{
    std::vector<std::string_view> fields;
    if (separator == Separator::Whitespace) {
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && isSpace(line[i])) ++i;
            const std::size_t start = i;
            while (i < line.size() && !isSpace(line[i])) ++i;
            if (i > start) fields.push_back(line.substr(start, i - start));
        }
        return fields;
    }
    const char sep = separator == Separator::Comma ? ',' : ';';
    std::size_t start = 0;
    for (;;) {
        const std::size_t at = line.find(sep, start);
        const std::string_view field = trimSpaces(line.substr(start, at == std::string_view::npos ? at : at - start));
        if (at == std::string_view::npos) {
            if (!field.empty() || fields.empty()) fields.push_back(field);
            return fields;
        }
        fields.push_back(field);
        start = at + 1;
    }
}

bool parseCountLine(std::string_view line, std::uint64_t& value)
{
    line = trimSpaces(line);
    if (line.empty()) return false;
    const auto [p, ec] = std::from_chars(line.data(), line.data() + line.size(), value);
    return ec == std::errc() && p == line.data() + line.size();
}

Result<ColumnLayout> layoutFromNames(const std::vector<std::string_view>& names)
{
    ColumnLayout layout;
    bool unitColors = false;
    for (const std::string_view raw : names) {
        std::string_view name = trimSpaces(raw);
        if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') && name.back() == name.front())
            name = name.substr(1, name.size() - 2); // quoted CSV names
        const std::string n = lower(name);
        ColumnRole role = R::Scalar;
        if (n.empty()) return layoutError("an empty column name");
        if (n == "_") role = R::Skip;
        else if (n == "x") role = R::X;
        else if (n == "y") role = R::Y;
        else if (n == "z") role = R::Z;
        else if (n == "nx" || n == "normal_x" || n == "normalx") role = R::NormalX;
        else if (n == "ny" || n == "normal_y" || n == "normaly") role = R::NormalY;
        else if (n == "nz" || n == "normal_z" || n == "normalz") role = R::NormalZ;
        else if (n == "r" || n == "red") role = R::Red;
        else if (n == "g" || n == "green") role = R::Green;
        else if (n == "b" || n == "blue") role = R::Blue;
        else if (n == "rf") role = R::Red, unitColors = true;
        else if (n == "gf") role = R::Green, unitColors = true;
        else if (n == "bf") role = R::Blue, unitColors = true;

        if (role == R::Scalar) {
            const std::string scalar = (n == "i" || n == "intensity") ? std::string("intensity") : std::string(name);
            if (std::find(layout.scalarNames.begin(), layout.scalarNames.end(), scalar) != layout.scalarNames.end())
                return layoutError("the column \"" + scalar + "\" is named twice");
            layout.scalarNames.push_back(scalar);
        } else if (role != R::Skip && layout.has(role)) {
            return layoutError("the column \"" + n + "\" is named twice");
        }
        layout.roles.push_back(role);
    }
    if (!layout.has(R::X) || !layout.has(R::Y) || !layout.has(R::Z))
        return layoutError("x, y and z must all be named (got \"" + layout.describe() + "\")");
    const int normals = layout.has(R::NormalX) + layout.has(R::NormalY) + layout.has(R::NormalZ);
    if (normals != 0 && normals != 3) return layoutError("a normal needs all of nx, ny and nz");
    const int colors = layout.has(R::Red) + layout.has(R::Green) + layout.has(R::Blue);
    if (colors != 0 && colors != 3) return layoutError("a colour needs all of r, g and b");
    if (unitColors) layout.colorScale = ColorScale::Unit;
    return layout;
}

Result<ColumnLayout> layoutFromOverride(std::string_view spec)
{
    const Separator sep = spec.find(',') != std::string_view::npos ? Separator::Comma : Separator::Whitespace;
    return layoutFromNames(splitFields(spec, sep));
}

ColumnLayout detectLayout(const ColumnSample& sample)
{
    assert(sample.columns >= 3 && "detectLayout(): a point needs at least 3 columns");
    ColumnLayout layout;
    layout.roles = {R::X, R::Y, R::Z};
    const auto addTriple = [&](R a, R b, R c) {
        layout.roles.push_back(a);
        layout.roles.push_back(b);
        layout.roles.push_back(c);
    };
    const auto addNormals = [&] { addTriple(R::NormalX, R::NormalY, R::NormalZ); };
    const auto addColors = [&] { addTriple(R::Red, R::Green, R::Blue); };
    const auto addIntensity = [&] {
        layout.roles.push_back(R::Scalar);
        layout.scalarNames.emplace_back("intensity");
    };

    switch (sample.columns) {
    case 3: break;
    case 4: addIntensity(); break;
    case 6:
        if (normalLike(sample, 3)) {
            addNormals();
        } else if (allSampled(sample, 3, isByte)) {
            addColors();
            layout.colorScale = ColorScale::Byte;
        } else if (allSampled(sample, 3, inUnitRange)) {
            addColors();
            layout.colorScale = ColorScale::Unit;
        } else {
            addNormals();
        }
        break;
    case 7:
        addIntensity();
        addColors();
        break;
    case 9: {
        const bool normalsFirst = normalLike(sample, 3)   ? true
                                  : normalLike(sample, 6) ? false
                                                          : !allSampled(sample, 3, isByte);
        if (normalsFirst) addNormals(), addColors();
        else addColors(), addNormals();
        break;
    }
    default:
        for (std::size_t c = 3; c < sample.columns; ++c) {
            layout.roles.push_back(R::Scalar);
            layout.scalarNames.push_back("scalar_" + std::to_string(c + 1));
        }
    }
    return layout;
}

ColorScale detectColorScale(const ColumnLayout& layout, const ColumnSample& sample)
{
    if (layout.colorScale != ColorScale::Detect) return layout.colorScale;
    const int r = layout.indexOf(R::Red), g = layout.indexOf(R::Green), b = layout.indexOf(R::Blue);
    if (r < 0 || sample.rows() == 0 || sample.columns != layout.columnCount()) return ColorScale::Byte;
    bool fractional = sample.fractional[r] || sample.fractional[g] || sample.fractional[b];
    for (std::size_t row = 0; row < sample.rows(); ++row) {
        for (const int c : {r, g, b}) {
            const double v = sample.at(row, static_cast<std::size_t>(c));
            if (!inUnitRange(v)) return ColorScale::Byte;
            if (!isInteger(v)) fractional = true;
        }
    }
    return fractional ? ColorScale::Unit : ColorScale::Byte;
}

} // namespace stylos::core::io
