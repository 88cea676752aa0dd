#pragma once
/** @file
 * @brief The Scene dock's model, the scene as a tree: first a row per assembly (its name and visibility,
 *        editable through the undo stack) with its member fragments under it, then the fragments at the top
 *        level, each in scene order — a fragment row shows its name (editable), a visibility check box and
 *        its colour as the decoration — and under each fragment a row per guide (axis, grooves), then a row
 *        for its développée once one was computed this session (SceneDocument::developpee()). Fragments are
 *        dragged onto an assembly (or its members) to move them in, onto the empty space or a top-level
 *        row to take them out; each drop is one undo step. Observes a SceneDocument; GUI thread only.
 */
#include "stylos/core/scene/Assembly.h"
#include "stylos/core/scene/Fragment.h"

#include <QAbstractItemModel>

#include <map>
#include <set>

namespace stylos::widgets {

class SceneDocument;

class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT

public:
    enum Role {
        FragmentIdRole = Qt::UserRole + 1,  ///< quint64 id of the row's fragment (its parent's for a guide)
        GuideIndexRole,                     ///< index of the guide in its fragment; -1 on other rows
        DeveloppeeRole,                     ///< true on a développée row
        AssemblyIdRole,                     ///< quint64 id of an assembly row; 0 on other rows
    };
    /** @brief The MIME type of dragged fragments: their ids, as text separated by spaces. */
    static constexpr const char* FragmentsMimeType = "application/x-stylos-fragments";

    /** Observes @p document (not owned; it must outlive the model). */
    explicit SceneTreeModel(SceneDocument& document, QObject* parent = nullptr);

    /** @brief The row of fragment @p id (invalid when there is none). */
    QModelIndex indexOf(core::scene::FragmentId id) const;
    /** @brief The row of assembly @p id (invalid when there is none). */
    QModelIndex indexOfAssembly(core::scene::AssemblyId id) const;
    /** @brief The assembly of an assembly row; NoAssembly otherwise. */
    core::scene::AssemblyId assemblyAt(const QModelIndex& index) const;
    /** @brief The fragment of a fragment row or of a guide row's parent; NoFragment for an invalid index. */
    core::scene::FragmentId fragmentAt(const QModelIndex& index) const;
    /** @brief True for a guide row. */
    bool isGuide(const QModelIndex& index) const;
    /** @brief True for a développée row. */
    bool isDeveloppee(const QModelIndex& index) const;
    /** @brief The développée row of fragment @p id (invalid when it has none). */
    QModelIndex developpeeIndexOf(core::scene::FragmentId id) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column, const QModelIndex& parent) override;
    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }

private:
    QVariant fragmentData(const core::scene::Fragment& fragment, int role) const;
    QVariant guideData(const core::scene::Fragment& fragment, int guide, int role) const;
    QVariant developpeeData(const core::scene::Fragment& fragment, int role) const;
    QVariant assemblyData(const core::scene::Assembly& assembly, int role) const;
    /** The assembly a drop on @p parent moves fragments into (NoAssembly: the top level). */
    core::scene::AssemblyId dropTarget(const QModelIndex& parent) const;
    int assemblyCount() const;
    void onFragmentChanged(quint64 id);
    void rebuildGuideCounts();
    void onDeveloppeeChanged(quint64 id);
    /** Rows under the fragment as the views know them: guides, then the développée. */
    int childCount(core::scene::FragmentId id) const;

    SceneDocument& m_document;
    /** Guide rows as the views know them (updated between begin/end calls). */
    std::map<core::scene::FragmentId, int> m_guideCounts;
    /** Fragments whose développée row the views know. */
    std::set<core::scene::FragmentId> m_developpeeRows;
};

} // namespace stylos::widgets
