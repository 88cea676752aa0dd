#pragma once
// Helpers shared by the widget tests: small point files written by hand, and a test main that uses the
// display it finds (Xvfb under `xvfb-run -a ctest`) and holds it while Qt connects, falling back to Qt's
// offscreen platform without one.
#include <QApplication>
#include <QFile>
#include <QStandardPaths>
#include <QString>
#include <QtTest/QtTest>

#include <chrono>
#include <thread>

#if STYLOS_TEST_HOLDS_DISPLAY
#include <xcb/xcb.h>
#endif

namespace stylos::test {

/** Three points: (0,0,0), (1,0,0), (0,1,2). Bounds [0,1]×[0,1]×[0,2]. */
inline const char* tinyPly()
{
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "end_header\n0 0 0\n1 0 0\n0 1 2\n";
}

/** Four points with negative and fractional coordinates: bounds [-2.5,3]×[-1,0.25]×[10,12]. */
inline const char* fourPointPly()
{
    return "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
           "end_header\n-2.5 0 10\n3 -1 11\n0 0.25 12\n1 0 10.5\n";
}

/** Writes @p text to @p dir/@p name and returns the path. */
inline QString writeFile(const QString& dir, const QString& name, const QByteArray& text)
{
    const QString path = dir + QLatin1Char('/') + name;
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size()) qFatal("cannot write %s", qPrintable(path));
    return path;
}

/** Before QApplication: use the offscreen platform when there is no display and none was chosen. */
inline void chooseTestPlatform()
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
}

/**
 * A connection to the X display held for the whole test, made before Qt makes its own. An X server resets
 * when its last client leaves and drops a client that connects meanwhile; Qt then aborts ("could not
 * connect to display"). Under `xvfb-run -a ctest -j2` without -noreset a test that starts as another
 * ends can meet such a reset: this connection is retried until the server answers (up to 10 s), and
 * while it is open the server has a client, so Qt's connection cannot meet one. Nothing without a display.
 */
class DisplayHold {
public:
    DisplayHold()
    {
#if STYLOS_TEST_HOLDS_DISPLAY
        const QByteArray platform = qgetenv("QT_QPA_PLATFORM");
        if (qEnvironmentVariableIsEmpty("DISPLAY") || (!platform.isEmpty() && !platform.startsWith("xcb"))) return;
        for (int attempt = 0; attempt < 100; ++attempt) {
            xcb_connection_t* connection = xcb_connect(nullptr, nullptr);
            if (xcb_connection_has_error(connection) == 0) {
                m_connection = connection;
                return;
            }
            xcb_disconnect(connection);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
#endif
    }
    ~DisplayHold()
    {
#if STYLOS_TEST_HOLDS_DISPLAY
        if (m_connection) xcb_disconnect(m_connection);
#endif
    }
    DisplayHold(const DisplayHold&) = delete;
    DisplayHold& operator=(const DisplayHold&) = delete;
    /** Whether a connection is held (false without a display, or without libxcb at build time). */
    bool held() const { return m_connection != nullptr; }

private:
#if STYLOS_TEST_HOLDS_DISPLAY
    xcb_connection_t* m_connection = nullptr;
#else
    void* m_connection = nullptr;
#endif
};

} // namespace stylos::test

/** QTEST_MAIN with the platform fallback, the display held (DisplayHold), test-mode paths (never the user's
 * settings or cache). */
#define STYLOS_WIDGET_TEST_MAIN(TestClass)                                                          \
    int main(int argc, char* argv[])                                                                \
    {                                                                                               \
        ::stylos::test::chooseTestPlatform();                                                       \
        const ::stylos::test::DisplayHold displayHold;                                              \
        QStandardPaths::setTestModeEnabled(true);                                                   \
        QApplication app(argc, argv);                                                               \
        QApplication::setOrganizationName(QStringLiteral("StylosTests"));                           \
        QApplication::setApplicationName(QStringLiteral(#TestClass));                               \
        app.setAttribute(Qt::AA_Use96Dpi, true);                                                    \
        TestClass test;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                  \
        return QTest::qExec(&test, argc, argv);                                                     \
    }
