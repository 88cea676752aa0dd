#pragma once
/** @file
 * @brief What the workbench knows about one loaded point file without keeping its points: format,
 *        counts, bounds and attribute names. Plain data, copied between threads by value.
 */
#include <QMetaType>
#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>

namespace stylos::widgets {

struct ScanSummary {
    QString path;             ///< absolute path of the file
    QString format;           ///< the reader's format name, e.g. "ply-binary-le", "las-1.2", "xyz"
    std::uint64_t points = 0; ///< points delivered (finite coordinates)
    std::uint64_t skipped = 0;///< points skipped because a coordinate was NaN or infinite
    /** Exact axis-aligned bounds of the points read, in file units: min x, y, z then max x, y, z
     *  (all 0 when there are no points). */
    std::array<double, 6> bounds{};
    QStringList attributes;   ///< "normal", "color", then scalar names

    bool hasBounds() const { return points > 0; }
    /** Extent along x, y, z (0 when empty). */
    std::array<double, 3> size() const
    {
        if (!hasBounds()) return {0.0, 0.0, 0.0};
        return {bounds[3] - bounds[0], bounds[4] - bounds[1], bounds[5] - bounds[2]};
    }
};

} // namespace stylos::widgets

Q_DECLARE_METATYPE(stylos::widgets::ScanSummary)
