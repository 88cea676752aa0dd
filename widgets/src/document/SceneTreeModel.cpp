#include "stylos/widgets/document/SceneTreeModel.h"

#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <QColor>
#include <QGuiApplication>
#include <QPalette>

namespace stylos::widgets {

using core::scene::Fragment;
using core::scene::FragmentId;

SceneTreeModel::SceneTreeModel(SceneDocument& document, QObject* parent)
    : QAbstractItemModel(parent), m_document(document)
{
    connect(&document, &SceneDocument::fragmentAboutToBeAdded, this,
            [this](int row) { beginInsertRows({}, row, row); });
    connect(&document, &SceneDocument::fragmentAdded, this, [this](quint64 id) {
        const Fragment* f = m_document.fragment(id);
        m_guideCounts[id] = f ? static_cast<int>(f->guides.size()) : 0;
        endInsertRows();
    });
    connect(&document, &SceneDocument::fragmentAboutToBeRemoved, this, [this](quint64 id) {
        const QModelIndex row = indexOf(id);
        beginRemoveRows({}, row.row(), row.row());
    });
    connect(&document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        m_guideCounts.erase(id);
        m_developpeeRows.erase(id);
        endRemoveRows();
    });
    connect(&document, &SceneDocument::fragmentChanged, this, &SceneTreeModel::onFragmentChanged);
    connect(&document, &SceneDocument::developpeeChanged, this, &SceneTreeModel::onDeveloppeeChanged);
    connect(&document, &SceneDocument::sceneAboutToBeReset, this, [this] { beginResetModel(); });
    connect(&document, &SceneDocument::sceneReset, this, [this] {
        rebuildGuideCounts();
        endResetModel();
    });
    rebuildGuideCounts();
}

QModelIndex SceneTreeModel::indexOf(FragmentId id) const
{
    const auto row = m_document.scene().indexOf(id);
    return row ? createIndex(static_cast<int>(*row), 0, quintptr(0)) : QModelIndex();
}

FragmentId SceneTreeModel::fragmentAt(const QModelIndex& index) const
{
    if (!index.isValid() || index.model() != this) return core::scene::NoFragment;
    if (index.internalId() != 0) return static_cast<FragmentId>(index.internalId());
    const auto& fragments = m_document.scene().fragments();
    return index.row() < static_cast<int>(fragments.size()) ? fragments[static_cast<std::size_t>(index.row())].id
                                                            : core::scene::NoFragment;
}

bool SceneTreeModel::isGuide(const QModelIndex& index) const
{
    return index.isValid() && index.internalId() != 0 && !isDeveloppee(index);
}

bool SceneTreeModel::isDeveloppee(const QModelIndex& index) const
{
    if (!index.isValid() || index.internalId() == 0) return false;
    const auto id = static_cast<FragmentId>(index.internalId());
    const auto guides = m_guideCounts.find(id);
    return m_developpeeRows.count(id) != 0 && guides != m_guideCounts.end() && index.row() == guides->second;
}

QModelIndex SceneTreeModel::developpeeIndexOf(FragmentId id) const
{
    const QModelIndex parent = indexOf(id);
    if (!parent.isValid() || m_developpeeRows.count(id) == 0) return {};
    return index(m_guideCounts.at(id), 0, parent);
}

int SceneTreeModel::childCount(FragmentId id) const
{
    const auto it = m_guideCounts.find(id);
    return (it == m_guideCounts.end() ? 0 : it->second) + static_cast<int>(m_developpeeRows.count(id));
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const
{
    if (!hasIndex(row, column, parent)) return {};
    if (!parent.isValid()) return createIndex(row, column, quintptr(0));
    if (parent.internalId() != 0) return {};
    // A guide row carries its fragment's id (ids start at 1, so 0 marks fragment rows).
    return createIndex(row, column, quintptr(fragmentAt(parent)));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const
{
    if (!child.isValid() || child.internalId() == 0) return {};
    return indexOf(static_cast<FragmentId>(child.internalId()));
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const
{
    if (!parent.isValid()) return static_cast<int>(m_document.scene().size());
    if (parent.column() != 0 || parent.internalId() != 0) return 0;
    return childCount(fragmentAt(parent));
}

int SceneTreeModel::columnCount(const QModelIndex&) const
{
    return 1;
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    const Fragment* f = m_document.fragment(fragmentAt(index));
    if (!f) return {};
    if (isDeveloppee(index)) return developpeeData(*f, role);
    if (isGuide(index)) return guideData(*f, index.row(), role);
    return fragmentData(*f, role);
}

QVariant SceneTreeModel::fragmentData(const Fragment& f, int role) const
{
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole: return QString::fromStdString(f.name);
    case Qt::DecorationRole: return QColor(f.colour.r, f.colour.g, f.colour.b);
    case Qt::CheckStateRole: return f.visible ? Qt::Checked : Qt::Unchecked;
    case Qt::ToolTipRole: {
        const QString path = QString::fromStdString(f.octreePath.string());
        return f.octreeMissing ? tr("%1 (missing)").arg(path) : path;
    }
    case Qt::ForegroundRole:
        if (f.octreeMissing) return QGuiApplication::palette().color(QPalette::Disabled, QPalette::Text);
        return {};
    case FragmentIdRole: return QVariant::fromValue<quint64>(f.id);
    case GuideIndexRole: return -1;
    case DeveloppeeRole: return false;
    default: return {};
    }
}

QVariant SceneTreeModel::developpeeData(const Fragment& f, int role) const
{
    const auto result = m_document.developpee(f.id);
    if (!result) return {};
    switch (role) {
    case Qt::DisplayRole:
        return tr("Développée (%1, %2 × %3)")
            .arg(DeveloppeeSettings::surfaceName(result->fit.surface.kind()))
            .arg(result->image.width())
            .arg(result->image.height());
    case Qt::ToolTipRole: return DeveloppeePanel::fitSummary(*result);
    case FragmentIdRole: return QVariant::fromValue<quint64>(f.id);
    case GuideIndexRole: return -1;
    case DeveloppeeRole: return true;
    default: return {};
    }
}

QVariant SceneTreeModel::guideData(const Fragment& f, int guide, int role) const
{
    if (guide < 0 || guide >= static_cast<int>(f.guides.size())) return {};
    const core::scene::Guide& g = f.guides[static_cast<std::size_t>(guide)];
    switch (role) {
    case Qt::DisplayRole: return QString::fromStdString(g.name);
    case Qt::ToolTipRole: return g.kind == core::scene::GuideKind::Axis ? tr("Axis") : tr("Groove");
    case FragmentIdRole: return QVariant::fromValue<quint64>(f.id);
    case GuideIndexRole: return guide;
    case DeveloppeeRole: return false;
    default: return {};
    }
}

bool SceneTreeModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || index.internalId() != 0) return false;
    const FragmentId id = fragmentAt(index);
    if (role == Qt::EditRole) {
        const QString name = value.toString().trimmed();
        if (name.isEmpty()) return false;
        m_document.renameFragment(id, name);
        return true;
    }
    if (role == Qt::CheckStateRole) {
        m_document.setFragmentVisible(id, value.toInt() == Qt::Checked);
        return true;
    }
    return false;
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const
{
    if (!index.isValid()) return Qt::NoItemFlags;
    if (index.internalId() != 0) return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemNeverHasChildren;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable | Qt::ItemIsUserCheckable;
}

QVariant SceneTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (section == 0 && orientation == Qt::Horizontal && role == Qt::DisplayRole) return tr("Scene");
    return {};
}

void SceneTreeModel::onFragmentChanged(quint64 id)
{
    const QModelIndex row = indexOf(id);
    const Fragment* f = m_document.fragment(id);
    if (!row.isValid() || !f) return;
    const int before = m_guideCounts[id];
    const int after = static_cast<int>(f->guides.size());
    if (before != after) {
        if (before > 0) {
            beginRemoveRows(row, 0, before - 1);
            m_guideCounts[id] = 0;
            endRemoveRows();
        }
        if (after > 0) {
            beginInsertRows(row, 0, after - 1);
            m_guideCounts[id] = after;
            endInsertRows();
        }
    } else if (after > 0) {
        Q_EMIT dataChanged(index(0, 0, row), index(after - 1, 0, row));
    }
    Q_EMIT dataChanged(row, row);
}

void SceneTreeModel::onDeveloppeeChanged(quint64 id)
{
    const QModelIndex row = indexOf(id);
    if (!row.isValid()) return;
    const bool had = m_developpeeRows.count(id) != 0;
    const bool has = m_document.developpee(id) != nullptr;
    const int at = m_guideCounts[id];
    if (had && !has) {
        beginRemoveRows(row, at, at);
        m_developpeeRows.erase(id);
        endRemoveRows();
    } else if (!had && has) {
        beginInsertRows(row, at, at);
        m_developpeeRows.insert(id);
        endInsertRows();
    } else if (has) {
        const QModelIndex child = index(at, 0, row);
        Q_EMIT dataChanged(child, child);
    }
}

void SceneTreeModel::rebuildGuideCounts()
{
    m_guideCounts.clear();
    m_developpeeRows.clear();
    for (const Fragment& f : m_document.scene().fragments()) {
        m_guideCounts[f.id] = static_cast<int>(f.guides.size());
        if (m_document.developpee(f.id)) m_developpeeRows.insert(f.id);
    }
}

} // namespace stylos::widgets
