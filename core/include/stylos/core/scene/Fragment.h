#pragma once
/** @file
 * @brief One fragment of a scene: a packed octree (`.poct`) placed in the scene by a rigid pose, with a
 *        name, a display colour and visibility, plus what fragment docking and annotation will need:
 *        guides (named axes and grooves in the fragment's own frame) and the name of the octree's
 *        attribute layer that holds its annotation classes (marble, fractured marble, plaster…).
 *        Plain data: it never draws and never opens its octree. Units: metres, radians.
 *        Thread-safety: a value type.
 */
#include "stylos/core/io/ImportFrame.h"
#include "stylos/core/scene/Pose.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::scene {

/** @brief A fragment's identity within its scene: stable across edits, undo and save; never reused. */
using FragmentId = std::uint64_t;
/** @brief "No fragment" (ids start at 1). */
inline constexpr FragmentId NoFragment = 0;

/** @brief A display colour, 8 bits per channel, sRGB. */
struct Rgb {
    std::uint8_t r = 200;
    std::uint8_t g = 200;
    std::uint8_t b = 200;

    /** @brief "#rrggbb", lower-case. */
    std::string toHex() const;
    /** @brief Parses "#rrggbb" (either case); nullopt for anything else. */
    static std::optional<Rgb> fromHex(std::string_view text);

    bool operator==(const Rgb&) const = default;
};

/** @brief What a guide stands for. */
enum class GuideKind {
    Axis,    ///< the axis of a drum or column (e.g. fitted by least squares)
    Groove,  ///< a flute, parallel to the axis
};

/** @brief "axis" or "groove" (the project file's words). */
const char* guideKindName(GuideKind kind);
/** @brief The inverse of guideKindName(); nullopt for an unknown word. */
std::optional<GuideKind> guideKindFromName(std::string_view name);

/** @brief A named line in the fragment's own frame (metres); the direction is a unit vector. */
struct Guide {
    std::string name;
    GuideKind kind = GuideKind::Axis;
    std::array<double, 3> origin{};
    std::array<double, 3> direction{0.0, 0.0, 1.0};

    bool operator==(const Guide&) const = default;
};

struct Fragment {
    FragmentId id = NoFragment;
    std::string name;
    std::filesystem::path octreePath;   ///< the `.poct`, absolute in memory (relative only in the file)
    std::filesystem::path sourcePath;   ///< the scan it was built from, absolute; empty when opened as a .poct
    Pose pose;                          ///< fragment frame → its assembly's frame (the scene's when none), rigid
    std::uint64_t assembly = 0;         ///< the AssemblyId it belongs to (Assembly.h); 0: the scene's top level
    Rgb colour;
    bool visible = true;
    std::vector<Guide> guides;          ///< in the fragment's frame, in display order
    std::string annotationLayer;        ///< `.poct` attribute layer with the annotation classes; "" for none
    /** How the scan was brought into the octree's frame on import (up axis, unit, offset): a record of
     *  what the `.poct` already holds, kept so that a rebuild from the source gives the same octree. */
    io::ImportFrame importFrame;
    /** The octree file was not found (or could not be opened) when the project was loaded. Runtime
     *  state, never saved. */
    bool octreeMissing = false;

    bool operator==(const Fragment&) const = default;
};

/** @brief The colour given to the @p index-th new fragment: a short palette of muted, distinct hues. */
Rgb defaultFragmentColour(std::size_t index);

} // namespace stylos::core::scene
