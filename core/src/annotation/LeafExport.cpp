// One PLY point per leaf with the annotation and ambient layers as properties.
#include "stylos/core/annotation/LeafExport.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/octree/LeafPly.h"

#include <cstring>
#include <set>

namespace stylos::core::annotation {

namespace {

Result<LeafColumn> readColumn(const octree::PackedOctree& octree, const std::string& name)
{
    const std::string file = octree.path().string();
    if (const auto layer = layerFromName(name)) {
        auto labels = readLeafLabels(octree, *layer);
        if (!labels) return labels.error();
        return LeafColumn{name, std::move(labels).value(), {}};
    }
    const auto view = octree.attribute(name);
    if (!view) return Error::at(ErrorCode::InvalidArgument, file, {}, "has no \"" + name + "\" layer (stylos-cli ao adds it)");
    const std::uint64_t leaves = leafCount(octree);
    if (view->type != octree::AttributeType::Float32 || view->components != 1 || view->bytes.size() != leaves * 4)
        return Error::at(ErrorCode::Malformed, file, "layer \"" + name + "\"", "not one float per leaf");
    LeafColumn column{name, {}, std::vector<float>(leaves)};
    if (leaves) std::memcpy(column.floats.data(), view->bytes.data(), view->bytes.size());
    return column;
}

} // namespace

bool isExportableLayer(const std::string& name) { return name == "material" || name == "toolmark" || name == "ambient"; }

Result<std::vector<LeafColumn>> readLeafColumns(const octree::PackedOctree& octree, const std::vector<std::string>& layers,
                                                const std::filesystem::path& output)
{
    std::vector<LeafColumn> columns;
    std::set<std::string> seen;
    for (const std::string& name : layers) {
        if (!isExportableLayer(name))
            return Error::at(ErrorCode::InvalidArgument, output.string(), {}, "unknown layer \"" + name + "\" (material, toolmark, ambient)");
        if (!seen.insert(name).second)
            return Error::at(ErrorCode::InvalidArgument, output.string(), {}, "layer \"" + name + "\" given twice");
        auto column = readColumn(octree, name);
        if (!column) return column.error();
        columns.push_back(std::move(column).value());
    }
    return columns;
}

Result<std::uint64_t> exportLeafPly(const octree::PackedOctree& octree, const std::vector<std::string>& layers,
                                    const std::filesystem::path& output, ProgressSink* progress)
{
    auto read = readLeafColumns(octree, layers, output);
    if (!read) return read.error();
    const std::vector<LeafColumn>& columns = *read;
    std::vector<octree::LeafPlyColumn> plyColumns;
    for (const LeafColumn& c : columns)
        plyColumns.push_back({c.name, c.isFloat() ? io::PlyScalarType::Float32 : io::PlyScalarType::UInt8,
                              [&c](std::uint64_t leaf) { return c.at(leaf); }});
    return octree::writeLeafPly(octree, plyColumns,
                                "stylos leaves: one vertex per leaf centre of an octree of depth " +
                                    std::to_string(octree.depth()),
                                output, progress);
}

} // namespace stylos::core::annotation
