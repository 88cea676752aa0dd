// The window all day: the display controls labelled (and translated), undo and redo from a number field or
// a text field, rename by F2 or a double click only (a click on the selected row starts nothing), the demo's
// names and the undo steps' texts in the language chosen last, docks as wide as their contents, imports
// side by side, Fit filling the view; the toolbars, the status bar and the Legend dock whole in French and Greek
// at 1600 × 1000 and 1280 × 800 (the messages' and Qt's dialogs' words: LanguageTextsTest). Synthesized keys and
// clicks, through the real shortcut map.
#include "AnnotationActions.h"
#include "DisplaySettingsWidget.h"
#include "DrumOctreeFixture.h"
#include "LegendDock.h"
#include "MainActions.h"
#include "MainWindow.h"
#include "ProjectActions.h"
#include "PropertiesDock.h"
#include "SceneDock.h"
#include "StatusMessage.h"
#include "ToolBarRows.h"
#include "Translations.h"
#include "WidgetTestSupport.h"
#include "stylos/core/scene/ImportPlacement.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/core/view/ScenePick.h"
#include "stylos/widgets/annotation/ClassMeasures.h"
#include "stylos/widgets/annotation/LegendWidget.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/DemoScene.h"
#include "stylos/widgets/document/FragmentPropertiesWidget.h"
#include "stylos/widgets/document/ScanImporter.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/document/SceneTreeModel.h"
#include "stylos/widgets/tasks/TaskManager.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QAbstractButton>
#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QStatusBar>
#include <QStatusTipEvent>
#include <QCheckBox>
#include <QSettings>
#include <QSlider>
#include <QStyleHints>
#include <QTemporaryDir>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QTreeWidget>
#include <QUndoStack>

#include <algorithm>
#include <memory>

using namespace stylos;

namespace {
/** Whether the tree has a rename editor open (the delegate's line edit, on its viewport). */
/** The tree's open name editor, or nullptr. */
QLineEdit* openEditor(QTreeView* tree)
{
    for (QLineEdit* editor : tree->viewport()->findChildren<QLineEdit*>())
        if (editor->isVisible()) return editor;
    return nullptr;
}
bool editorOpen(QTreeView* tree) { return openEditor(tree) != nullptr; }

const QList<QSize> WindowSizes = {QSize(1600, 1000), QSize(1280, 800)};
const QStringList Languages = {QStringLiteral("en"), QStringLiteral("fr"), QStringLiteral("el")};

/** "fr 1280×800: " for the failure messages. */
QString where(const QString& code, QSize size)
{
    return QStringLiteral("%1 %2×%3: ").arg(code).arg(size.width()).arg(size.height());
}
} // namespace

class WindowUsabilityTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void displayControlsAreLabelledAndTranslated();
    void gapFillingIsOnByDefaultSwitchesOffAndIsKept();
    void undoAndRedoFromANumberFieldOrATextField();
    void renameByF2OrDoubleClickOnly();
    void undoTextsFollowTheLanguage();
    void demoNamesFollowTheLanguage();
    void docksShowEveryLabelInEveryLanguage();
    void toolBarsShowEveryActionInEveryLanguage();
    void statusBarCutsWithAnEllipsisAndKeepsTheWhole();
    void aPickedPointsLineGoesWithItsFragment();
    void legendShowsEveryColumnInEveryLanguage();
    void importsGoSideBySideAndFitFillsTheView();

private:
    std::unique_ptr<app::MainWindow> makeWindow();
    void importDrum(app::MainWindow& window);
    void setLanguage(const QString& code);

    QTemporaryDir m_dir;
    test::DrumOctree m_drum;
    std::unique_ptr<app::Translations> m_translations;
};

void WindowUsabilityTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = test::makeDrumOctree(m_dir.path());
    m_translations = std::make_unique<app::Translations>();
}

void WindowUsabilityTest::init() { QSettings().clear(); }

void WindowUsabilityTest::cleanup()
{
    setLanguage(QStringLiteral("en"));
    QSettings().clear();
}

void WindowUsabilityTest::setLanguage(const QString& code)
{
    QVERIFY(m_translations->setLanguage(code));
    QCoreApplication::processEvents(); // LanguageChange is posted
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

std::unique_ptr<app::MainWindow> WindowUsabilityTest::makeWindow()
{
    auto window = std::make_unique<app::MainWindow>(*m_translations, m_dir.filePath("demo"));
    window->setErrorDialogsEnabled(false);
    window->importer().setCacheDirectory(m_dir.filePath("octrees"));
    window->resize(1280, 800);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) qWarning("window not exposed");
    return window;
}

void WindowUsabilityTest::importDrum(app::MainWindow& window)
{
    window.projectActions().openPaths({QString::fromStdString(m_drum.poct.string())});
    QVERIFY(window.tasks().waitForIdle(60000));
    QTRY_VERIFY_WITH_TIMEOUT(!window.isBusy(), 10000);
}

void WindowUsabilityTest::displayControlsAreLabelledAndTranslated()
{
    auto window = makeWindow();
    app::DisplaySettingsWidget* display = window->propertiesDock().displaySettings();
    if (!display) QSKIP("no OpenGL 3.3: no 3D view, no display settings");
    const QList<QWidget*> fields = {display->shadingBox(), display->annotationLayerBox(), display->splatSpin(),
                                    display->budgetSpin(), display->detailBox(), display->levelSlider(),
                                    display->gapFillBox()};
    const QStringList english = {QStringLiteral("Shading"), QStringLiteral("Annotation layer"), QStringLiteral("Splat size"),
                                 QStringLiteral("Point budget"), QStringLiteral("Level of detail"),
                                 QStringLiteral("Octree level"), QStringLiteral("Fill gaps")};
    // A fresh workbench draws splats at the size the renderer was measured at (1.5: 1.4 % holes on the Buddha
    // close-up against 5.1 % at 1.0, docs/benchmarks.md); the field said 1.00 and set the view to it.
    QCOMPARE(display->splatSpin()->value(), 1.5);
    if (widgets::ViewportWidget* viewport = window->viewport()) QCOMPARE(viewport->splatFactor(), 1.5);
    for (int row = 0; row < fields.size(); ++row) {
        QLabel* label = display->label(row);
        QVERIFY(label);
        QCOMPARE(label->text(), english[row]);
        QVERIFY(label->isVisible());
        QCOMPARE(label->buddy(), fields[row]);
        QVERIFY2(!fields[row]->toolTip().isEmpty(), qPrintable(english[row]));
    }
    for (const QString& code : {QStringLiteral("fr"), QStringLiteral("el")}) {
        setLanguage(code);
        for (int row = 0; row < fields.size(); ++row) {
            const QString text = display->label(row)->text();
            QVERIFY2(!text.isEmpty() && text != english[row], qPrintable(code + QLatin1Char(' ') + text));
            QCOMPARE(text, QCoreApplication::translate("stylos::app::DisplaySettingsWidget", qPrintable(english[row])));
        }
    }
}

void WindowUsabilityTest::gapFillingIsOnByDefaultSwitchesOffAndIsKept()
{
    {
        auto window = makeWindow();
        app::DisplaySettingsWidget* display = window->propertiesDock().displaySettings();
        if (!display) QSKIP("no OpenGL 3.3: no 3D view, no display settings");
        QVERIFY(display->gapFillBox()->isChecked());
        QVERIFY(window->viewport()->gapFilling());
        display->gapFillBox()->setChecked(false);
        QVERIFY(!window->viewport()->gapFilling());
        QCOMPARE(QSettings().value(QStringLiteral("view/gapFill")).toBool(), false);
    }
    auto window = makeWindow(); // a new session restores it
    QVERIFY(!window->propertiesDock().displaySettings()->gapFillBox()->isChecked());
    QVERIFY(!window->viewport()->gapFilling());
}

void WindowUsabilityTest::undoAndRedoFromANumberFieldOrATextField()
{
    auto window = makeWindow();
    importDrum(*window);
    widgets::SceneDocument& document = window->document();
    const auto id = document.scene().fragments().front().id;
    window->sceneDock().selectFragment(id);
    QVERIFY(document.renameFragment(id, QStringLiteral("Drum III")));
    QCOMPARE(document.nameOf(id), QStringLiteral("Drum III"));

    widgets::FragmentPropertiesWidget* properties = window->propertiesDock().fragmentWidget();
    QDoubleSpinBox* spin = properties->poseSpin(0);
    QLineEdit* name = properties->nameEdit();
    for (QWidget* field : {static_cast<QWidget*>(spin), static_cast<QWidget*>(name)}) {
        window->activateWindow();
        field->setFocus(Qt::OtherFocusReason);
        QTRY_VERIFY(field->hasFocus());
        const int index = document.undoStack()->index();
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(document.undoStack()->index(), index - 1);
        QCOMPARE(document.nameOf(id), QStringLiteral("drum"));
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(document.undoStack()->index(), index);
        QCOMPARE(document.nameOf(id), QStringLiteral("Drum III"));
    }
    // A value typed into the spin box is a step of its own, and Ctrl+Z there undoes it, not its text.
    window->activateWindow();
    spin->setFocus(Qt::OtherFocusReason);
    const double before = document.worldPose(id).translationPart()[0]; // the fixture is in a site frame
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("7"));
    QTest::keyClick(spin, Qt::Key_Return);
    QCOMPARE(document.worldPose(id).translationPart()[0], 7.0);
    QTest::keyClick(spin, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(document.worldPose(id).translationPart()[0], before);
    QCOMPARE(document.nameOf(id), QStringLiteral("Drum III"));
}

void WindowUsabilityTest::renameByF2OrDoubleClickOnly()
{
    auto window = makeWindow();
    importDrum(*window);
    widgets::SceneDocument& document = window->document();
    const auto id = document.scene().fragments().front().id;
    QVERIFY(document.setFragmentVisible(id, false)); // a step to undo
    QVERIFY(document.setFragmentVisible(id, true));
    QTreeView* tree = window->sceneDock().view();
    const QModelIndex row = window->sceneDock().model()->indexOf(id);
    window->sceneDock().selectFragment(id);
    window->activateWindow(); // focus goes only to a widget of the active window
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    tree->setFocus(Qt::OtherFocusReason);
    QTRY_VERIFY(tree->hasFocus());
    const QPoint centre = tree->visualRect(row).center();
    // A click on the selected row, then time for a delayed edit to begin: none does.
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, centre);
    QTest::qWait(2 * QGuiApplication::styleHints()->mouseDoubleClickInterval());
    QVERIFY(!editorOpen(tree));
    QVERIFY(!qobject_cast<QLineEdit*>(QApplication::focusWidget()));
    // The next shortcut reaches the document.
    const int index = document.undoStack()->index();
    QTest::keyClick(tree, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(document.undoStack()->index(), index - 1);
    QVERIFY(!document.fragment(id)->visible);
    QTest::keyClick(tree, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(document.fragment(id)->visible);

    // F2 renames.
    QTest::keyClick(tree, Qt::Key_F2);
    QVERIFY(editorOpen(tree));
    QLineEdit* editor = openEditor(tree);
    QVERIFY(editor);
    editor->setText(QStringLiteral("Drum IV"));
    QTest::keyClick(editor, Qt::Key_Return);
    QTRY_COMPARE(document.nameOf(id), QStringLiteral("Drum IV")); // the delegate commits on the next turn
    QTRY_VERIFY(!editorOpen(tree));
    // So does a double click.
    QTest::mouseDClick(tree->viewport(), Qt::LeftButton, {}, centre);
    QTRY_VERIFY(editorOpen(tree));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    QCOMPARE(document.nameOf(id), QStringLiteral("Drum IV"));
}

void WindowUsabilityTest::undoTextsFollowTheLanguage()
{
    auto window = makeWindow();
    importDrum(*window);
    widgets::SceneDocument& document = window->document();
    const auto id = document.scene().fragments().front().id;
    QVERIFY(document.setFragmentPose(id, core::scene::Pose::translation({1, 0, 0})));
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Move drum"));
    QCOMPARE(document.undoStack()->text(0), QStringLiteral("Import drum.poct"));
    const QString remove = QStringLiteral("Remove %n fragment(s)");
    document.beginMacro([] { return app::MainWindow::tr("Remove %n fragment(s)", nullptr, 2); });
    QVERIFY(document.setFragmentVisible(id, false));
    document.endMacro();
    QCOMPARE(document.undoStack()->undoText(), app::MainWindow::tr("Remove %n fragment(s)", nullptr, 2));
    QAction* undo = window->actions().undoAction();
    for (const QString& code : {QStringLiteral("fr"), QStringLiteral("el")}) {
        setLanguage(code);
        const QString move = QCoreApplication::translate("stylos::widgets::SetFragmentPoseCommand", "Move %1")
                                 .arg(QStringLiteral("drum"));
        const QString import = QCoreApplication::translate("stylos::widgets::ScanImporter", "Import %1")
                                   .arg(QStringLiteral("drum.poct"));
        const QString macro = QCoreApplication::translate("stylos::app::MainWindow", "Remove %n fragment(s)", nullptr, 2);
        QVERIFY2(move != QStringLiteral("Move drum") && import != QStringLiteral("Import drum.poct") &&
                     macro != QStringLiteral("Remove 2 fragments"),
                 qPrintable(code + QLatin1Char(' ') + move + QLatin1Char(' ') + import + QLatin1Char(' ') + macro));
        QCOMPARE(document.undoStack()->text(0), import);
        QCOMPARE(document.undoStack()->text(1), move);
        QCOMPARE(document.undoStack()->undoText(), macro);
        QVERIFY2(undo->text().contains(macro), qPrintable(undo->text()));
        document.undoStack()->undo();
        QVERIFY2(undo->text().contains(move), qPrintable(undo->text()));
        document.undoStack()->redo();
    }
    Q_UNUSED(remove);
}

void WindowUsabilityTest::demoNamesFollowTheLanguage()
{
    // The demo cached in English, opened in French: its names are French; switched to Greek while open:
    // Greek, except the one the user renamed; the undo step that names a fragment follows.
    auto window = makeWindow();
    window->demo().setSpacing(0.012);
    window->openDemo();
    QTRY_VERIFY_WITH_TIMEOUT(!window->document().scene().empty(), 120000);
    QVERIFY(window->tasks().waitForIdle(60000));
    QTRY_VERIFY_WITH_TIMEOUT(!window->isBusy(), 20000);
    QCOMPARE(window->document().scene().fragments().front().name, std::string("Drum"));
    window->close();
    window.reset();

    setLanguage(QStringLiteral("fr"));
    window = makeWindow();
    window->demo().setSpacing(0.012);
    window->openDemo();
    QTRY_VERIFY_WITH_TIMEOUT(!window->isBusy() && !window->document().scene().empty(), 60000);
    widgets::SceneDocument& document = window->document();
    const auto names = widgets::DemoScene::names();
    const auto& fragments = document.scene().fragments();
    QCOMPARE(fragments.size(), std::size_t{4});
    for (std::size_t i = 0; i < fragments.size(); ++i)
        QCOMPARE(QString::fromStdString(fragments[i].name), names.items[static_cast<int>(i)]);
    QVERIFY(names.items[0] != QStringLiteral("Drum"));
    const auto& drum = fragments.front();
    QVERIFY(!drum.guides.empty());
    QCOMPARE(QString::fromStdString(drum.guides.front().name), names.axis);
    QVERIFY(names.axis != QStringLiteral("Axis"));
    QCOMPARE(QString::fromStdString(document.scene().assemblies().front().name), names.assembly);
    QVERIFY(!document.isModified());

    // The user renames the omphalos and moves Fragment A; then Greek.
    const auto omphalos = fragments[3].id, fragmentA = fragments[1].id;
    QVERIFY(document.renameFragment(omphalos, QStringLiteral("Mine")));
    QVERIFY(document.setFragmentPose(fragmentA, core::scene::Pose::translation({0, 0, 1})));
    setLanguage(QStringLiteral("el"));
    const auto greek = widgets::DemoScene::names();
    QCOMPARE(document.nameOf(fragmentA), greek.items[1]);
    QVERIFY(greek.items[1] != names.items[1]);
    QCOMPARE(document.nameOf(omphalos), QStringLiteral("Mine"));
    QCOMPARE(QString::fromStdString(document.fragment(drum.id)->guides.front().name), greek.axis);
    QCOMPARE(document.undoStack()->undoText(),
             QCoreApplication::translate("stylos::widgets::SetFragmentPoseCommand", "Move %1").arg(greek.items[1]));
    // The tree shows the new names.
    const widgets::SceneTreeModel& tree = *window->sceneDock().model();
    QCOMPARE(tree.indexOf(fragmentA).data().toString(), greek.items[1]);
}

void WindowUsabilityTest::docksShowEveryLabelInEveryLanguage()
{
    // In each language and at both window sizes, at the window's default layout, no label of any dock is cut: each
    // is as wide as its text needs (or wraps), and every field gets at least its minimum size.
    for (const QString& code : Languages) {
        setLanguage(code);
        for (const QSize size : WindowSizes) {
            const QString at = where(code, size);
            auto window = makeWindow();
            window->resize(size);
            importDrum(*window);
            window->sceneDock().selectFragment(window->document().scene().fragments().front().id);
            QTest::qWait(100); // the layout requests settle: contents → the scroll area's minimum → the dock → the window
            // The Properties dock's contents fit its width: nothing cut on the right.
            auto* scroll = window->propertiesDock().findChild<QScrollArea*>();
            QVERIFY(scroll && scroll->widget());
            QVERIFY2(scroll->widget()->minimumSizeHint().width() <= scroll->viewport()->width(),
                     qPrintable(at + QStringLiteral("contents need ") +
                                QString::number(scroll->widget()->minimumSizeHint().width()) +
                                QStringLiteral(", the dock shows ") + QString::number(scroll->viewport()->width())));
            QVERIFY(scroll->widget()->width() <= scroll->viewport()->width());
            for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
                if (!dock->isVisible()) continue;
                const QString in = at + dock->objectName() + QStringLiteral(": ");
                for (QLabel* label : dock->findChildren<QLabel*>()) {
                    if (!label->isVisible() || label->text().isEmpty() || label->wordWrap() ||
                        label->sizePolicy().horizontalPolicy() == QSizePolicy::Ignored)
                        continue;
                    QVERIFY2(label->width() >= label->minimumSizeHint().width(),
                             qPrintable(in + QLatin1Char('\'') + label->text() + QStringLiteral("' ") +
                                        QString::number(label->width()) + QStringLiteral(" < ") +
                                        QString::number(label->minimumSizeHint().width())));
                }
                for (QWidget* field : dock->findChildren<QWidget*>()) {
                    if (!field->isVisible() ||
                        !(qobject_cast<QAbstractSpinBox*>(field) || qobject_cast<QComboBox*>(field) ||
                          qobject_cast<QLineEdit*>(field) || qobject_cast<QAbstractButton*>(field)) ||
                        qobject_cast<QAbstractSpinBox*>(field->parentWidget()) ||
                        qobject_cast<QComboBox*>(field->parentWidget()) ||
                        qobject_cast<QAbstractItemView*>(field->parentWidget()->parentWidget()) ||
                        field->objectName().startsWith(QStringLiteral("qt_"))) // the dock's title buttons
                        continue;
                    QVERIFY2(field->width() >= field->minimumSizeHint().width(),
                             qPrintable(in + field->objectName() + QLatin1Char(' ') +
                                        field->property("text").toString() + QLatin1Char(' ') +
                                        QString::number(field->width()) + QStringLiteral(" < ") +
                                        QString::number(field->minimumSizeHint().width())));
                }
            }
        }
    }
}

void WindowUsabilityTest::toolBarsShowEveryActionInEveryLanguage()
{
    // Every action of every toolbar on a button of its own that shows whole inside the window, none behind the
    // » extension; the lasso on, so that its class box and Erase show too. Short labels, translated; the full text
    // and the shortcut in the tooltip.
    for (const QString& code : Languages) {
        setLanguage(code);
        for (const QSize size : WindowSizes + QList<QSize>{QSize(1000, 700)}) {
            const QString at = where(code, size);
            auto window = makeWindow();
            window->resize(size);
            if (window->viewport()) window->annotation().lassoAction()->setChecked(true);
            QTest::qWait(50);
            window->toolBarRows().update();
            QTest::qWait(50); // the main window lays the rows out
            int buttons = 0;
            for (QToolBar* bar : window->findChildren<QToolBar*>()) {
                if (!bar->isVisible()) continue;
                const QRect barRect(bar->mapTo(window.get(), QPoint(0, 0)), bar->size());
                QVERIFY2(window->rect().contains(barRect), qPrintable(at + bar->objectName()));
                for (QToolButton* extension : bar->findChildren<QToolButton*>(QStringLiteral("qt_toolbar_ext_button")))
                    QVERIFY2(!extension->isVisible(), qPrintable(at + bar->objectName() + QStringLiteral(": » shown")));
                for (QAction* action : bar->actions()) {
                    if (action->isSeparator() || !action->isVisible()) continue;
                    QWidget* widget = bar->widgetForAction(action);
                    const QString name = at + action->objectName() + QLatin1Char(' ') + action->iconText();
                    QVERIFY2(widget && widget->isVisible(), qPrintable(name + QStringLiteral(" hidden")));
                    QVERIFY2(bar->rect().contains(widget->geometry()), qPrintable(name + QStringLiteral(" cut")));
                    QVERIFY2(widget->width() >= widget->sizeHint().width(),
                             qPrintable(name + QStringLiteral(" narrower than its text")));
                    ++buttons;
                    if (qobject_cast<QToolButton*>(widget)) {
                        QVERIFY2(!action->toolTip().isEmpty(), qPrintable(name));
                        if (!action->shortcut().isEmpty())
                            QVERIFY2(action->toolTip().contains(action->shortcut().toString(QKeySequence::NativeText)),
                                     qPrintable(name + QStringLiteral(": ") + action->toolTip()));
                    }
                }
            }
            QVERIFY2(buttons >= 10, qPrintable(at + QString::number(buttons)));
            // The toolbar's labels are short and in the language chosen.
            QAction* skydome = window->actions().skydomeAction();
            QCOMPARE(skydome->iconText(), QCoreApplication::translate("stylos::app::MainActions", "Skydome", "toolbar"));
            if (code != QStringLiteral("en"))
                QVERIFY2(window->projectActions().openAction()->iconText() != QStringLiteral("Open"),
                         qPrintable(at + QStringLiteral("Open left in English")));
            QVERIFY2(skydome->toolTip().startsWith(skydome->text().remove(QLatin1Char('&'))),
                     qPrintable(at + skydome->toolTip()));
            // 1000 pixels do not hold both toolbars on one row in Greek; 1600 do in English.
            if (code == QStringLiteral("el") && size.width() == 1000) QVERIFY(window->toolBarRows().isSplit());
            if (code == QStringLiteral("en") && size.width() == 1600) QVERIFY(!window->toolBarRows().isSplit());
        }
    }
}

// The line a picked point leaves in the status bar ("x … on drum") goes when its fragment does, or with the
// project (it stayed after File › New, naming a fragment no longer there).
void WindowUsabilityTest::aPickedPointsLineGoesWithItsFragment()
{
    auto window = makeWindow();
    importDrum(*window);
    importDrum(*window);
    widgets::ViewportWidget* viewport = window->viewport();
    if (!viewport) QSKIP("no OpenGL 3.3: no 3D view to pick in");
    widgets::SceneDocument& document = window->document();
    const auto first = document.scene().fragments()[0].id, second = document.scene().fragments()[1].id;
    app::StatusMessage& message = window->statusMessage();
    Q_EMIT viewport->pointPicked(Eigen::Vector3d(0.5, 0.25, 1.0), first);
    const QString picked = message.message();
    QVERIFY2(picked.endsWith(QStringLiteral(" on drum")), qPrintable(picked));
    QVERIFY(document.removeFragment(second)); // another fragment: the line stays
    QCOMPARE(message.message(), picked);
    QVERIFY(document.removeFragment(first));
    QCOMPARE(message.message(), QString());
    importDrum(*window);
    Q_EMIT viewport->pointPicked(Eigen::Vector3d(0.5, 0.25, 1.0), document.scene().fragments()[0].id);
    QVERIFY(!message.message().isEmpty());
    document.newProject();
    QCOMPARE(message.message(), QString());

    // A status tip (hovering the lasso's button) takes the line, cut with "…" before the readout (Qt's own status
    // bar cut it without one, into the coordinates), and leaves the message to come back.
    message.showMessage(QStringLiteral("Imported drum"));
    const QString tip = window->annotation().lassoAction()->statusTip();
    QStatusTipEvent hover(tip);
    QCoreApplication::sendEvent(window.get(), &hover);
    QCOMPARE(window->statusBar()->currentMessage(), QString());
    QCOMPARE(message.toolTip(), tip);
    QVERIFY2(message.fontMetrics().horizontalAdvance(tip) > message.contentsRect().width(), "the tip fits: nothing checked");
    QVERIFY2(message.text().endsWith(QStringLiteral("…")) && tip.startsWith(message.text().chopped(1)), qPrintable(message.text()));
    QStatusTipEvent leave{QString()};
    QCoreApplication::sendEvent(window.get(), &leave);
    QCOMPARE(message.text(), QStringLiteral("Imported drum"));
}

void WindowUsabilityTest::statusBarCutsWithAnEllipsisAndKeepsTheWhole()
{
    // The développée's summary reported at 1280 × 800 in Greek: the status bar shows its start, cut with "…" to the
    // width left by the readout, never widening the window; the tooltip and the Développée dock have it whole.
    setLanguage(QStringLiteral("el"));
    auto window = makeWindow();
    importDrum(*window);
    app::StatusMessage& message = window->statusMessage();
    QCOMPARE(message.message(),
             QCoreApplication::translate("stylos::app::MainWindow", "Imported %1").arg(QStringLiteral("drum")));
    window->sceneDock().selectFragment(window->document().scene().fragments().front().id);
    window->actions().developpeeAction()->trigger();
    QVERIFY(window->tasks().waitForIdle(60000));
    QTRY_VERIFY(window->developpeePanel().view()->hasDeveloppee());
    const QString summary = window->developpeePanel().statusText();
    QTRY_COMPARE(message.message(), summary);
    QCOMPARE(message.toolTip(), summary);
    QVERIFY2(message.fontMetrics().horizontalAdvance(summary) > message.contentsRect().width(),
             "the summary fits anyway: this test checks nothing");
    QVERIFY(message.isElided());
    QVERIFY2(message.text().endsWith(QStringLiteral("…")), qPrintable(message.text()));
    QVERIFY(summary.startsWith(message.text().chopped(1)));
    QVERIFY2(message.fontMetrics().horizontalAdvance(message.text()) <= message.contentsRect().width(),
             qPrintable(message.text()));
    const QRect shown(message.mapTo(window.get(), QPoint(0, 0)), message.size());
    QVERIFY(window->rect().contains(shown));
    QCOMPARE(window->width(), 1280);
    // Wider, it shows more of the same text.
    const int before = int(message.text().size());
    window->resize(1600, 1000);
    QTRY_VERIFY(message.text().size() > before);
    // A message that fits is shown as it is.
    message.showMessage(QStringLiteral("short"));
    QCOMPARE(message.text(), QStringLiteral("short"));
    QVERIFY(!message.isElided());
}

void WindowUsabilityTest::legendShowsEveryColumnInEveryLanguage()
{
    // The Legend dock at the default layout: every column (class, hatch, cells, area) as wide as its header and its
    // values, and all of them inside the tree's viewport (no column scrolled out of sight), at both window sizes.
    for (const QString& code : Languages) {
        setLanguage(code);
        for (const QSize size : WindowSizes) {
            const QString at = where(code, size);
            auto window = makeWindow();
            window->resize(size);
            importDrum(*window);
            if (auto* measures = window->findChild<widgets::ClassMeasures*>())
                QTRY_VERIFY_WITH_TIMEOUT(!measures->isBusy(), 20000);
            QTest::qWait(100);
            QTreeWidget* tree = window->legendDock().legend().tree();
            QVERIFY(tree->isVisible());
            QHeaderView* header = tree->header();
            const QAbstractItemView* view = tree;
            int total = 0;
            for (int column = 0; column < header->count(); ++column) {
                const int needed = std::max(view->sizeHintForColumn(column), header->sectionSizeHint(column));
                QVERIFY2(header->sectionSize(column) >= needed,
                         qPrintable(at + tree->headerItem()->text(column) + QLatin1Char(' ') +
                                    QString::number(header->sectionSize(column)) + QStringLiteral(" < ") +
                                    QString::number(needed)));
                total += header->sectionSize(column);
            }
            QVERIFY2(total <= tree->viewport()->width(),
                     qPrintable(at + QStringLiteral("columns ") + QString::number(total) + QStringLiteral(" > ") +
                                QString::number(tree->viewport()->width())));
            const QRect dock(window->legendDock().mapTo(window.get(), QPoint(0, 0)), window->legendDock().size());
            QVERIFY2(window->rect().contains(dock), qPrintable(at));
            if (code != QStringLiteral("en"))
                QVERIFY2(tree->headerItem()->text(3) != QStringLiteral("Area (m²)"), qPrintable(at));
        }
    }
}

void WindowUsabilityTest::importsGoSideBySideAndFitFillsTheView()
{
    auto window = makeWindow();
    importDrum(*window);
    importDrum(*window); // the same drum again
    widgets::SceneDocument& document = window->document();
    const auto& fragments = document.scene().fragments();
    QCOMPARE(fragments.size(), std::size_t{2});
    const auto octree = document.octree(fragments[1].id);
    QVERIFY(octree);
    const Eigen::AlignedBox3d local = core::view::occupiedBounds(*octree);
    const Eigen::AlignedBox3d first = core::scene::worldBounds({local, document.worldPose(fragments[0].id)});
    const Eigen::AlignedBox3d second = core::scene::worldBounds({local, document.worldPose(fragments[1].id)});
    // The fixture drum is in a site frame: the first import is brought near the origin by one offset.
    QVERIFY(document.worldPose(fragments[0].id) == core::scene::placeImport({}, local));
    // The same drum again shares that site frame: it comes at its true coordinates, through the same offset (two
    // scans of one monument stay registered). Scans near the origin go side by side (ImportPlacementTest).
    QVERIFY(document.worldPose(fragments[1].id) == document.worldPose(fragments[0].id));
    QVERIFY(first.isApprox(second));

    widgets::ViewportWidget* viewport = window->viewport();
    if (!viewport) QSKIP("no OpenGL 3.3: no 3D view to fit");
    QTRY_COMPARE(viewport->fragments().size(), std::size_t{2});
    viewport->fitToScene();
    // Every occupied cell in view, and the scene's picture reaches at least 85 % of the half width or height.
    const auto corners = core::view::sceneCorners(viewport->fragments());
    double reach = 0;
    const double w = viewport->camera().width(), h = viewport->camera().height();
    for (const auto& c : corners) {
        const auto p = viewport->camera().project(c);
        QVERIFY(p);
        QVERIFY(p->x() >= -1e-6 && p->x() <= w + 1e-6 && p->y() >= -1e-6 && p->y() <= h + 1e-6);
        reach = std::max({reach, std::abs(p->x() - w / 2) / (w / 2), std::abs(p->y() - h / 2) / (h / 2)});
    }
    QVERIFY2(reach > 0.85 && reach < 1.0, qPrintable(QString::number(reach)));
}

STYLOS_WIDGET_TEST_MAIN(WindowUsabilityTest)
#include "WindowUsabilityTest.moc"
