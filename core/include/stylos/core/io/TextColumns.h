#pragma once
/** @file
 * @brief The pieces of text-point parsing that do not touch a file: splitting a line into numbers,
 *        naming columns (an override string or a header line) and guessing the column layout from
 *        the first data lines. Used by TextReader and ObjReader. Pure functions, thread-safe.
 */
#include "stylos/core/io/PointBatch.h"
#include "stylos/core/util/Result.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::io {

/** @brief What one column of a text point file holds. */
enum class ColumnRole : std::uint8_t { Skip, X, Y, Z, NormalX, NormalY, NormalZ, Red, Green, Blue, Scalar };

/** @brief How colour values are written: detected from the data, 0–255, or floats in [0, 1]. */
enum class ColorScale : std::uint8_t { Detect, Byte, Unit };

/** @brief Column roles of a text file, one per column, in file order. */
struct ColumnLayout {
    std::vector<ColumnRole> roles;
    std::vector<std::string> scalarNames; ///< names of the Scalar columns, in column order
    ColorScale colorScale = ColorScale::Detect;

    std::size_t columnCount() const { return roles.size(); }
    bool has(ColumnRole role) const;
    /** Column index of @p role (the first one); -1 when absent. */
    int indexOf(ColumnRole role) const;
    /** The schema points read with this layout have. */
    PointSchema schema() const;
    /** "x y z nx ny nz" style description, for messages and tests. */
    std::string describe() const;
};

/** @brief How the fields of a line are separated. */
enum class Separator : std::uint8_t { Whitespace, Comma, Semicolon };

/** Separator of a data or header line: ';' if present, else ',' if present, else spaces/tabs. */
Separator detectSeparator(std::string_view line);

/** @brief Outcome of splitting a line into numbers. */
struct FieldScan {
    std::size_t count = 0;          ///< fields on the line (all of them, even beyond the capacity)
    std::size_t badField = 0;       ///< 1-based index of the first field that is not a number; 0: none
    std::string_view badToken;      ///< that field's text
};

/**
 * @brief Parses the fields of @p line as doubles into @p out (at most @p capacity of them; later
 *        fields are only counted). Accepts a leading '+', "nan", "inf" and "infinity" (any case).
 *        Spaces and tabs around fields are ignored; with ',' or ';' one trailing separator is tolerated.
 *        No allocation.
 */
FieldScan parseFields(std::string_view line, Separator separator, double* out, std::size_t capacity);

/** "column N is not a number: \"abc\"" (or "is empty") for a scan with a bad field. */
std::string fieldProblem(const FieldScan& scan);

/** Splits a header line into its names (no allocation beyond the vector). */
std::vector<std::string_view> splitFields(std::string_view line, Separator separator);

/** True when @p line, once trimmed, is a non-negative integer (a Leica PTS count line); sets @p value. */
bool parseCountLine(std::string_view line, std::uint64_t& value);

/** Trims spaces and tabs at both ends. */
std::string_view trimSpaces(std::string_view text);

/**
 * @brief Layout from column names: x y z, nx ny nz (or normal_x...), r g b / red green blue (colour,
 *        scale detected), rf gf bf (colour as floats in [0, 1]), i / intensity (scalar "intensity"),
 *        "_" (skipped), any other name a scalar of that name. Case-insensitive.
 * @return InvalidArgument naming the problem when x, y or z is missing or repeated, a normal or colour
 *         triple is incomplete, or a name is empty.
 */
Result<ColumnLayout> layoutFromNames(const std::vector<std::string_view>& names);

/** Layout from ReadOptions::columns, e.g. "x,y,z,i,r,g,b" (commas or spaces). Errors as layoutFromNames. */
Result<ColumnLayout> layoutFromOverride(std::string_view spec);

/** @brief The first data lines of a file, kept to guess its layout and colour scale. */
struct ColumnSample {
    std::size_t columns = 0;
    std::vector<double> values;     ///< rows × columns, only rows whose values are all finite
    std::vector<char> fractional;   ///< per column: some field was written with '.' or an exponent

    std::size_t rows() const { return columns == 0 ? 0 : values.size() / columns; }
    double at(std::size_t row, std::size_t column) const { return values[row * columns + column]; }
};

/**
 * @brief Guesses the layout from the column count and the sample: 3 → x y z; 4 → x y z intensity;
 *        6 → x y z r g b when columns 4–6 are integers in 0..255 (and not all unit vectors), else
 *        x y z nx ny nz; 7 → x y z intensity r g b (PTS); 9 → x y z + normals and colours, in the order
 *        that makes the normal triple unit-length; other counts → x y z then scalar_4, scalar_5...
 *        Needs at least 3 columns (assertion).
 */
ColumnLayout detectLayout(const ColumnSample& sample);

/**
 * @brief Colour scale from the sample: Unit when every sampled colour lies in [0, 1] and some is
 *        fractional or written with a decimal point; Byte otherwise. Keeps an explicit scale.
 */
ColorScale detectColorScale(const ColumnLayout& layout, const ColumnSample& sample);

/** Colour value to 8 bits: scaled by 255 when @p unit, rounded, clamped to 0..255 (NaN gives 0). */
inline std::uint8_t colorToByte(double value, bool unit)
{
    if (unit) value *= 255.0;
    if (!(value > 0.0)) return 0;
    if (value >= 255.0) return 255;
    return static_cast<std::uint8_t>(value + 0.5);
}

} // namespace stylos::core::io
