#pragma once
/** @file
 * @brief A batch of points as parallel arrays (structure of arrays), the unit every reader yields.
 *        Positions are in double (site and museum frames have large coordinates), in metres or the
 *        file's own units; normals are unit float vectors; colours 8-bit RGB; extra scalars (intensity,
 *        scan id, GPS time...) are double columns named in the schema.
 */
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace stylos::core::io {

/** @brief Which attributes a point source provides besides the position. */
struct PointSchema {
    bool hasNormals = false;
    bool hasColors = false;
    std::vector<std::string> scalarNames;  ///< extra per-point values, in column order

    bool operator==(const PointSchema&) const = default;
    /** Attribute names as `info` lists them: "normal", "color", then the scalar names. */
    std::vector<std::string> attributeNames() const;
};

/** @brief Up to a few tens of thousands of points; arrays are empty for absent attributes. */
struct PointBatch {
    std::vector<double> positions;                 ///< x y z interleaved, size 3n
    std::vector<float> normals;                    ///< nx ny nz interleaved, size 3n or 0
    std::vector<std::uint8_t> colors;              ///< r g b interleaved, size 3n or 0
    std::vector<std::vector<double>> scalars;      ///< one column per schema scalar, each size n

    std::size_t size() const { return positions.size() / 3; }
    bool empty() const { return positions.empty(); }

    /** Empties the batch and shapes it for @p schema, reserving @p capacity points. */
    void reset(const PointSchema& schema, std::size_t capacity);
    /** Appends every point of @p other, which must have the same shape (same schema). */
    void append(const PointBatch& other);
    /** Removes the last point (all its attributes); used when a point proves non-finite. */
    void popBack();
};

} // namespace stylos::core::io
