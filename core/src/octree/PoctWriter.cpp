#include "stylos/core/octree/PoctWriter.h"

#include "PoctBits.h"
#include "PoctFileSink.h"
#include "PoctLayout.h"
#include "stylos/core/octree/PackedOctree.h"

#include <bit>
#include <cmath>
#include <optional>
#include <set>

namespace stylos::core::octree {

namespace fs = std::filesystem;
using poct::SectionEntry;
using poct::SectionStream;
using poct::TempFile;

namespace {

/** A layer to write: its description and its bytes (owned elsewhere), or the pending layer that gives them
 *  once the cells are written. */
struct LayerSource {
    SectionEntry entry;
    std::span<const std::uint8_t> bytes;
    const PendingLayer* pending = nullptr;
};

Error invalid(const fs::path& path, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, path.string(), "", problem);
}

/** Why @p d cannot be written, or nothing. */
std::optional<std::string> descriptionProblem(const OctreeDescription& d)
{
    if (d.depth < MinOctreeDepth || d.depth > MaxOctreeDepth)
        return "depth " + std::to_string(d.depth) + " outside " + std::to_string(MinOctreeDepth) + ".." +
               std::to_string(MaxOctreeDepth);
    if (d.cellsPerLevel.size() != static_cast<std::size_t>(d.depth) + 1)
        return "cells per level has " + std::to_string(d.cellsPerLevel.size()) + " entries for depth " +
               std::to_string(d.depth);
    for (std::size_t l = 0; l < d.cellsPerLevel.size(); ++l) {
        const std::uint64_t c = d.cellsPerLevel[l];
        const std::uint64_t parent = l == 0 ? 1 : d.cellsPerLevel[l - 1];
        if ((l == 0 && c != 1) || c == 0 || c > 8 * parent || c > poct::MaxCellsPerLevel)
            return "level " + std::to_string(l) + " cannot have " + std::to_string(c) + " cells";
    }
    if (d.normalCode != NormalCodeKind::Paper15 && d.normalCode != NormalCodeKind::Octahedral16)
        return std::string("unknown normal code");
    const auto& b = d.box;
    if (!std::isfinite(b.origin[0]) || !std::isfinite(b.origin[1]) || !std::isfinite(b.origin[2]) ||
        !std::isfinite(b.size) || !(b.size > 0))
        return std::string("the root box is not finite with a positive size");
    return std::nullopt;
}

/** Why @p layer cannot be stored in an octree of @p leaves leaves, or nothing. */
std::optional<std::string> layerProblem(const std::string& name, AttributeType type, std::uint8_t components,
                                        std::size_t bytes, std::uint64_t leaves)
{
    if (auto p = poct::layerNameProblem(name); !p.empty()) return p;
    if (poct::elementSize(type) == 0) return "attribute layer \"" + name + "\" has an unknown element type";
    if (components < 1 || components > poct::MaxComponents)
        return "attribute layer \"" + name + "\" must have 1.." + std::to_string(poct::MaxComponents) + " components";
    if (name == "colour" && (type != AttributeType::UInt8 || components != 3))
        return std::string("attribute layer \"colour\" must be 3 × UInt8");
    const std::uint64_t expected = leaves * components * poct::elementSize(type);
    if (bytes != expected)
        return "attribute layer \"" + name + "\" has " + std::to_string(bytes) + " bytes, expected " +
               std::to_string(expected) + " (" + std::to_string(leaves) + " leaves)";
    return std::nullopt;
}

/**
 * Writes the cells of @p levels, the colour layer from the leaf blocks when @p colourFromLevels, and
 * then @p layers, to @p path (atomically).
 */
Result<std::uint64_t> writeFile(const OctreeLevels& levels, const fs::path& path, std::span<const LayerSource> layers,
                                bool colourFromLevels, ProgressSink* progress)
{
    const OctreeDescription& d = levels.description();
    if (auto p = descriptionProblem(d)) return invalid(path, *p);
    const std::uint64_t leaves = d.cellsPerLevel.back();
    std::vector<SectionEntry> entries;
    std::set<std::string> names;
    if (colourFromLevels) {
        entries.push_back({"colour", poct::SectionKind::Attribute, AttributeType::UInt8, 3, 0, 0, 0});
        names.insert("colour");
    }
    for (const LayerSource& layer : layers) {
        const SectionEntry& e = layer.entry;
        const std::uint64_t bytes = layer.pending ? leaves * e.components * poct::elementSize(e.type) : layer.bytes.size();
        if (auto p = layerProblem(e.name, e.type, e.components, bytes, leaves)) return invalid(path, *p);
        if (!names.insert(e.name).second) return invalid(path, "attribute layer \"" + e.name + "\" given twice");
        entries.push_back(e);
    }
    if (entries.size() > poct::MaxLayers)
        return invalid(path, "more than " + std::to_string(poct::MaxLayers) + " attribute layers");

    poct::Header header = poct::planHeader(d, entries);
    auto file = TempFile::create(path);
    if (!file) return file.error();

    // Every level writes at its own place in the masks, normals (and colour) sections, so the levels may
    // come interleaved, in one walk of the tree; the sections are hashed when complete, from the file.
    const int depth = d.depth;
    std::vector<SectionStream> maskStreams, normalStreams;
    std::optional<SectionStream> colours;
    constexpr std::size_t levelBuffer = std::size_t(256) << 10;
    {
        std::uint64_t before = 0;
        for (int l = 0; l <= depth; ++l) {
            if (l < depth) maskStreams.emplace_back(*file, header.sections[0].offset + before, levelBuffer);
            normalStreams.emplace_back(*file, header.sections[1].offset + 2 * before, levelBuffer);
            before += d.cellsPerLevel[std::size_t(l)];
        }
        if (colourFromLevels) colours.emplace(*file, header.sections[2].offset, levelBuffer);
    }

    std::uint64_t totalCells = 0, writtenCells = 0;
    for (std::uint64_t c : d.cellsPerLevel) totalCells += c;
    std::vector<std::uint64_t> cells(std::size_t(depth) + 1, 0), children(std::size_t(depth) + 1, 0);
    Status status;
    levels.visitLevels([&](int l, const CellBlock& block) {
        if (!status) return;
        const bool leafLevel = l == depth;
        const std::size_t n = block.normals.size();
        const auto level = static_cast<std::size_t>(l);
        if (!leafLevel && block.masks.size() != n)
            status = invalid(path, "level " + std::to_string(l) + ": a block has " + std::to_string(block.masks.size()) +
                                       " masks for " + std::to_string(n) + " cells");
        else if (leafLevel && colourFromLevels && block.colours.size() != 3 * n)
            status = invalid(path, "leaf level: a block has " + std::to_string(block.colours.size()) +
                                       " colour bytes for " + std::to_string(n) + " cells");
        else if (cells[level] + n > d.cellsPerLevel[level])
            status = invalid(path, "level " + std::to_string(l) + " delivered " + std::to_string(cells[level] + n) +
                                       " cells or more, its description says " +
                                       std::to_string(d.cellsPerLevel[level]));
        if (!status) return;
        if (!leafLevel) {
            for (std::size_t i = 0; i < n; ++i) {
                if (block.masks[i] == 0) {
                    status = invalid(path, "level " + std::to_string(l) + ": inner cell " +
                                               std::to_string(cells[level] + i) + " has no children");
                    return;
                }
                children[level] += poct::popcount8(block.masks[i]);
            }
            status = maskStreams[level].append(block.masks.data(), n);
        }
        if (status) status = normalStreams[level].append(block.normals.data(), 2 * n);
        if (status && leafLevel && colours) status = colours->append(block.colours.data(), 3 * n);
        cells[level] += n;
        writtenCells += n;
        if (progress && status) {
            progress->update(totalCells ? std::min(1.0, double(writtenCells) / double(totalCells)) : 1.0);
            if (progress->isCancelRequested())
                status = Error::at(ErrorCode::Cancelled, path.string(), "", "cancelled while writing");
        }
    });
    for (int l = 0; l <= depth && status; ++l) {
        const auto level = static_cast<std::size_t>(l);
        if (cells[level] != d.cellsPerLevel[level])
            status = invalid(path, "level " + std::to_string(l) + " delivered " + std::to_string(cells[level]) +
                                       " cells, its description says " + std::to_string(d.cellsPerLevel[level]));
        else if (l < depth && children[level] != d.cellsPerLevel[level + 1])
            status = invalid(path, "level " + std::to_string(l) + ": child masks give " +
                                       std::to_string(children[level]) + " children, level " +
                                       std::to_string(l + 1) + " has " + std::to_string(d.cellsPerLevel[level + 1]) +
                                       " cells");
    }
    for (SectionStream& stream : maskStreams)
        if (status) status = stream.flush();
    for (SectionStream& stream : normalStreams)
        if (status) status = stream.flush();
    if (status && colours) status = colours->flush();
    if (!status) return status.error();
    std::size_t next = 0;
    for (; next < (colours ? 3u : 2u); ++next) {
        SectionEntry& e = header.sections[next];
        auto hash = file->hashRange(e.offset, e.length);
        if (!hash) return hash.error();
        e.checksum = *hash;
    }
    for (const LayerSource& layer : layers) {
        SectionEntry& e = header.sections[next++];
        AttributeLayer finished;
        std::span<const std::uint8_t> bytes = layer.bytes;
        if (layer.pending) {
            finished = layer.pending->finish();
            if (finished.name != e.name || finished.type != e.type || finished.components != e.components)
                return invalid(path, "attribute layer \"" + e.name + "\" came back as \"" + finished.name +
                                         "\" with another type or component count");
            if (auto p = layerProblem(e.name, e.type, e.components, finished.bytes.size(), leaves))
                return invalid(path, *p);
            bytes = finished.bytes;
        }
        if (auto s = file->writeAt(e.offset, bytes.data(), bytes.size()); !s) return s.error();
        e.checksum = xxh64(bytes);
    }
    const std::vector<std::uint8_t> head = poct::serialiseHeader(header);
    const std::uint64_t size = poct::fileBytes(header);
    if (auto s = file->writeAt(0, head.data(), head.size()); !s) return s.error();
    if (auto s = file->resize(size); !s) return s.error(); // padding gaps read as zeros
    if (auto s = file->commit(); !s) return s.error();
    return size;
}

} // namespace

Result<std::uint64_t> writePoct(const OctreeLevels& levels, const fs::path& path,
                                std::span<const AttributeLayer> extraLayers, ProgressSink* progress)
{
    return writePoct(levels, path, extraLayers, {}, progress);
}

Result<std::uint64_t> writePoct(const OctreeLevels& levels, const fs::path& path,
                                std::span<const AttributeLayer> extraLayers, std::span<const PendingLayer> pendingLayers,
                                ProgressSink* progress)
{
    std::vector<LayerSource> layers;
    for (const AttributeLayer& l : extraLayers)
        layers.push_back({SectionEntry{l.name, poct::SectionKind::Attribute, l.type, l.components, 0, 0, 0}, l.bytes});
    for (const PendingLayer& l : pendingLayers)
        layers.push_back({SectionEntry{l.name, poct::SectionKind::Attribute, l.type, l.components, 0, 0, 0}, {}, &l});
    return writeFile(levels, path, layers, levels.description().hasColour, progress);
}

Result<std::uint64_t> setPoctAttributeLayer(const fs::path& path, const AttributeLayer& layer)
{
    auto octree = PackedOctree::open(path);
    if (!octree) return octree.error();
    const std::uint64_t leaves = octree->cellCount(octree->depth());
    if (auto p = layerProblem(layer.name, layer.type, layer.components, layer.bytes.size(), leaves))
        return invalid(path, *p);
    std::vector<LayerSource> layers;
    bool replaced = false;
    for (const AttributeView& v : octree->attributes()) {
        if (v.name == layer.name) {
            replaced = true;
            layers.push_back(
                {SectionEntry{layer.name, poct::SectionKind::Attribute, layer.type, layer.components, 0, 0, 0},
                 layer.bytes});
        } else {
            layers.push_back(
                {SectionEntry{v.name, poct::SectionKind::Attribute, v.type, v.components, 0, 0, 0}, v.bytes});
        }
    }
    if (!replaced)
        layers.push_back({SectionEntry{layer.name, poct::SectionKind::Attribute, layer.type, layer.components, 0, 0, 0},
                          layer.bytes});
    // The old file stays mapped (and readable) until `octree` goes, after the rename.
    return writeFile(octree->levels(), path, layers, false, nullptr);
}

} // namespace stylos::core::octree
