#pragma once
/** @file
 * @brief The annotation labels of the open project, in memory: per fragment, one class id per leaf of its
 *        octree for each layer (material, tool mark). The one source of truth that the développée painting,
 *        the 3D tint and the lasso read and change (through SceneDocument's undo commands, never directly).
 *        Loaded from the fragment's `.poct` layers when its octree opens (annotation/LeafLabels.h); written
 *        back by SceneDocument::save() for the fragments changed since (dirty()).
 *
 * Labels are handed out as shared, read-only arrays; an edit copies an array only while someone else (a
 * background job) still holds it, so readers never see it change under them. A fragment that is removed
 * keeps its labels here (undoing the removal brings them back); a new or opened project clears them.
 * GUI thread only.
 */
#include "stylos/widgets/annotation/LabelEdit.h"

#include "stylos/core/util/Result.h"

#include <QObject>

#include <array>
#include <map>
#include <memory>
#include <span>
#include <vector>

namespace stylos::core::octree {
class PackedOctree;
}

namespace stylos::widgets {

class LabelStore : public QObject {
    Q_OBJECT

public:
    using FragmentId = core::scene::FragmentId;
    using Layer = core::annotation::AnnotationLayer;
    using Labels = std::vector<std::uint8_t>;
    using LabelsPtr = std::shared_ptr<const Labels>;

    explicit LabelStore(QObject* parent = nullptr);

    /** @brief The labels of @p id's @p layer (one per leaf, leaf order); null until its octree opened. */
    LabelsPtr labels(FragmentId id, Layer layer) const;
    /** @brief Whether @p id has labels (its octree opened once). */
    bool has(FragmentId id) const { return m_entries.count(id) > 0; }
    /**
     * @brief Takes @p id's labels from @p octree's layers, unless the store already holds labels of the same
     *        leaf count for it (the same octree reopened: what is in memory, saved or not, wins). Emits
     *        labelsChanged() for both layers when it loads. Errors: Malformed (a label layer of the wrong type
     *        or size, naming the file); the fragment then gets all-zero labels.
     */
    core::Status load(FragmentId id, const core::octree::PackedOctree& octree);
    /** @brief Forgets every fragment's labels (a new or opened project). */
    void clear();

    /**
     * @brief The edit that gives @p classId to @p leaves (any order; duplicates and leaves out of range are
     *        ignored) of @p id's @p layer, holding only the leaves that change. Empty without labels.
     */
    LabelEdit makeEdit(FragmentId id, Layer layer, std::span<const std::uint32_t> leaves, std::uint8_t classId) const;
    /** @brief The edit that turns every leaf of class @p from into @p to in @p id's @p layer. */
    LabelEdit relabelEdit(FragmentId id, Layer layer, std::uint8_t from, std::uint8_t to) const;
    /** @brief Applies @p edit (forward: before → after; else after → before) and emits labelsChanged().
     *         Precondition: @p edit was made from the current labels (asserted in debug builds). */
    void apply(const LabelEdit& edit, bool forward);

    /** @brief How many leaves of every fragment hold @p classId in @p layer. */
    std::uint64_t count(Layer layer, std::uint8_t classId) const;
    /** @brief The fragments whose labels changed since they were loaded or last marked saved. */
    std::vector<FragmentId> dirty() const;
    void markSaved(FragmentId id);

Q_SIGNALS:
    /**
     * @brief @p fragment's layer @p layer (an AnnotationLayer as int) changed at @p leaves (ascending); all of
     *        it when @p leaves is empty (loaded). Connected directly: @p leaves is only valid during the call.
     */
    void labelsChanged(quint64 fragment, int layer, const std::vector<std::uint32_t>& leaves);

private:
    struct Entry {
        std::array<std::shared_ptr<Labels>, 2> layers;
        std::array<std::uint64_t, 2> revision{0, 0};
        std::array<std::uint64_t, 2> saved{0, 0};
    };
    static std::size_t slot(Layer layer) { return layer == Layer::Material ? 0 : 1; }

    std::map<FragmentId, Entry> m_entries;
};

} // namespace stylos::widgets
