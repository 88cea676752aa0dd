#include "stylos/widgets/document/SceneTreeModel.h"

#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <QColor>
#include <QFont>
#include <QMimeData>
#include <QGuiApplication>
#include <QPalette>

namespace stylos::widgets {

using core::scene::Assembly;
using core::scene::AssemblyId;
using core::scene::Fragment;
using core::scene::FragmentId;

namespace {

// Internal ids: 0 on the root's rows (assemblies, then top-level fragments); kAssemblyTag | assembly on the
// rows of an assembly's members; the fragment's id on the rows under a fragment (guides, développée).
constexpr quintptr kAssemblyTag = quintptr(1) << (sizeof(quintptr) * 8 - 1);

bool isMemberRow(const QModelIndex& index) { return (index.internalId() & kAssemblyTag) != 0; }

} // namespace

SceneTreeModel::SceneTreeModel(SceneDocument& document, QObject* parent)
    : QAbstractItemModel(parent), m_document(document)
{
    connect(&document, &SceneDocument::fragmentAboutToBeAdded, this, [this](int index, quint64 assembly) {
        // Its row among the fragments of the same parent that come before it in the scene.
        const auto& fragments = m_document.scene().fragments();
        int row = assembly == core::scene::NoAssembly ? assemblyCount() : 0;
        for (int i = 0; i < index && i < static_cast<int>(fragments.size()); ++i)
            if (fragments[static_cast<std::size_t>(i)].assembly == assembly) ++row;
        beginInsertRows(indexOfAssembly(assembly), row, row);
    });
    connect(&document, &SceneDocument::fragmentAdded, this, [this](quint64 id) {
        const Fragment* f = m_document.fragment(id);
        m_guideCounts[id] = f ? static_cast<int>(f->guides.size()) : 0;
        endInsertRows();
    });
    connect(&document, &SceneDocument::fragmentAboutToBeRemoved, this, [this](quint64 id) {
        const QModelIndex row = indexOf(id);
        beginRemoveRows(row.parent(), row.row(), row.row());
    });
    connect(&document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        m_guideCounts.erase(id);
        m_developpeeRows.erase(id);
        endRemoveRows();
    });
    connect(&document, &SceneDocument::structureAboutToChange, this, [this] { beginResetModel(); });
    connect(&document, &SceneDocument::structureChanged, this, [this] {
        rebuildGuideCounts();
        endResetModel();
    });
    connect(&document, &SceneDocument::assemblyChanged, this, [this](quint64 id) {
        const QModelIndex row = indexOfAssembly(id);
        if (row.isValid()) Q_EMIT dataChanged(row, row);
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
    const core::scene::Scene& scene = m_document.scene();
    const Fragment* f = scene.find(id);
    if (!f) return {};
    int row = f->assembly == core::scene::NoAssembly ? assemblyCount() : 0;
    for (const Fragment& other : scene.fragments()) {
        if (other.id == id) break;
        if (other.assembly == f->assembly) ++row;
    }
    const quintptr internal = f->assembly == core::scene::NoAssembly ? 0 : (kAssemblyTag | quintptr(f->assembly));
    return createIndex(row, 0, internal);
}

int SceneTreeModel::assemblyCount() const
{
    return static_cast<int>(m_document.scene().assemblies().size());
}

QModelIndex SceneTreeModel::indexOfAssembly(AssemblyId id) const
{
    const auto row = m_document.scene().assemblyIndexOf(id);
    return row ? createIndex(static_cast<int>(*row), 0, quintptr(0)) : QModelIndex();
}

AssemblyId SceneTreeModel::assemblyAt(const QModelIndex& index) const
{
    if (!index.isValid() || index.model() != this || index.internalId() != 0 || index.row() >= assemblyCount())
        return core::scene::NoAssembly;
    return m_document.scene().assemblies()[static_cast<std::size_t>(index.row())].id;
}

FragmentId SceneTreeModel::fragmentAt(const QModelIndex& index) const
{
    if (!index.isValid() || index.model() != this) return core::scene::NoFragment;
    if (isMemberRow(index)) {
        const auto members = m_document.scene().membersOf(AssemblyId(index.internalId() & ~kAssemblyTag));
        return index.row() < static_cast<int>(members.size()) ? members[static_cast<std::size_t>(index.row())]
                                                              : core::scene::NoFragment;
    }
    if (index.internalId() != 0) return static_cast<FragmentId>(index.internalId());
    const int row = index.row() - assemblyCount();
    if (row < 0) return core::scene::NoFragment;
    const auto top = m_document.scene().membersOf(core::scene::NoAssembly);
    return row < static_cast<int>(top.size()) ? top[static_cast<std::size_t>(row)] : core::scene::NoFragment;
}

bool SceneTreeModel::isGuide(const QModelIndex& index) const
{
    return index.isValid() && index.internalId() != 0 && !isMemberRow(index) && !isDeveloppee(index);
}

bool SceneTreeModel::isDeveloppee(const QModelIndex& index) const
{
    if (!index.isValid() || index.internalId() == 0 || isMemberRow(index)) return false;
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
    if (const AssemblyId a = assemblyAt(parent); a != core::scene::NoAssembly)
        return createIndex(row, column, kAssemblyTag | quintptr(a));
    if (parent.internalId() != 0 && !isMemberRow(parent)) return {};
    // A guide row carries its fragment's id (ids start at 1, below the tag).
    return createIndex(row, column, quintptr(fragmentAt(parent)));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const
{
    if (!child.isValid() || child.internalId() == 0) return {};
    if (isMemberRow(child)) return indexOfAssembly(AssemblyId(child.internalId() & ~kAssemblyTag));
    return indexOf(static_cast<FragmentId>(child.internalId()));
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const
{
    if (!parent.isValid())
        return assemblyCount() + static_cast<int>(m_document.scene().membersOf(core::scene::NoAssembly).size());
    if (parent.column() != 0) return 0;
    if (const AssemblyId a = assemblyAt(parent); a != core::scene::NoAssembly)
        return static_cast<int>(m_document.scene().membersOf(a).size());
    if (parent.internalId() != 0 && !isMemberRow(parent)) return 0;
    return childCount(fragmentAt(parent));
}

int SceneTreeModel::columnCount(const QModelIndex&) const
{
    return 1;
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    if (const Assembly* a = m_document.assembly(assemblyAt(index))) return assemblyData(*a, role);
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

QVariant SceneTreeModel::assemblyData(const Assembly& a, int role) const
{
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole: return QString::fromStdString(a.name);
    case Qt::CheckStateRole: return a.visible ? Qt::Checked : Qt::Unchecked;
    case Qt::ToolTipRole: {
        const int members = static_cast<int>(m_document.scene().membersOf(a.id).size());
        const Fragment* drum = m_document.fragment(a.drum);
        const QString text = tr("Assembly of %n fragment(s)", nullptr, members);
        return drum ? text + QLatin1Char('\n') + tr("Docks against %1").arg(QString::fromStdString(drum->name)) : text;
    }
    case Qt::FontRole: {
        QFont font;
        font.setBold(true);
        return font;
    }
    case FragmentIdRole: return QVariant::fromValue<quint64>(0);
    case GuideIndexRole: return -1;
    case DeveloppeeRole: return false;
    case AssemblyIdRole: return QVariant::fromValue<quint64>(a.id);
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
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return false;
    if (const AssemblyId a = assemblyAt(index); a != core::scene::NoAssembly) {
        if (role == Qt::EditRole) {
            if (value.toString().trimmed().isEmpty()) return false;
            m_document.renameAssembly(a, value.toString());
            return true;
        }
        if (role == Qt::CheckStateRole) {
            m_document.setAssemblyVisible(a, value.toInt() == Qt::Checked);
            return true;
        }
        return false;
    }
    if (index.internalId() != 0 && !isMemberRow(index)) return false;
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
    if (!index.isValid()) return Qt::ItemIsDropEnabled;
    if (assemblyAt(index) != core::scene::NoAssembly)
        return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable | Qt::ItemIsUserCheckable |
               Qt::ItemIsDropEnabled;
    if (index.internalId() != 0 && !isMemberRow(index))
        return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemNeverHasChildren;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable | Qt::ItemIsUserCheckable |
           Qt::ItemIsDragEnabled | Qt::ItemIsDropEnabled;
}

QVariant SceneTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (section == 0 && orientation == Qt::Horizontal && role == Qt::DisplayRole) return tr("Scene");
    return {};
}

QStringList SceneTreeModel::mimeTypes() const
{
    return {QString::fromLatin1(FragmentsMimeType)};
}

QMimeData* SceneTreeModel::mimeData(const QModelIndexList& indexes) const
{
    QStringList ids;
    for (const QModelIndex& index : indexes) {
        if (index.internalId() != 0 && !isMemberRow(index)) continue; // guides and développées stay
        const FragmentId id = fragmentAt(index);
        if (id != core::scene::NoFragment && !ids.contains(QString::number(id))) ids << QString::number(id);
    }
    if (ids.isEmpty()) return nullptr;
    auto* data = new QMimeData;
    data->setData(QString::fromLatin1(FragmentsMimeType), ids.join(QLatin1Char(' ')).toLatin1());
    return data;
}

AssemblyId SceneTreeModel::dropTarget(const QModelIndex& parent) const
{
    if (const AssemblyId a = assemblyAt(parent); a != core::scene::NoAssembly) return a;
    if (parent.isValid() && isMemberRow(parent)) return AssemblyId(parent.internalId() & ~kAssemblyTag);
    return core::scene::NoAssembly;
}

bool SceneTreeModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int, int, const QModelIndex&) const
{
    return data && action == Qt::MoveAction && data->hasFormat(QString::fromLatin1(FragmentsMimeType));
}

bool SceneTreeModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                  const QModelIndex& parent)
{
    if (!canDropMimeData(data, action, row, column, parent)) return false;
    std::vector<FragmentId> ids;
    for (const QByteArray& part : data->data(QString::fromLatin1(FragmentsMimeType)).split(' ')) {
        bool ok = false;
        const FragmentId id = part.toULongLong(&ok);
        if (ok && m_document.fragment(id)) ids.push_back(id);
    }
    if (ids.empty()) return false;
    m_document.moveToAssembly(ids, dropTarget(parent));
    return false; // the rows moved through the document: nothing for the view to remove
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
