#pragma once
/** @file
 * @brief The Scene dock's model: one top-level row per fragment, in scene order — its name (editable,
 *        through the undo stack), a visibility check box (through the undo stack) and its colour as the
 *        decoration — and under each fragment a row per guide (axis, grooves), then a row for its
 *        développée once one was computed this session (SceneDocument::developpee()). Observes a SceneDocument; GUI thread only.
 */
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
    };

    /** Observes @p document (not owned; it must outlive the model). */
    explicit SceneTreeModel(SceneDocument& document, QObject* parent = nullptr);

    /** @brief The row of fragment @p id (invalid when there is none). */
    QModelIndex indexOf(core::scene::FragmentId id) const;
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

private:
    QVariant fragmentData(const core::scene::Fragment& fragment, int role) const;
    QVariant guideData(const core::scene::Fragment& fragment, int guide, int role) const;
    QVariant developpeeData(const core::scene::Fragment& fragment, int role) const;
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
