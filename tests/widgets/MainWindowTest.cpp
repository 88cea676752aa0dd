// MainWindow: loads files in the background and shows their exact total; reports errors in a
// non-blocking message box naming the file; its status-bar Cancel button stops a running task.
#include "WidgetTestSupport.h"

#include "MainActions.h"
#include "MainWindow.h"
#include "stylos/widgets/SceneSession.h"
#include "stylos/widgets/SceneSummaryModel.h"
#include "stylos/widgets/SceneSummaryWidget.h"
#include "stylos/widgets/TaskRunner.h"
#include "stylos/widgets/TaskStatusWidget.h"

#include <QAction>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QThread>

using stylos::app::MainWindow;
using stylos::widgets::SceneSession;

class MainWindowTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void loadsFilesAndShowsExactTotal();
    void reportsErrorsNamingTheFile();
    void cancelButtonStopsRunningTask();
    void fileFilterListsEverySupportedExtension();
    void closingStopsTheTaskAndSavesGeometry();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

void MainWindowTest::init()
{
    m_window = std::make_unique<MainWindow>(m_dir.filePath("demo"));
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QCOMPARE(m_window->windowTitle(), QString("Stylos"));
}

void MainWindowTest::cleanup()
{
    m_window.reset();
}

void MainWindowTest::loadsFilesAndShowsExactTotal()
{
    const QString a = stylos::test::writeFile(m_dir.path(), "a.ply", stylos::test::tinyPly());
    const QString b = stylos::test::writeFile(m_dir.path(), "b.ply", stylos::test::fourPointPly());
    QSignalSpy finished(&m_window->session(), &SceneSession::operationFinished);
    QVERIFY(m_window->session().openFiles({a, b}));
    QVERIFY(!m_window->actions().openScansAction()->isEnabled());
    QVERIFY(finished.wait(10000));
    QVERIFY(finished.first().at(0).toStringList().isEmpty());
    QVERIFY(m_window->actions().openScansAction()->isEnabled());

    QCOMPARE(m_window->session().model().rowCount(), 2);
    QCOMPARE(m_window->session().model().totalPoints(), 7u);
    const QString total = m_window->summary().totalText();
    QVERIFY2(total.contains(QLocale().toString(7)) && total.contains("2 file"), qPrintable(total));
    QVERIFY(!m_window->findChild<QMessageBox*>("loadErrorBox"));
}

void MainWindowTest::reportsErrorsNamingTheFile()
{
    const QString good = stylos::test::writeFile(m_dir.path(), "good.ply", stylos::test::tinyPly());
    const QString bad = stylos::test::writeFile(m_dir.path(), "corrupt-drum.ply", "not a ply at all");
    QSignalSpy finished(&m_window->session(), &SceneSession::operationFinished);
    QVERIFY(m_window->session().openFiles({good, bad}));
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.first().at(0).toStringList().size(), 1);

    QMessageBox* box = nullptr;
    QTRY_VERIFY((box = m_window->findChild<QMessageBox*>("loadErrorBox")) != nullptr);
    QVERIFY2(box->text().contains("corrupt-drum.ply"), qPrintable(box->text()));
    // The box does not block: the window still answers and the good file is in the scene.
    QCOMPARE(m_window->session().model().totalPoints(), 3u);
    QVERIFY(m_window->session().openFiles({good}));
    QVERIFY(finished.wait(10000));
    box->close();
}

void MainWindowTest::cancelButtonStopsRunningTask()
{
    auto& runner = m_window->session().runner();
    auto sawCancel = std::make_shared<std::atomic<bool>>(false);
    QVERIFY(runner.start<int>("endless", [sawCancel](QPromise<int>&, stylos::core::ProgressSink& progress) {
        while (!progress.isCancelRequested()) QThread::msleep(1);
        sawCancel->store(true);
    }));
    auto* cancel = m_window->taskStatus().cancelButton();
    QTRY_VERIFY(cancel->isVisible());
    QSignalSpy finished(&runner, &stylos::widgets::TaskRunner::finished);
    QTest::mouseClick(cancel, Qt::LeftButton);
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.first().at(0).toBool(), true);
    QVERIFY(sawCancel->load());
    QVERIFY(!runner.isBusy());
    QVERIFY(!m_window->taskStatus().isVisible());
}

void MainWindowTest::fileFilterListsEverySupportedExtension()
{
    const QString filter = stylos::app::MainActions::scanFileFilter();
    for (const char* ext : {"*.ply", "*.las", "*.xyz", "*.asc", "*.csv", "*.pts", "*.txt", "*.obj"})
        QVERIFY2(filter.contains(ext), ext);
}

void MainWindowTest::closingStopsTheTaskAndSavesGeometry()
{
    QSettings().remove("mainWindow/geometry");
    auto started = std::make_shared<std::atomic<bool>>(false);
    auto sawCancel = std::make_shared<std::atomic<bool>>(false);
    QVERIFY(m_window->session().runner().start<int>(
        "endless", [started, sawCancel](QPromise<int>&, stylos::core::ProgressSink& progress) {
            started->store(true);
            while (!progress.isCancelRequested()) QThread::msleep(1);
            sawCancel->store(true);
        }));
    // Under load the pool may not have started the worker yet; a task cancelled before it starts
    // never runs, so wait for it to run before checking that close() stops it and waits.
    QTRY_VERIFY(started->load());
    m_window->resize(700, 450);
    QVERIFY(m_window->close());
    QVERIFY(sawCancel->load()); // close() waited for the worker
    QVERIFY(!QSettings().value("mainWindow/geometry").toByteArray().isEmpty());

    MainWindow restored(m_dir.filePath("demo"));
    QCOMPARE(restored.size(), QSize(700, 450));
}

STYLOS_WIDGET_TEST_MAIN(MainWindowTest)
#include "MainWindowTest.moc"
