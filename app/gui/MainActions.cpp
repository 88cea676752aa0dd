#include "MainActions.h"

#include "stylos/widgets/SceneSession.h"
#include "stylos/widgets/TaskRunner.h"

#include <QAction>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>

namespace stylos::app {

namespace {
const auto LastDirKey = QStringLiteral("files/lastDirectory");
}

MainActions::MainActions(widgets::SceneSession& session, QWidget& window)
    : QObject(&window), m_session(session), m_window(window), m_openScans(new QAction(this)),
      m_quit(new QAction(this)), m_openDemo(new QAction(this)), m_about(new QAction(this))
{
    m_openScans->setObjectName(QStringLiteral("actionOpenScans"));
    m_quit->setObjectName(QStringLiteral("actionQuit"));
    m_openDemo->setObjectName(QStringLiteral("actionOpenDemo"));
    m_about->setObjectName(QStringLiteral("actionAbout"));
    m_openScans->setShortcut(QKeySequence::Open);
    m_quit->setShortcut(QKeySequence::Quit);
    m_quit->setMenuRole(QAction::QuitRole);
    m_about->setMenuRole(QAction::AboutRole);

    connect(m_openScans, &QAction::triggered, this, &MainActions::openScans);
    connect(m_quit, &QAction::triggered, &m_window, &QWidget::close);
    connect(m_openDemo, &QAction::triggered, this, [this] { m_session.openDemo(); });
    connect(m_about, &QAction::triggered, this, &MainActions::about);
    connect(&m_session.runner(), &widgets::TaskRunner::started, this, &MainActions::updateEnabled);
    connect(&m_session, &widgets::SceneSession::operationFinished, this, &MainActions::updateEnabled);
    retranslateUi();
}

void MainActions::populate(QMenuBar& menuBar)
{
    m_fileMenu = menuBar.addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("menuFile"));
    m_fileMenu->addAction(m_openScans);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quit);
    m_helpMenu = menuBar.addMenu(QString());
    m_helpMenu->setObjectName(QStringLiteral("menuHelp"));
    m_helpMenu->addAction(m_openDemo);
    m_helpMenu->addSeparator();
    m_helpMenu->addAction(m_about);
    retranslateUi();
}

void MainActions::retranslateUi()
{
    if (m_fileMenu) m_fileMenu->setTitle(tr("&File"));
    if (m_helpMenu) m_helpMenu->setTitle(tr("&Help"));
    m_openScans->setText(tr("&Open scans…"));
    m_openScans->setStatusTip(tr("Load point files (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ) into the scene"));
    m_quit->setText(tr("&Quit"));
    m_openDemo->setText(tr("Open &demo"));
    m_openDemo->setStatusTip(tr("Replace the scene by the demo scene: a fluted drum, two fragments and an omphalos"));
    m_about->setText(tr("&About Stylos"));
}

QString MainActions::scanFileFilter()
{
    return tr("Point files (*.ply *.las *.xyz *.asc *.csv *.pts *.txt *.obj)") + QStringLiteral(";;") +
           tr("All files (*)");
}

void MainActions::openScans()
{
    QSettings settings;
    const QStringList files = QFileDialog::getOpenFileNames(
        &m_window, tr("Open scans"), settings.value(LastDirKey).toString(), scanFileFilter());
    if (files.isEmpty()) return;
    settings.setValue(LastDirKey, QFileInfo(files.first()).absolutePath());
    m_session.openFiles(files);
}

void MainActions::about()
{
    QMessageBox::about(&m_window, tr("About Stylos"),
                       tr("<h3>Stylos %1</h3><p>A workbench for very large 3D scans of monuments: column drums, "
                          "capitals, fragments.</p><p>Point-based, after Duguet, Drettakis, Girardeau-Montaut, "
                          "Martinez and Schneider (VAST 2004).</p>")
                           .arg(QCoreApplication::applicationVersion()));
}

void MainActions::updateEnabled()
{
    const bool idle = !m_session.isBusy();
    m_openScans->setEnabled(idle);
    m_openDemo->setEnabled(idle);
}

} // namespace stylos::app
