#pragma once
/** @file
 * @brief The File menu: New, Open project…, Open recent, Save, Save as…, Import scans…, Quit — the actions
 *        and their handlers (file dialogs, the import options after the scans are chosen, "save changes?"
 *        before the project is replaced or the window closes, the recent projects and the import options
 *        kept in QSettings; the importer starts with the remembered import options, for drops too). Saving brings
 *        the octrees into the project's folder (asking first for big ones from outside the cache) so that the
 *        folder travels whole; cleanOctreeCache() keeps the cache to what something uses. Outcomes go out as messages (reported()) for the
 *        window to log and show. GUI thread only.
 */
#include <QFileInfo>
#include <QObject>
#include <QStringList>
#include <QUrl>

#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace stylos::widgets {
class ScanImporter;
class SceneDocument;
} // namespace stylos::widgets

namespace stylos::app {

class ProjectActions : public QObject {
    Q_OBJECT

public:
    static constexpr int MaxRecent = 8;

    /** None owned; @p window parents the dialogs. */
    ProjectActions(widgets::SceneDocument& document, widgets::ScanImporter& importer, QWidget& window);

    /** @brief Adds the actions to @p menu (File). */
    void populate(QMenu& menu);
    void retranslateUi();

    /**
     * @brief Opens what the command line or a drop names: one `.stylos` project (replacing the current
     *        one), or point files and `.poct` octrees, imported into the current project.
     */
    void openPaths(const QStringList& paths);
    /**
     * @brief The local files among @p urls that openPaths() takes by their extension: `.stylos` projects,
     *        and the point files and octrees whose extension ScanImporter::canImport() takes (LAZ too, refused
     *        on import with what to do).
     */
    static QStringList openableFiles(const QList<QUrl>& urls);
    /** @brief Opens the project @p path (after asking to save changes, unless @p askFirst is false: the caller has
     *         asked); false when it failed or was declined. */
    bool openProject(const QString& path, bool askFirst = true);
    /** @brief Saves (asking for a file when never saved); false when it failed or was cancelled. */
    bool save();
    bool saveAs();
    /** Saves to @p path, asking first when big octrees would be copied into its folder. */
    bool saveTo(const QString& path);
    /**
     * @brief When the project has unsaved changes, asks to save them: true to go on (saved or discarded),
     *        false to stop. Without prompts (automation), changes are discarded.
     */
    bool maybeSave();
    /** @brief Whether dialogs may be shown (false for automation and tests). */
    void setPromptsEnabled(bool enabled) { m_prompts = enabled; }
    /** @brief What File › Open asks for the project to open (default: a file dialog from @p folder; empty: none). */
    using ProjectChooser = std::function<QString(QWidget& parent, const QString& folder)>;
    void setProjectChooser(ProjectChooser chooser) { m_chooseProject = std::move(chooser); }
    /** The demo's project: its folder is rebuilt whenever the generator's output differs, so nothing is ever saved
     *  there. Save on the demo asks for a project of one's own (Save as); saving into that folder is refused. */
    void setRebuiltProject(const QString& path) { m_rebuiltProject = path; }

    /** @brief Recent projects, most recent first (existing or not). */
    static QStringList recentProjects();
    /** @brief Where the file choosers open: the folder last chosen in one, or its nearest folder that still exists
     *         (a project folder moved or deleted since: given as it was, Qt's chooser took its last name for a file
     *         name, "proj", in the name box); empty when none was remembered. */
    static QString rememberedFolder();

    /** @brief Saving asks before copying more than this many bytes of octrees from outside the cache into the
     *         project's folder (the cache's octrees are always copied: the cache is cleaned). */
    static constexpr qint64 AskBeforeCopying = qint64(1) << 30;
    /**
     * @brief Removes from the octree cache what neither the open project nor a recent project uses, once a
     *        day old (core::scene::cleanCache); reports what it freed. The workbench calls it at start.
     */
    void cleanOctreeCache();

    QAction* newAction() const { return m_new; }
    QAction* openAction() const { return m_open; }
    QAction* saveAction() const { return m_save; }
    QAction* saveAsAction() const { return m_saveAs; }
    QAction* importAction() const { return m_import; }
    QAction* quitAction() const { return m_quit; }
    QMenu* recentMenu() const { return m_recent; }

Q_SIGNALS:
    /** @brief Something to tell the user (translated); @p failed: an error naming the file and the reason. */
    void reported(const QString& message, bool failed);

private:
    void newProject();
    void chooseProject();
    void importScans();
    void addRecent(const QString& path);
    void rebuildRecentMenu();

    widgets::SceneDocument& m_document;
    widgets::ScanImporter& m_importer;
    QWidget& m_window;
    QAction* m_new;
    QAction* m_open;
    QAction* m_save;
    QAction* m_saveAs;
    QAction* m_import;
    QAction* m_quit;
    QMenu* m_recent;
    /** Whether @p path is in the rebuilt project's folder (symbolic links resolved; the file need not exist). */
    bool isRebuilt(const QString& path) const;
    bool m_prompts = true;
    ProjectChooser m_chooseProject;
    QString m_rebuiltProject;
};

} // namespace stylos::app
