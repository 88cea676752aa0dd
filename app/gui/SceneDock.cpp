#include "SceneDock.h"

#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/document/SceneTreeModel.h"

#include <QEvent>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QTreeView>

#include <algorithm>

namespace stylos::app {

SceneDock::SceneDock(widgets::SceneDocument& document, QWidget* parent)
    : QDockWidget(parent), m_document(document), m_model(new widgets::SceneTreeModel(document, this)),
      m_view(new QTreeView(this))
{
    setObjectName(QStringLiteral("sceneDock"));
    m_view->setObjectName(QStringLiteral("sceneTree"));
    m_view->setModel(m_model);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    // Rename by F2 or a double click only: a click on the selected row must not open an editor (which would
    // take the focus and swallow the next shortcut, Ctrl+Z or Delete).
    m_view->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
    m_view->setHeaderHidden(true);
    m_view->setUniformRowHeights(true);
    m_view->header()->setStretchLastSection(true);
    m_view->setDragEnabled(true);
    m_view->setAcceptDrops(true);
    m_view->setDropIndicatorShown(true);
    m_view->setDragDropMode(QAbstractItemView::DragDrop);
    m_view->setDefaultDropAction(Qt::MoveAction);
    setWidget(m_view);
    // Assemblies made or removed reset the tree: keep what was selected, and show the assemblies open.
    connect(m_model, &QAbstractItemModel::modelAboutToBeReset, this, [this] {
        m_keptSelection = selectedFragments();
        m_keptAssembly = currentAssembly();
    });
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        for (const auto& a : m_document.scene().assemblies()) m_view->expand(m_model->indexOfAssembly(a.id));
        QItemSelection selection;
        for (const auto id : m_keptSelection)
            if (const QModelIndex index = m_model->indexOf(id); index.isValid()) selection.select(index, index);
        if (const QModelIndex a = m_model->indexOfAssembly(m_keptAssembly); a.isValid()) selection.select(a, a);
        if (!selection.isEmpty()) {
            m_view->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
            m_view->selectionModel()->setCurrentIndex(selection.indexes().first(), QItemSelectionModel::NoUpdate);
        }
        Q_EMIT selectionChanged();
    });

    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this, &SceneDock::selectionChanged);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this, &SceneDock::selectionChanged);
    // A freshly added fragment becomes the selection: what the user just imported is what they act on.
    connect(&document, &widgets::SceneDocument::fragmentAdded, this,
            [this](quint64 id) { selectFragment(static_cast<core::scene::FragmentId>(id)); });
    retranslateUi();
}

QList<core::scene::FragmentId> SceneDock::selectedFragments() const
{
    QList<core::scene::FragmentId> ids;
    for (const QModelIndex& index : m_view->selectionModel()->selectedIndexes()) {
        const core::scene::FragmentId id = m_model->fragmentAt(index);
        if (id != core::scene::NoFragment && !ids.contains(id)) ids << id;
    }
    const auto& fragments = m_document.scene().fragments();
    const auto position = [&fragments](core::scene::FragmentId id) {
        return std::find_if(fragments.begin(), fragments.end(), [id](const auto& f) { return f.id == id; }) -
               fragments.begin();
    };
    std::sort(ids.begin(), ids.end(), [&](auto a, auto b) { return position(a) < position(b); });
    return ids;
}

core::scene::AssemblyId SceneDock::currentAssembly() const
{
    return m_model->assemblyAt(m_view->selectionModel()->currentIndex());
}

core::scene::FragmentId SceneDock::currentFragment() const
{
    return m_model->fragmentAt(m_view->selectionModel()->currentIndex());
}

void SceneDock::selectFragment(core::scene::FragmentId id)
{
    const QModelIndex index = m_model->indexOf(id);
    if (!index.isValid()) return;
    m_view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
}

void SceneDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QDockWidget::changeEvent(event);
}

void SceneDock::retranslateUi()
{
    setWindowTitle(tr("Scene"));
}

} // namespace stylos::app
