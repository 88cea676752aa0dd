#pragma once
/** @file
 * @brief The Stylos main window. It only wires: the scene document with its undo stack, the task
 *        manager, the importer and the demo; the 3D view in the centre (a message in its place without
 *        OpenGL 3.3); the Scene, Properties, Tasks, Développée and Log docks; the menus, toolbar and
 *        status bar; window settings; and the reporting of what happened (log, status bar, message boxes).
 */
#include <QMainWindow>
#include <QStringList>

class QDockWidget;
class QToolBar;

namespace stylos::widgets {
class DemoScene;
class ClassMeasures;
class DeveloppeeAnnotator;
class DeveloppeePanel;
class ScanImporter;
class SceneDocument;
class SkydomeRunner;
class TaskManager;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class AnnotationActions;
class AnnotationSync;
class DeveloppeeDock;
class AssemblyActions;
class DockingActions;
class DeveloppeeLink;
class LegendDock;
class LogDock;
class MainActions;
class PlateActions;
class ProjectActions;
class PropertiesDock;
class SceneDock;
class StatusMessage;
class StatusReadout;
class ToolBarRows;
class TasksDock;
class Translations;
class ViewportSync;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    /** @p translations switches the language (Help › Language; not owned). The demo goes to
     *  @p demoDirectory, or to the user cache when empty. */
    explicit MainWindow(Translations& translations, const QString& demoDirectory = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    widgets::TaskManager& tasks() const { return *m_tasks; }
    widgets::SceneDocument& document() const { return *m_document; }
    widgets::ScanImporter& importer() const { return *m_importer; }
    widgets::DemoScene& demo() const { return *m_demo; }
    widgets::SkydomeRunner& skydome() const { return *m_skydome; }
    /** @brief Null when this platform has no OpenGL 3.3 core (a message stands in its place). */
    widgets::ViewportWidget* viewport() const { return m_viewport; }
    /** @brief What feeds the 3D view from the document; null without a view. */
    ViewportSync* viewportSync() const { return m_sync; }
    SceneDock& sceneDock() const { return *m_sceneDock; }
    PropertiesDock& propertiesDock() const { return *m_propertiesDock; }
    widgets::DeveloppeePanel& developpeePanel() const;
    DeveloppeeLink& developpeeLink() const { return *m_developpeeLink; }
    LogDock& logDock() const { return *m_logDock; }
    LegendDock& legendDock() const { return *m_legendDock; }
    widgets::DeveloppeeAnnotator& annotator() const { return *m_annotator; }
    ProjectActions& projectActions() const { return *m_projectActions; }
    PlateActions& plateActions() const { return *m_plates; }
    MainActions& actions() const { return *m_actions; }
    DockingActions& docking() const { return *m_docking; }
    AssemblyActions& assemblies() const { return *m_assemblies; }
    AnnotationActions& annotation() const { return *m_annotation; }
    /** @brief What feeds the 3D view's annotation tint; null without a view. */
    AnnotationSync* annotationSync() const { return m_annotationSync; }
    StatusReadout& readout() const { return *m_readout; }
    /** @brief The status bar's message (the last report, cut to the width; the whole as its tooltip). */
    StatusMessage& statusMessage() const { return *m_message; }
    /** @brief The two toolbars' rows (one, or two when they do not fit the window's width). */
    ToolBarRows& toolBarRows() const { return *m_toolBarRows; }

    /** @brief Opens the demo project (generated first when the cache lacks it). */
    void openDemo();
    /** @brief Starts "Compute skydome" on the selected fragments. */
    void computeSkydome();
    /** Switches the 3D view (and the menus and Properties) to skydome shading. */
    void showSkydomeShading();
    /** @brief True while anything runs or loads: tasks, imports, octrees being opened, the demo. */
    bool isBusy() const;

    /** When false, errors go to the log and stderr only (automation, tests); by default also to a message box. */
    void setErrorDialogsEnabled(bool enabled);

protected:
    /** Status tips (menus, buttons) go to the status line, cut with "…" before the readout. */
    bool event(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createDocks();
    void createMenus();
    void connectDocument();
    void selectionChanged();
    void report(const QString& message, bool failed);
    void reportAll(const QStringList& errors);
    void showDeveloppee();
    void updateTitle();
    void retranslateUi();

    Translations& m_translations;
    widgets::TaskManager* m_tasks;
    widgets::SceneDocument* m_document;
    widgets::ScanImporter* m_importer;
    bool m_closing = false; ///< closeEvent accepted: no more dialogs
    widgets::DemoScene* m_demo;
    widgets::SkydomeRunner* m_skydome;
    widgets::ViewportWidget* m_viewport = nullptr;
    ViewportSync* m_sync = nullptr;
    AnnotationSync* m_annotationSync = nullptr;
    AnnotationActions* m_annotation = nullptr;
    SceneDock* m_sceneDock = nullptr;
    PropertiesDock* m_propertiesDock = nullptr;
    TasksDock* m_tasksDock = nullptr;
    DeveloppeeDock* m_developpeeDock = nullptr;
    DeveloppeeLink* m_developpeeLink = nullptr;
    LogDock* m_logDock = nullptr;
    LegendDock* m_legendDock = nullptr;
    widgets::ClassMeasures* m_measures = nullptr;
    widgets::DeveloppeeAnnotator* m_annotator = nullptr;
    ProjectActions* m_projectActions = nullptr;
    PlateActions* m_plates = nullptr;
    MainActions* m_actions = nullptr;
    AssemblyActions* m_assemblies = nullptr;
    DockingActions* m_docking = nullptr;
    StatusReadout* m_readout = nullptr;
    QToolBar* m_toolBar = nullptr;
    QToolBar* m_viewToolBar = nullptr;
    ToolBarRows* m_toolBarRows = nullptr;
    StatusMessage* m_message = nullptr;
    std::pair<quint64, QString> m_picked; ///< the fragment of the point picked last and the line it showed
    QString m_dragShown;                  ///< the gizmo drag's readout on show, cleared when the drag ends
    QMenu* m_fileMenu = nullptr;
    bool m_errorDialogs = true;
    bool m_demoPending = false;
};

} // namespace stylos::app
