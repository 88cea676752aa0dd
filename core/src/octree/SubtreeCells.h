#pragma once
// Internal to the construction octree: the cells of one subtree gathered level by level while it is pulled
// (pullAndVisitLevels), in breadth-first order within the subtree — the order in which its pull enters the
// tables of each level. Masks are taken when a table is entered, normals once it is pulled.
#include "stylos/core/octree/ConstructionOctree.h"

#include <cstring>
#include <vector>

namespace stylos::core::octree {

struct ConstructionOctree::SubtreeCells {
    int top = 0;                                      ///< level of the subtree's root
    int depth = 0;                                    ///< the leaf level
    bool colour = false;
    std::vector<std::vector<std::uint8_t>> masks;     ///< [level − top], inner levels
    std::vector<std::vector<std::uint16_t>> normals;  ///< [level − top]
    std::vector<std::uint8_t> colours;                ///< leaf level, r g b per leaf

    /** Empties it for a subtree rooted at @p rootLevel (the vectors keep their memory). */
    void reset(int rootLevel, int leafLevel, bool hasColour)
    {
        top = rootLevel;
        depth = leafLevel;
        colour = hasColour;
        masks.resize(std::size_t(depth - top + 1));
        normals.resize(std::size_t(depth - top + 1));
        for (auto& m : masks) m.clear();
        for (auto& n : normals) n.clear();
        colours.clear();
    }
    /** Places the table of @p count inner cells from @p first at @p level; returns its position there. */
    std::size_t reserve(int level, const CellArena& arena, std::uint32_t first, unsigned count)
    {
        auto& m = masks[std::size_t(level - top)];
        const std::size_t at = m.size();
        m.resize(at + count);
        normals[std::size_t(level - top)].resize(at + count);
        for (unsigned i = 0; i < count; ++i) m[at + i] = cell::mask(arena.cell(first + i));
        return at;
    }
    /** The pulled normals of the table placed at @p at. */
    void setNormals(int level, std::size_t at, const CellArena& arena, std::uint32_t first, unsigned count)
    {
        std::uint16_t* n = normals[std::size_t(level - top)].data() + at;
        for (unsigned i = 0; i < count; ++i) n[i] = cell::normal(arena.cell(first + i));
    }
    /** A table of @p count leaves from @p first. */
    void addLeaves(const CellArena& arena, std::uint32_t first, unsigned count)
    {
        auto& n = normals[std::size_t(depth - top)];
        for (unsigned i = 0; i < count; ++i) n.push_back(cell::normal(arena.cell(first + i)));
        if (colour)
            for (unsigned i = 0; i < count; ++i) {
                const std::uint8_t* rgb = cell::colour(static_cast<const std::uint8_t*>(arena.cell(first + i)));
                colours.insert(colours.end(), rgb, rgb + 3);
            }
    }
};

} // namespace stylos::core::octree
