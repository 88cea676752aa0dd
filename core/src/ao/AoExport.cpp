// Writing the skydome's per-leaf values: the "ambient" layer of a .poct, or a PLY of the leaf centres.
#include "stylos/core/ao/AoExport.h"

#include "stylos/core/octree/LeafPly.h"

#include <cstring>
#include <string>
#include <system_error>
#include <vector>

namespace stylos::core::ao {

namespace {

namespace fs = std::filesystem;

std::uint64_t leafCount(const octree::PackedOctree& octree) { return octree.cellCount(octree.depth()); }

/** InvalidArgument naming @p output when @p perLeaf does not hold one value per leaf. */
Status checkCount(const octree::PackedOctree& octree, std::span<const float> perLeaf, const fs::path& output)
{
    if (perLeaf.size() == leafCount(octree)) return {};
    return Error::at(ErrorCode::InvalidArgument, output.string(), "",
                     std::to_string(perLeaf.size()) + " ambient values for an octree of " +
                         std::to_string(leafCount(octree)) + " leaves (" + octree.path().string() + ")");
}

/** Whether @p output is the file the octree was opened from (false for an octree held in memory). */
bool isSameFile(const octree::PackedOctree& octree, const fs::path& output)
{
    std::error_code error;
    const bool same = fs::equivalent(octree.path(), output, error);
    return same && !error;
}

} // namespace

octree::AttributeLayer ambientLayer(std::span<const float> perLeaf)
{
    static_assert(sizeof(float) == 4, "the layer stores IEEE-754 binary32");
    octree::AttributeLayer layer;
    layer.name = AmbientLayerName;
    layer.type = octree::AttributeType::Float32;
    layer.components = 1;
    layer.bytes.resize(perLeaf.size() * sizeof(float));
    if (!perLeaf.empty()) std::memcpy(layer.bytes.data(), perLeaf.data(), layer.bytes.size()); // little-endian host
    return layer;
}

Result<std::uint64_t> writeAmbientPoct(const octree::PackedOctree& octree, std::span<const float> perLeaf,
                                       const fs::path& output, ProgressSink* progress)
{
    if (auto s = checkCount(octree, perLeaf, output); !s) return s.error();
    octree::AttributeLayer ambient = ambientLayer(perLeaf);
    if (isSameFile(octree, output)) return octree::setPoctAttributeLayer(output, ambient);

    // The other layers, in file order; "colour" travels with the cells (levels().description().hasColour).
    std::vector<octree::AttributeLayer> layers;
    bool placed = false;
    for (const octree::AttributeView& view : octree.attributes()) {
        if (view.name == "colour") continue;
        if (view.name == AmbientLayerName) {
            layers.push_back(std::move(ambient));
            placed = true;
            continue;
        }
        layers.push_back({view.name, view.type, view.components, {view.bytes.begin(), view.bytes.end()}});
    }
    if (!placed) layers.push_back(std::move(ambient));
    return octree::writePoct(octree.levels(), output, layers, progress);
}

Result<std::uint64_t> writeAmbientPly(const octree::PackedOctree& octree, std::span<const float> perLeaf,
                                      const fs::path& output, ProgressSink* progress)
{
    if (auto s = checkCount(octree, perLeaf, output); !s) return s.error();
    return octree::writeLeafPly(octree,
                                {{AmbientLayerName, io::PlyScalarType::Float32,
                                  [perLeaf](std::uint64_t leaf) { return double(perLeaf[leaf]); }}},
                                "stylos ambient occlusion: one vertex per leaf centre of an octree of depth " +
                                    std::to_string(octree.depth()),
                                output, progress);
}

} // namespace stylos::core::ao
