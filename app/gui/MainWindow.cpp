#include "MainWindow.h"

#include "MainActions.h"
#include "stylos/widgets/SceneSession.h"
#include "stylos/widgets/SceneSummaryModel.h"
#include "stylos/widgets/SceneSummaryWidget.h"
#include "stylos/widgets/TaskRunner.h"
#include "stylos/widgets/TaskStatusWidget.h"

#include <QCloseEvent>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

#include <cstdio>

namespace stylos::app {

namespace {
const auto GeometryKey = QStringLiteral("mainWindow/geometry");
const auto StateKey = QStringLiteral("mainWindow/state");
} // namespace

MainWindow::MainWindow(const QString& demoDirectory, QWidget* parent)
    : QMainWindow(parent), m_session(new widgets::SceneSession(demoDirectory, this))
{
    setObjectName(QStringLiteral("MainWindow"));
    m_summary = new widgets::SceneSummaryWidget(m_session->model(), this);
    setCentralWidget(m_summary);
    m_taskStatus = new widgets::TaskStatusWidget(m_session->runner(), this);
    statusBar()->addPermanentWidget(m_taskStatus);
    m_actions = new MainActions(*m_session, *this);
    m_actions->populate(*menuBar());

    connect(m_session, &widgets::SceneSession::operationFinished, this, &MainWindow::reportFinished);

    QSettings settings;
    if (!restoreGeometry(settings.value(GeometryKey).toByteArray())) resize(960, 600);
    restoreState(settings.value(StateKey).toByteArray());
    retranslateUi();
}

MainWindow::~MainWindow() = default;

void MainWindow::closeEvent(QCloseEvent* event)
{
    QSettings settings;
    settings.setValue(GeometryKey, saveGeometry());
    settings.setValue(StateKey, saveState());
    // The worker checks for Cancel every batch: this returns within a fraction of a second.
    m_session->runner().cancelAndWait();
    event->accept();
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
        m_actions->retranslateUi();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslateUi()
{
    setWindowTitle(tr("Stylos"));
}

void MainWindow::reportFinished(const QStringList& errors, bool cancelled)
{
    const int files = m_session->model().rowCount();
    if (cancelled) statusBar()->showMessage(tr("Cancelled"), 5000);
    else statusBar()->showMessage(tr("%n file(s) in the scene", nullptr, files), 5000);
    if (errors.isEmpty()) return;

    for (const QString& error : errors) std::fprintf(stderr, "stylos: %s\n", qPrintable(error));
    if (!m_errorDialogs) return;
    // Window-modal and non-blocking: the event loop, and any later task, keep running.
    const int count = static_cast<int>(errors.size());
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Stylos"),
                                count == 1 ? errors.first() : tr("%n problem(s) while loading:", nullptr, count),
                                QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("loadErrorBox"));
    if (count > 1) box->setInformativeText(errors.join(QStringLiteral("\n\n")));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace stylos::app
