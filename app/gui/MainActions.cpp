#include "MainActions.h"

#include "ToolBarText.h"
#include "Translations.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QToolBar>
#include <QUndoStack>

namespace stylos::app {

namespace {
using core::view::StandardView;
constexpr std::array<StandardView, 7> Views = {StandardView::Front, StandardView::Back, StandardView::Left,
                                               StandardView::Right, StandardView::Top,  StandardView::Bottom,
                                               StandardView::Iso};
/** The viewport's own keys (its navigation, NavigationTool.h), as shortcuts active while it has the focus. */
const std::array<QKeySequence, 7> ViewKeys = {QKeySequence(Qt::Key_1), QKeySequence(Qt::CTRL | Qt::Key_1),
                                              QKeySequence(Qt::CTRL | Qt::Key_3), QKeySequence(Qt::Key_3),
                                              QKeySequence(Qt::Key_7), QKeySequence(Qt::CTRL | Qt::Key_7),
                                              QKeySequence(Qt::Key_0)};
} // namespace

MainActions::MainActions(widgets::SceneDocument& document, widgets::ViewportWidget* viewport,
                         Translations& translations, QWidget& window)
    : QObject(&window), m_document(document), m_viewport(viewport), m_translations(translations), m_window(window),
      m_undo(new QAction(this)), m_redo(new QAction(this)),
      m_remove(new QAction(this)), m_fitScene(new QAction(this)), m_fitSelection(new QAction(this)),
      m_orthographic(new QAction(this)), m_shading(new QActionGroup(this)), m_skydome(new QAction(this)),
      m_developpee(new QAction(this)), m_openDemo(new QAction(this)), m_languages(new QActionGroup(this)),
      m_about(new QAction(this))
{
    m_undo->setObjectName(QStringLiteral("actionUndo"));
    m_redo->setObjectName(QStringLiteral("actionRedo"));
    m_remove->setObjectName(QStringLiteral("actionRemove"));
    m_skydome->setObjectName(QStringLiteral("actionSkydome"));
    m_developpee->setObjectName(QStringLiteral("actionDeveloppee"));
    m_openDemo->setObjectName(QStringLiteral("actionOpenDemo"));
    m_orthographic->setObjectName(QStringLiteral("actionOrthographic"));
    m_undo->setShortcut(QKeySequence::Undo);
    m_redo->setShortcut(QKeySequence::Redo);
    m_remove->setShortcut(QKeySequence::Delete);
    m_skydome->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    m_developpee->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    m_undo->setIcon(QIcon::fromTheme(QStringLiteral("edit-undo")));
    m_redo->setIcon(QIcon::fromTheme(QStringLiteral("edit-redo")));
    m_remove->setIcon(QIcon::fromTheme(QStringLiteral("edit-delete")));
    m_fitScene->setIcon(QIcon::fromTheme(QStringLiteral("zoom-fit-best")));
    m_about->setMenuRole(QAction::AboutRole);
    m_remove->setEnabled(false);
    m_skydome->setEnabled(false);
    m_developpee->setEnabled(false);

    QUndoStack* stack = document.undoStack();
    m_undo->setEnabled(stack->canUndo());
    m_redo->setEnabled(stack->canRedo());
    connect(m_undo, &QAction::triggered, stack, &QUndoStack::undo);
    connect(m_redo, &QAction::triggered, stack, &QUndoStack::redo);
    connect(stack, &QUndoStack::canUndoChanged, m_undo, &QAction::setEnabled);
    connect(stack, &QUndoStack::canRedoChanged, m_redo, &QAction::setEnabled);
    connect(stack, &QUndoStack::undoTextChanged, this, &MainActions::retranslateUi);
    connect(stack, &QUndoStack::redoTextChanged, this, &MainActions::retranslateUi);
    connect(m_remove, &QAction::triggered, this, &MainActions::removeRequested);
    connect(m_skydome, &QAction::triggered, this, &MainActions::skydomeRequested);
    connect(m_developpee, &QAction::triggered, this, &MainActions::developpeeRequested);
    connect(m_openDemo, &QAction::triggered, this, &MainActions::openDemoRequested);
    connect(m_about, &QAction::triggered, this, &MainActions::about);
    addViewActions();

    for (const QString& code : QStringList{QString()} + Translations::languages()) {
        QAction* action = m_languages->addAction(code.isEmpty() ? QString() : Translations::nativeName(code));
        action->setCheckable(true);
        action->setData(code);
        action->setChecked(code == translations.language());
        connect(action, &QAction::triggered, this, [this, code] { m_translations.setLanguage(code); });
    }
    retranslateUi();
}

void MainActions::addViewActions()
{
    m_fitScene->setShortcut(QKeySequence(Qt::Key_F));
    m_fitSelection->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F));
    m_orthographic->setShortcut(QKeySequence(Qt::Key_5));
    m_orthographic->setCheckable(true);
    for (std::size_t i = 0; i < Views.size(); ++i) {
        m_views[i] = new QAction(this);
        m_views[i]->setShortcut(ViewKeys[i]);
    }
    for (int s = 0; s < 5; ++s) {
        QAction* action = m_shading->addAction(QString());
        action->setCheckable(true);
        action->setData(s);
    }
    if (!m_viewport) {
        for (QAction* a : {m_fitScene, m_fitSelection, m_orthographic}) a->setEnabled(false);
        for (QAction* a : m_views) a->setEnabled(false);
        m_shading->setEnabled(false);
        return;
    }
    // Single keys act only while the 3D view has the focus (they would steal typing elsewhere).
    for (QAction* a : {m_fitScene, m_fitSelection, m_orthographic}) {
        a->setShortcutContext(Qt::WidgetShortcut);
        m_viewport->addAction(a);
    }
    for (QAction* a : m_views) {
        a->setShortcutContext(Qt::WidgetShortcut);
        m_viewport->addAction(a);
    }
    connect(m_fitScene, &QAction::triggered, m_viewport, &widgets::ViewportWidget::fitToScene);
    connect(m_fitSelection, &QAction::triggered, m_viewport, &widgets::ViewportWidget::fitToSelection);
    connect(m_orthographic, &QAction::toggled, m_viewport, &widgets::ViewportWidget::setOrthographic);
    for (std::size_t i = 0; i < Views.size(); ++i)
        connect(m_views[i], &QAction::triggered, m_viewport, [this, i] { m_viewport->setStandardView(Views[i]); });
    connect(m_shading, &QActionGroup::triggered, this, [this](QAction* action) {
        m_viewport->setShading(static_cast<widgets::PointRenderer::Shading>(action->data().toInt()));
        Q_EMIT shadingChanged();
    });
    syncShading();
}

QMenu* MainActions::populate(QMenuBar& menuBar)
{
    m_edit = menuBar.addMenu(QString());
    m_edit->setObjectName(QStringLiteral("menuEdit"));
    m_edit->addAction(m_undo);
    m_edit->addAction(m_redo);
    m_edit->addSeparator();
    m_edit->addAction(m_remove);

    m_view = menuBar.addMenu(QString());
    m_view->setObjectName(QStringLiteral("menuView"));
    m_view->addAction(m_fitScene);
    m_view->addAction(m_fitSelection);
    m_standard = m_view->addMenu(QString());
    for (QAction* a : m_views) m_standard->addAction(a);
    m_view->addAction(m_orthographic);
    m_shadingMenu = m_view->addMenu(QString());
    m_shadingMenu->addActions(m_shading->actions());
    m_view->addSeparator();

    m_tools = menuBar.addMenu(QString());
    m_tools->setObjectName(QStringLiteral("menuTools"));
    m_tools->addAction(m_skydome);
    m_tools->addAction(m_developpee);

    m_help = menuBar.addMenu(QString());
    m_help->setObjectName(QStringLiteral("menuHelp"));
    m_help->addAction(m_openDemo);
    m_language = m_help->addMenu(QString());
    m_language->setObjectName(QStringLiteral("menuLanguage"));
    m_language->addActions(m_languages->actions());
    m_help->addSeparator();
    m_help->addAction(m_about);
    retranslateUi();
    return m_view;
}

void MainActions::populateToolBars(QToolBar& edit, QToolBar& view)
{
    edit.addAction(m_undo);
    edit.addAction(m_redo);
    view.addAction(m_fitScene);
    view.addAction(m_orthographic);
    view.addSeparator();
    view.addAction(m_skydome);
    view.addAction(m_developpee);
}

void MainActions::setSelectionCount(int count)
{
    m_remove->setEnabled(count > 0);
    m_skydome->setEnabled(count > 0);
    m_developpee->setEnabled(count == 1);
    m_fitSelection->setEnabled(m_viewport && count > 0);
}

void MainActions::syncShading()
{
    if (!m_viewport) return;
    const int current = static_cast<int>(m_viewport->shading());
    for (QAction* action : m_shading->actions()) action->setChecked(action->data().toInt() == current);
}

void MainActions::retranslateUi()
{
    if (m_edit) {
        m_edit->setTitle(tr("&Edit"));
        m_view->setTitle(tr("&View"));
        m_standard->setTitle(tr("Standard &views"));
        m_shadingMenu->setTitle(tr("&Shading"));
        m_tools->setTitle(tr("&Tools"));
        m_help->setTitle(tr("&Help"));
        m_language->setTitle(tr("&Language"));
    }
    // "Undo Import drum.ply": the step's own text (already translated when it was pushed).
    const QUndoStack* stack = m_document.undoStack();
    m_undo->setText(stack->undoText().isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(stack->undoText()));
    m_redo->setText(stack->redoText().isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(stack->redoText()));
    m_undo->setStatusTip(tr("Undo the last change to the scene"));
    m_redo->setStatusTip(tr("Redo the change undone last"));
    m_remove->setText(tr("&Remove from the scene"));
    m_fitScene->setText(tr("&Fit to the scene"));
    m_fitSelection->setText(tr("Fit to the &selection"));
    const QStringList viewNames = {tr("Front"), tr("Back"), tr("Left"), tr("Right"), tr("Top"), tr("Bottom"),
                                   tr("Isometric")};
    for (std::size_t i = 0; i < m_views.size(); ++i) m_views[i]->setText(viewNames[static_cast<int>(i)]);
    m_orthographic->setText(tr("&Orthographic"));
    const QStringList shadingNames = {tr("&Headlight"), tr("S&kydome"), tr("Scan &colour"),
                                      tr("&Eye-dome lighting"), tr("&Annotation")};
    for (QAction* action : m_shading->actions()) action->setText(shadingNames.value(action->data().toInt()));
    m_skydome->setText(tr("Compute &skydome"));
    m_skydome->setStatusTip(tr("Compute the 3D skydome (ambient occlusion) of the selected fragments in the "
                               "background; the view then shades them by it"));
    m_developpee->setText(tr("&Développée"));
    m_developpee->setStatusTip(tr("Unroll the selected fragment in the Développée dock"));
    m_openDemo->setText(tr("Open &demo"));
    m_openDemo->setStatusTip(tr("Open the demo scene: a fluted drum, two of its fragments and an omphalos"));
    for (QAction* action : m_languages->actions())
        if (action->data().toString().isEmpty()) action->setText(tr("System language"));
    m_about->setText(tr("&About Stylos"));
    // The toolbar's short labels; the tooltips carry the full text ("Undo Move Fragment A") and the shortcut.
    setToolBarText(*m_undo, tr("Undo", "toolbar"));
    setToolBarText(*m_redo, tr("Redo", "toolbar"));
    setToolBarText(*m_fitScene, tr("Fit", "toolbar"));
    setToolBarText(*m_orthographic, tr("Orthographic", "toolbar"));
    setToolBarText(*m_skydome, tr("Skydome", "toolbar"));
    setToolBarText(*m_developpee, tr("Développée", "toolbar"));
}

void MainActions::about()
{
    QMessageBox::about(&m_window, tr("About Stylos"),
                       tr("<h3>Stylos %1</h3><p>A workbench for very large 3D scans of monuments: column drums, "
                          "capitals, fragments.</p><p>Point-based, after Duguet, Drettakis, Girardeau-Montaut, "
                          "Martinez and Schneider (VAST 2004).</p>")
                           .arg(QCoreApplication::applicationVersion()));
}

} // namespace stylos::app
