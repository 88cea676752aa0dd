// The open project's annotation labels, per fragment and layer, with copy-on-write arrays.
#include "stylos/widgets/annotation/LabelStore.h"

#include "stylos/core/annotation/LeafLabels.h"

#include <algorithm>
#include <cassert>

namespace stylos::widgets {

using core::annotation::AllAnnotationLayers;

LabelStore::LabelStore(QObject* parent) : QObject(parent) {}

LabelStore::LabelsPtr LabelStore::labels(FragmentId id, Layer layer) const
{
    const auto it = m_entries.find(id);
    return it == m_entries.end() ? nullptr : it->second.layers[slot(layer)];
}

core::Status LabelStore::load(FragmentId id, const core::octree::PackedOctree& octree)
{
    const std::uint64_t leaves = core::annotation::leafCount(octree);
    if (const auto it = m_entries.find(id); it != m_entries.end() && it->second.layers[0]->size() == leaves)
        return {};
    Entry entry;
    core::Status status;
    for (Layer layer : AllAnnotationLayers) {
        auto read = core::annotation::readLeafLabels(octree, layer);
        if (!read && status.ok()) status = read.error();
        entry.layers[slot(layer)] = std::make_shared<Labels>(read ? std::move(read).value() : Labels(leaves, 0));
    }
    m_entries[id] = std::move(entry);
    for (Layer layer : AllAnnotationLayers) Q_EMIT labelsChanged(id, int(layer), {});
    return status;
}

void LabelStore::clear()
{
    m_entries.clear();
}

LabelEdit LabelStore::makeEdit(FragmentId id, Layer layer, std::span<const std::uint32_t> leaves,
                               std::uint8_t classId) const
{
    LabelEdit edit;
    edit.fragment = id;
    edit.layer = layer;
    const LabelsPtr current = labels(id, layer);
    if (!current) return edit;
    for (std::uint32_t leaf : leaves)
        if (leaf < current->size() && (*current)[leaf] != classId) edit.leaves.push_back(leaf);
    std::sort(edit.leaves.begin(), edit.leaves.end());
    edit.leaves.erase(std::unique(edit.leaves.begin(), edit.leaves.end()), edit.leaves.end());
    edit.before.reserve(edit.leaves.size());
    for (std::uint32_t leaf : edit.leaves) edit.before.push_back((*current)[leaf]);
    edit.after.assign(edit.leaves.size(), classId);
    return edit;
}

LabelEdit LabelStore::relabelEdit(FragmentId id, Layer layer, std::uint8_t from, std::uint8_t to) const
{
    LabelEdit edit;
    edit.fragment = id;
    edit.layer = layer;
    const LabelsPtr current = labels(id, layer);
    if (!current || from == to) return edit;
    for (std::size_t leaf = 0; leaf < current->size(); ++leaf)
        if ((*current)[leaf] == from) edit.leaves.push_back(static_cast<std::uint32_t>(leaf));
    edit.before.assign(edit.leaves.size(), from);
    edit.after.assign(edit.leaves.size(), to);
    return edit;
}

void LabelStore::apply(const LabelEdit& edit, bool forward)
{
    const auto it = m_entries.find(edit.fragment);
    if (it == m_entries.end() || edit.empty()) return;
    std::shared_ptr<Labels>& layer = it->second.layers[slot(edit.layer)];
    if (layer.use_count() > 1) layer = std::make_shared<Labels>(*layer); // a reader still holds the old one
    Labels& labels = *layer;
    const std::vector<std::uint8_t>& from = forward ? edit.before : edit.after;
    const std::vector<std::uint8_t>& to = forward ? edit.after : edit.before;
    for (std::size_t i = 0; i < edit.leaves.size(); ++i) {
        const std::uint32_t leaf = edit.leaves[i];
        if (leaf >= labels.size()) continue;
        assert(labels[leaf] == from[i]);
        (void)from;
        labels[leaf] = to[i];
    }
    ++it->second.revision[slot(edit.layer)];
    Q_EMIT labelsChanged(edit.fragment, int(edit.layer), edit.leaves);
}

std::uint64_t LabelStore::count(Layer layer, std::uint8_t classId) const
{
    std::uint64_t n = 0;
    for (const auto& [id, entry] : m_entries) {
        const Labels& labels = *entry.layers[slot(layer)];
        n += static_cast<std::uint64_t>(std::count(labels.begin(), labels.end(), classId));
    }
    return n;
}

std::vector<LabelStore::FragmentId> LabelStore::dirty() const
{
    std::vector<FragmentId> out;
    for (const auto& [id, entry] : m_entries)
        if (entry.revision != entry.saved) out.push_back(id);
    return out;
}

void LabelStore::markSaved(FragmentId id)
{
    if (const auto it = m_entries.find(id); it != m_entries.end()) it->second.saved = it->second.revision;
}

} // namespace stylos::widgets
