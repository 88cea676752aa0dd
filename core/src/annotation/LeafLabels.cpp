// Per-leaf annotation labels as UInt8 attribute layers of a .poct.
#include "stylos/core/annotation/LeafLabels.h"

#include <algorithm>
#include <string>
#include <system_error>

namespace stylos::core::annotation {

namespace {

namespace fs = std::filesystem;

bool isSameFile(const octree::PackedOctree& octree, const fs::path& output)
{
    std::error_code error;
    const bool same = fs::equivalent(octree.path(), output, error);
    return same && !error;
}

} // namespace

Result<std::vector<std::uint8_t>> readLeafLabels(const octree::PackedOctree& octree, AnnotationLayer layer)
{
    const std::uint64_t leaves = leafCount(octree);
    const auto view = octree.attribute(layerName(layer));
    if (!view) return std::vector<std::uint8_t>(leaves, 0);
    if (view->type != octree::AttributeType::UInt8 || view->components != 1 || view->bytes.size() != leaves)
        return Error::at(ErrorCode::Malformed, octree.path().string(), std::string("layer \"") + layerName(layer) + "\"",
                         "not one byte per leaf (" + std::to_string(view->bytes.size()) + " bytes, " +
                             std::to_string(leaves) + " leaves)");
    return std::vector<std::uint8_t>(view->bytes.begin(), view->bytes.end());
}

octree::AttributeLayer labelAttribute(AnnotationLayer layer, std::span<const std::uint8_t> labels)
{
    return {layerName(layer), octree::AttributeType::UInt8, 1, {labels.begin(), labels.end()}};
}

Result<std::uint64_t> writeAttributePoct(const octree::PackedOctree& octree, octree::AttributeLayer attribute,
                                         const fs::path& output, ProgressSink* progress)
{
    if (isSameFile(octree, output)) return octree::setPoctAttributeLayer(output, attribute);
    std::vector<octree::AttributeLayer> layers;
    bool placed = false;
    for (const octree::AttributeView& view : octree.attributes()) {
        if (view.name == "colour") continue; // travels with the cells (description().hasColour)
        if (view.name == attribute.name) {
            layers.push_back(std::move(attribute));
            placed = true;
            continue;
        }
        layers.push_back({view.name, view.type, view.components, {view.bytes.begin(), view.bytes.end()}});
    }
    if (!placed) layers.push_back(std::move(attribute));
    return octree::writePoct(octree.levels(), output, layers, progress);
}

Result<std::uint64_t> writeAttributesPoct(const octree::PackedOctree& octree,
                                          std::vector<octree::AttributeLayer> attributes, const fs::path& output,
                                          ProgressSink* progress)
{
    std::vector<octree::AttributeLayer> layers;
    for (const octree::AttributeView& view : octree.attributes()) {
        if (view.name == "colour") continue; // travels with the cells (description().hasColour)
        const auto replaced = std::find_if(attributes.begin(), attributes.end(),
                                           [&](const octree::AttributeLayer& a) { return a.name == view.name; });
        if (replaced != attributes.end()) continue; // written below, in the order given
        layers.push_back({view.name, view.type, view.components, {view.bytes.begin(), view.bytes.end()}});
    }
    for (octree::AttributeLayer& attribute : attributes) layers.push_back(std::move(attribute));
    return octree::writePoct(octree.levels(), output, layers, progress);
}

Result<std::uint64_t> writeLeafLabels(const octree::PackedOctree& octree, AnnotationLayer layer,
                                      std::span<const std::uint8_t> labels, const fs::path& output, ProgressSink* progress)
{
    if (labels.size() != leafCount(octree))
        return Error::at(ErrorCode::InvalidArgument, output.string(), "",
                         std::to_string(labels.size()) + " " + layerName(layer) + " labels for an octree of " +
                             std::to_string(leafCount(octree)) + " leaves (" + octree.path().string() + ")");
    return writeAttributePoct(octree, labelAttribute(layer, labels), output, progress);
}

} // namespace stylos::core::annotation
