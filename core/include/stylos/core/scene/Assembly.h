#pragma once
/** @file
 * @brief An assembly: a group of fragments placed together, e.g. "Drum 1 reconstruction" — the fragments
 *        of a ruined drum docked against the guides of an intact one. It has its own pose (assembly frame
 *        → scene frame); each member fragment's pose is relative to it, so moving the assembly moves its
 *        fragments. It may name the drum (a fragment, in the assembly or not) whose guides its fragments
 *        dock against. Plain data. Units: metres. Thread-safety: a value type.
 */
#include "stylos/core/scene/Fragment.h"
#include "stylos/core/scene/Pose.h"

#include <cstdint>
#include <string>

namespace stylos::core::scene {

/** @brief An assembly's identity: stable across edits, undo and save; never reused; ids start at 1. */
using AssemblyId = std::uint64_t;
/** @brief "No assembly": a fragment at the top level of the scene. */
inline constexpr AssemblyId NoAssembly = 0;

struct Assembly {
    AssemblyId id = NoAssembly;
    std::string name;
    Pose pose;                     ///< assembly frame → scene frame, rigid
    FragmentId drum = NoFragment;  ///< the drum whose guides the members dock against; NoFragment for none
    bool visible = true;           ///< false hides every member

    bool operator==(const Assembly&) const = default;
};

} // namespace stylos::core::scene
