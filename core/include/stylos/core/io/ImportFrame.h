#pragma once
/** @file
 * @brief The import frame: how the points of a scan are brought into Stylos's frame (Z up, metres) as they
 *        are read. Three parts, applied in this order to a position p of the file:
 *
 *            p' = R · ((p − offset) / unitsPerMetre)
 *
 *        - **offset**: subtracted first, in the file's own coordinates and units (a site's large easting and
 *          northing, say); zero by default;
 *        - **unit**: the file's length unit, mm, cm or m; a coordinate is divided by 1000, 100 or 1, so that
 *          1234 mm becomes the double nearest to 1.234 m;
 *        - **up axis**: the file's axis that points up (+X, −X, +Y, −Y, +Z, −Z), turned onto +Z by a proper
 *          rotation R (det +1, a quarter or half turn; no mirror):
 *
 *              up   R (x, y, z) =      turn                        the other axes
 *              +Z   ( x,  y,  z)       none                        unchanged
 *              −Z   ( x, −y, −z)       half turn about X           X kept, Y → −Y
 *              +Y   ( x, −z,  y)       quarter turn about X        X kept, +Z (the front) → −Y
 *              −Y   ( x,  z, −y)       quarter turn about X back   X kept, +Z → +Y
 *              +X   (−z,  y,  x)       quarter turn about Y        Y kept, +Z → −X
 *              −X   ( z,  y, −x)       quarter turn about Y back   Y kept, +Z → +X
 *
 *        Normals are rotated by R and neither scaled nor offset. R only swaps and negates components, so it
 *        is exact in float and double, and a box maps onto a box.
 *
 *        Names: upAxisName() gives "+X" … "-Z"; upAxisFromName() also takes "x" for "+X", any case, and the
 *        Unicode minus "−". Units: "mm", "cm", "m". Pure functions and a value type; thread-safe.
 */
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace stylos::core::io {

enum class UpAxis { PosX, NegX, PosY, NegY, PosZ, NegZ };
enum class LengthUnit { Millimetre, Centimetre, Metre };

/** @brief "+X", "-X", "+Y", "-Y", "+Z" or "-Z" (the project file's and the CLI's words). */
const char* upAxisName(UpAxis axis);
/** @brief The inverse of upAxisName(), also "x"/"X" for "+X", any case, "−" (U+2212) for "-"; else nullopt. */
std::optional<UpAxis> upAxisFromName(std::string_view name);
/** @brief "mm", "cm" or "m". */
const char* lengthUnitName(LengthUnit unit);
/** @brief The inverse of lengthUnitName(), any case; nullopt for anything else. */
std::optional<LengthUnit> lengthUnitFromName(std::string_view name);
/** @brief 1000, 100 or 1. */
double unitsPerMetre(LengthUnit unit);

/** @brief "+X, -X, +Y, -Y, +Z or -Z" and "mm, cm or m", for messages. */
std::string upAxisChoices();
std::string lengthUnitChoices();

struct ImportFrame {
    UpAxis up = UpAxis::PosZ;
    LengthUnit unit = LengthUnit::Metre;
    std::array<double, 3> offset{0.0, 0.0, 0.0};  ///< in the file's coordinates and units, subtracted first

    /** @brief Z up, metres, no offset: the reader's points pass unchanged. */
    bool isIdentity() const;
    /** @brief R, row-major 3×3 (entries 0, 1 or −1; det +1). */
    std::array<double, 9> rotation() const;

    /** @brief One position of the file into the corrected frame (see the file comment). */
    std::array<double, 3> applyToPosition(const std::array<double, 3>& p) const;
    /** @brief One normal, rotated only. */
    std::array<float, 3> applyToNormal(const std::array<float, 3>& n) const;
    /** @brief @p count interleaved positions (x y z …) in place. */
    void applyToPositions(double* xyz, std::size_t count) const;
    /** @brief @p count interleaved normals in place. */
    void applyToNormals(float* xyz, std::size_t count) const;
    /** @brief The box [min, max] of the file mapped to the corrected frame (exact: R maps boxes to boxes). */
    void applyToBounds(std::array<double, 3>& min, std::array<double, 3>& max) const;

    bool operator==(const ImportFrame&) const = default;
};

} // namespace stylos::core::io
