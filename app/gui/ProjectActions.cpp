#include "ProjectActions.h"

#include "ToolBarText.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/widgets/document/ImportOptionsDialog.h"
#include "stylos/widgets/document/ScanImporter.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace stylos::app {

namespace {
const auto RecentKey = QStringLiteral("files/recentProjects");
const auto LastDirKey = QStringLiteral("files/lastDirectory");
const auto ProjectSuffix = QStringLiteral("stylos");

bool isProject(const QString& path)
{
    return QFileInfo(path).suffix().compare(ProjectSuffix, Qt::CaseInsensitive) == 0;
}
} // namespace

ProjectActions::ProjectActions(widgets::SceneDocument& document, widgets::ScanImporter& importer, QWidget& window)
    : QObject(&window), m_document(document), m_importer(importer), m_window(window), m_new(new QAction(this)),
      m_open(new QAction(this)), m_save(new QAction(this)), m_saveAs(new QAction(this)), m_import(new QAction(this)),
      m_quit(new QAction(this)), m_recent(new QMenu(&window))
{
    const std::pair<QAction*, const char*> names[] = {{m_new, "actionNew"},     {m_open, "actionOpen"},
                                                      {m_save, "actionSave"},   {m_saveAs, "actionSaveAs"},
                                                      {m_import, "actionImport"}, {m_quit, "actionQuit"}};
    for (const auto& [action, name] : names) action->setObjectName(QString::fromLatin1(name));
    m_recent->setObjectName(QStringLiteral("menuRecent"));
    m_new->setShortcut(QKeySequence::New);
    m_open->setShortcut(QKeySequence::Open);
    m_save->setShortcut(QKeySequence::Save);
    // Qt gives SaveAs no keys outside GNOME, KDE and macOS (so none on Windows or other desktops).
    m_saveAs->setShortcut(QKeySequence(QKeySequence::SaveAs).isEmpty() ? QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)
                                                                       : QKeySequence(QKeySequence::SaveAs));
    m_import->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    m_quit->setShortcut(QKeySequence::Quit);
    m_quit->setMenuRole(QAction::QuitRole);
    m_new->setIcon(QIcon::fromTheme(QStringLiteral("document-new")));
    m_open->setIcon(QIcon::fromTheme(QStringLiteral("document-open")));
    m_save->setIcon(QIcon::fromTheme(QStringLiteral("document-save")));
    m_import->setIcon(QIcon::fromTheme(QStringLiteral("document-import")));

    connect(m_new, &QAction::triggered, this, &ProjectActions::newProject);
    connect(m_open, &QAction::triggered, this, &ProjectActions::chooseProject);
    connect(m_save, &QAction::triggered, this, &ProjectActions::save);
    connect(m_saveAs, &QAction::triggered, this, &ProjectActions::saveAs);
    connect(m_import, &QAction::triggered, this, &ProjectActions::importScans);
    connect(m_quit, &QAction::triggered, &m_window, &QWidget::close);
    connect(m_recent, &QMenu::aboutToShow, this, &ProjectActions::rebuildRecentMenu);
    QSettings settings;
    m_importer.setImportFrame(widgets::ImportOptionsDialog::load(settings));
    retranslateUi();
}

void ProjectActions::populate(QMenu& menu)
{
    menu.addAction(m_new);
    menu.addAction(m_open);
    menu.addMenu(m_recent);
    menu.addSeparator();
    menu.addAction(m_save);
    menu.addAction(m_saveAs);
    menu.addSeparator();
    menu.addAction(m_import);
    menu.addSeparator();
    menu.addAction(m_quit);
}

void ProjectActions::retranslateUi()
{
    m_new->setText(tr("&New project"));
    m_open->setText(tr("&Open project…"));
    m_open->setStatusTip(tr("Open a Stylos project (.stylos)"));
    m_recent->setTitle(tr("Open &recent"));
    m_save->setText(tr("&Save project"));
    m_saveAs->setText(tr("Save project &as…"));
    m_import->setText(tr("&Import scans…"));
    m_import->setStatusTip(tr("Build a packed octree of each scan in the background and add it to the scene"));
    m_quit->setText(tr("&Quit"));
    setToolBarText(*m_open, tr("Open", "toolbar"));
    setToolBarText(*m_save, tr("Save", "toolbar"));
    setToolBarText(*m_import, tr("Import", "toolbar"));
}

void ProjectActions::openPaths(const QStringList& paths)
{
    QStringList scans;
    for (const QString& path : paths) {
        if (isProject(path)) {
            if (paths.size() > 1) {
                Q_EMIT reported(tr("%1: a project opens alone, not with other files").arg(path), true);
                return;
            }
            openProject(path);
            return;
        }
        scans << path;
    }
    if (!scans.isEmpty()) m_importer.importFiles(scans);
}

QStringList ProjectActions::openableFiles(const QList<QUrl>& urls)
{
    QStringList files;
    for (const QUrl& url : urls) {
        const QString path = url.toLocalFile();
        if (url.isLocalFile() && (isProject(path) || widgets::ScanImporter::canImport(path))) files << path;
    }
    return files;
}

bool ProjectActions::openProject(const QString& path, bool askFirst)
{
    if (askFirst && !maybeSave()) return false;
    QString error;
    if (!m_document.open(path, &error)) {
        Q_EMIT reported(error, true);
        return false;
    }
    addRecent(m_document.projectPath());
    Q_EMIT reported(tr("Opened %1").arg(QDir::toNativeSeparators(m_document.projectPath())), false);
    return true;
}

bool ProjectActions::save()
{
    if (m_document.projectPath().isEmpty()) return saveAs();
    if (isRebuilt(m_document.projectPath())) {
        Q_EMIT reported(tr("The demo is rebuilt when it is opened again: save your work as a project of your own."),
                        false);
        return saveAs();
    }
    return saveTo(m_document.projectPath());
}

bool ProjectActions::isRebuilt(const QString& path) const
{
    if (m_rebuiltProject.isEmpty()) return false;
    // The folders compared, links resolved: the demo's project reached through a link, or a project of one's own
    // saved beside it (its octrees would stay in the folder that is rebuilt), are the same case.
    const auto folderOf = [](const QString& file) {
        const QString folder = QFileInfo(file).absolutePath();
        const QString canonical = QFileInfo(folder).canonicalFilePath();
        return canonical.isEmpty() ? QDir::cleanPath(folder) : canonical;
    };
#if defined(Q_OS_WIN) || defined(Q_OS_MACOS)
    const Qt::CaseSensitivity cs = Qt::CaseInsensitive;
#else
    const Qt::CaseSensitivity cs = Qt::CaseSensitive;
#endif
    return folderOf(path).compare(folderOf(m_rebuiltProject), cs) == 0;
}

bool ProjectActions::saveAs()
{
    if (!m_prompts) return false;
    QSettings settings;
    QString path = QFileDialog::getSaveFileName(&m_window, tr("Save project"),
                                                rememberedFolder(),
                                                tr("Stylos projects (*.stylos)"));
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".stylos");
    settings.setValue(LastDirKey, QFileInfo(path).absolutePath());
    return saveTo(path);
}

bool ProjectActions::saveTo(const QString& path)
{
    if (isRebuilt(path)) {
        Q_EMIT reported(tr("Could not save %1: it is in the demo's folder, rebuilt when the demo is opened again. "
                           "Choose another folder.").arg(QDir::toNativeSeparators(path)),
                        true);
        return false;
    }
    const core::scene::GatherPlan plan = m_document.octreeGatherPlan(path);
    auto copies = widgets::SceneDocument::OctreeCopies::All;
    if (m_prompts && plan.copyBytes > static_cast<std::uintmax_t>(AskBeforeCopying)) {
        int outside = 0;
        for (const core::scene::OctreeTransfer& t : plan.transfers) outside += t.fromCache ? 0 : 1;
        QMessageBox box(QMessageBox::Question, tr("Save project"),
                        tr("The project uses %n octree(s) outside its folder, %1 in all.", nullptr, outside)
                            .arg(QLocale().formattedDataSize(static_cast<qint64>(plan.copyBytes))),
                        QMessageBox::NoButton, &m_window);
        box.setInformativeText(tr("Copied into the folder, they travel with it: the folder can be moved or "
                                  "copied whole. Left where they are, the project names them there."));
        QPushButton* copy = box.addButton(tr("Copy into the folder"), QMessageBox::AcceptRole);
        QPushButton* leave = box.addButton(tr("Leave them where they are"), QMessageBox::DestructiveRole);
        box.addButton(QMessageBox::Cancel);
        box.setDefaultButton(copy);
        box.exec();
        if (box.clickedButton() == leave) copies = widgets::SceneDocument::OctreeCopies::CacheOnly;
        else if (box.clickedButton() != copy) return false;
    }
    QString error;
    const bool saved = m_document.saveAs(path, &error, copies);
    if (!saved) {
        Q_EMIT reported(error, true);
        return false;
    }
    int copied = 0;
    for (const core::scene::OctreeTransfer& t : plan.transfers)
        copied += t.fromCache || copies == widgets::SceneDocument::OctreeCopies::All ? 1 : 0;
    addRecent(m_document.projectPath());
    const QString where = QDir::toNativeSeparators(m_document.projectPath());
    Q_EMIT reported(copied == 0 ? tr("Saved %1").arg(where)
                                : tr("Saved %1, with %n octree(s) copied into its folder", nullptr, copied).arg(where),
                    false);
    return true;
}

void ProjectActions::cleanOctreeCache()
{
    std::vector<std::filesystem::path> inUse;
    for (const core::scene::Fragment& f : m_document.scene().fragments()) inUse.push_back(f.octreePath);
    std::vector<std::filesystem::path> projects;
    for (const QString& project : recentProjects()) projects.push_back(project.toStdString());
    const core::scene::CacheCleanReport report = core::scene::cleanCache(
        m_document.octreeCacheFolder().toStdString(), inUse, projects, std::chrono::hours(24));
    if (report.removed.empty()) return;
    Q_EMIT reported(tr("Removed %n unused octree(s) from the cache, %1 freed", nullptr,
                       static_cast<int>(report.removed.size()))
                        .arg(QLocale().formattedDataSize(static_cast<qint64>(report.bytesFreed))),
                    false);
}

bool ProjectActions::maybeSave()
{
    if (!m_document.isModified() || !m_prompts) return true;
    const auto answer = QMessageBox::warning(
        &m_window, tr("Stylos"), tr("The project %1 has unsaved changes.").arg(m_document.displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel) return false;
    return answer == QMessageBox::Discard || save();
}

QStringList ProjectActions::recentProjects()
{
    return QSettings().value(RecentKey).toStringList();
}

void ProjectActions::newProject()
{
    if (maybeSave()) m_document.newProject();
}

void ProjectActions::chooseProject()
{
    if (!maybeSave()) return;
    QSettings settings;
    const QString folder = rememberedFolder();
    const QString path = m_chooseProject ? m_chooseProject(m_window, folder)
                                         : QFileDialog::getOpenFileName(&m_window, tr("Open project"), folder,
                                                                        tr("Stylos projects (*.stylos)"));
    if (path.isEmpty()) return;
    settings.setValue(LastDirKey, QFileInfo(path).absolutePath());
    openProject(path, false); // asked above: Discard there is not asked again (a Save then saved what was discarded)
}

QString ProjectActions::rememberedFolder()
{
    QString folder = QSettings().value(LastDirKey).toString();
    if (folder.isEmpty()) return {};
    while (!QFileInfo(folder).isDir() && !folder.isEmpty()) {
        const QString parent = QFileInfo(folder).path();
        if (parent == folder) break;
        folder = parent;
    }
    return QFileInfo(folder).isDir() ? QFileInfo(folder).absoluteFilePath() : QString();
}

void ProjectActions::importScans()
{
    QSettings settings;
    const QStringList files = QFileDialog::getOpenFileNames(&m_window, tr("Import scans"),
                                                            rememberedFolder(),
                                                            widgets::ScanImporter::fileFilter());
    if (files.isEmpty()) return;
    settings.setValue(LastDirKey, QFileInfo(files.first()).absolutePath());
    const bool pointFiles = std::any_of(files.begin(), files.end(), [](const QString& file) {
        return !core::io::hasPoctExtension(file.toStdString());
    });
    if (pointFiles) {
        // The up axis and unit apply to point files (a .poct is opened as it is); remembered for the next time.
        widgets::ImportOptionsDialog options(m_importer.importFrame(), &m_window);
        if (options.exec() != QDialog::Accepted) return;
        m_importer.setImportFrame(options.frame());
        widgets::ImportOptionsDialog::save(settings, options.frame());
    }
    m_importer.importFiles(files);
}

void ProjectActions::addRecent(const QString& path)
{
    QStringList recent = recentProjects();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > MaxRecent) recent.removeLast();
    QSettings().setValue(RecentKey, recent);
}

void ProjectActions::rebuildRecentMenu()
{
    m_recent->clear();
    const QStringList recent = recentProjects();
    for (const QString& path : recent) {
        QAction* action = m_recent->addAction(QDir::toNativeSeparators(path));
        action->setEnabled(QFileInfo::exists(path));
        connect(action, &QAction::triggered, this, [this, path] { openProject(path); });
    }
    if (recent.isEmpty()) m_recent->addAction(tr("No recent project"))->setEnabled(false);
    m_recent->addSeparator();
    connect(m_recent->addAction(tr("Clear the list")), &QAction::triggered, this,
            [] { QSettings().remove(RecentKey); });
}

} // namespace stylos::app
