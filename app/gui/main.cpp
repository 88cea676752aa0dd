// stylos: the Qt workbench. Opens the demo scene, or the point files given on the command line.
#include "CommandLine.h"
#include "MainWindow.h"
#include "stylos/widgets/SceneSession.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QPixmap>
#include <QTimer>
#include <QTranslator>

#include <cstdio>

namespace {

/**
 * Installs the Stylos translation for the system locale (French, Greek), English otherwise (it only
 * carries the plural forms), and Qt's own for the standard dialogs when installed.
 */
void installTranslations(QApplication& app)
{
    auto* stylos = new QTranslator(&app);
    if (stylos->load(QLocale(), QStringLiteral("stylos"), QStringLiteral("_"), QStringLiteral(":/i18n")) ||
        stylos->load(QStringLiteral(":/i18n/stylos_en")))
        QApplication::installTranslator(stylos);
    auto* qt = new QTranslator(&app);
    if (qt->load(QLocale(), QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(qt);
}

/** Once the first request ends, renders @p window to @p path and quits (1 on any error). */
void grabWhenFinished(stylos::app::MainWindow& window, const QString& path)
{
    window.setErrorDialogsEnabled(false);
    QObject::connect(&window.session(), &stylos::widgets::SceneSession::operationFinished, &window,
                     [&window, path](const QStringList& errors, bool cancelled) {
                         // One more turn of the event loop so that the views lay out their new rows.
                         QTimer::singleShot(100, &window, [&window, path, failed = !errors.isEmpty() || cancelled] {
                             if (!window.grab().save(path, "PNG")) {
                                 std::fprintf(stderr, "stylos: %s: could not write the image\n", qPrintable(path));
                                 QApplication::exit(1);
                                 return;
                             }
                             QApplication::exit(failed ? 1 : 0);
                         });
                     });
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Stylos"));
    QApplication::setApplicationName(QStringLiteral("stylos"));
    QApplication::setApplicationDisplayName(QStringLiteral("Stylos"));
    QApplication::setApplicationVersion(QStringLiteral(STYLOS_VERSION));
    installTranslations(app);

    const stylos::app::CommandLine options = stylos::app::CommandLine::parse(app);

    stylos::app::MainWindow window;
    if (!options.grabPath.isEmpty()) grabWhenFinished(window, options.grabPath);
    window.show();
    if (options.files.isEmpty()) window.session().openDemo();
    else window.session().openFiles(options.files);
    return QApplication::exec();
}
