#include "stylos/core/view/SplatBuffer.h"

#include "stylos/core/octree/PoctWriter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

namespace stylos::core::view {

namespace oct = octree;

namespace {

std::int8_t toSnorm8(float v) { return static_cast<std::int8_t>(std::lround(std::clamp(v, -1.0f, 1.0f) * 127.0f)); }

std::uint8_t toUnorm8(float v)
{
    if (!std::isfinite(v)) return 0;
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

} // namespace

std::uint64_t firstLeafOf(const oct::PackedOctree& octree, int level, std::uint64_t index)
{
    for (; level < octree.depth(); ++level) index = octree.firstChild(level, index);
    return index;
}

SplatBuffer makeSplatBuffer(const oct::PackedOctree& octree, const oct::CutResult& cut, std::uint64_t seed)
{
    SplatBuffer out;
    out.origin = octree.box().origin;
    out.budgetReached = cut.budgetReached;
    out.deepestLevel = cut.deepestLevel;

    const std::uint64_t leaves = octree.cellCount(octree.depth());
    std::span<const std::uint8_t> colours;
    if (auto layer = octree.attribute("colour");
        layer && layer->type == oct::AttributeType::UInt8 && layer->components == 3 && layer->bytes.size() == 3 * leaves)
        colours = layer->bytes;
    std::span<const std::uint8_t> ambient;
    if (auto layer = octree.attribute("ambient");
        layer && layer->type == oct::AttributeType::Float32 && layer->components == 1 && layer->bytes.size() == 4 * leaves)
        ambient = layer->bytes;
    out.hasColour = !colours.empty();
    out.hasAmbient = !ambient.empty();

    out.vertices.resize(cut.cells.size());
    for (std::size_t i = 0; i < cut.cells.size(); ++i) {
        const oct::CutCell& c = cut.cells[i];
        SplatVertex& v = out.vertices[i];
        v.position = c.centre;
        const std::uint64_t leaf = firstLeafOf(octree, c.level, c.index);
        v.size = std::max(c.size, 2.0f * octree.leafSpacing(leaf)); // a disc of radius h reaches its neighbours
        v.normal = {toSnorm8(c.normal[0]), toSnorm8(c.normal[1]), toSnorm8(c.normal[2]), 0};
        v.colour = {255, 255, 255, 255};
        if (!colours.empty()) {
            v.colour[0] = colours[3 * leaf];
            v.colour[1] = colours[3 * leaf + 1];
            v.colour[2] = colours[3 * leaf + 2];
        }
        if (!ambient.empty()) {
            float a = 0;
            std::memcpy(&a, ambient.data() + 4 * leaf, 4); // little-endian file, little-endian host
            v.colour[3] = toUnorm8(a);
        }
    }
    if (seed != 0) std::shuffle(out.vertices.begin(), out.vertices.end(), std::mt19937_64(seed));
    return out;
}

} // namespace stylos::core::view
