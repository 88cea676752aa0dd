// stylos: the Qt workbench. Opens the demo scene, or the project or scans given on the command line.
#include "Automation.h"
#include "CommandLine.h"
#include "DisplayCheck.h"
#include "MainWindow.h"
#include "ProjectActions.h"
#include "Translations.h"

#include <QApplication>
#include <QIcon>

int main(int argc, char* argv[])
{
    if (!stylos::app::hasDisplay(argc, argv)) return stylos::app::runWithoutDisplay(argc, argv, STYLOS_VERSION);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Stylos"));
    QApplication::setApplicationName(QStringLiteral("stylos"));
    QApplication::setApplicationDisplayName(QStringLiteral("Stylos"));
    QApplication::setApplicationVersion(QStringLiteral(STYLOS_VERSION));
    QApplication::setDesktopFileName(QStringLiteral("stylos"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/stylos.svg")));
    stylos::app::Translations translations;
    translations.setLanguage(stylos::app::Translations::savedLanguage());

    const stylos::app::CommandLine options = stylos::app::CommandLine::parse(app);

    stylos::app::MainWindow window(translations);
    if (!options.grabPath.isEmpty() && !options.plateBase.isEmpty())
        stylos::app::grabPlateWhenReady(window, options.grabPath, options.plateBase);
    else if (!options.grabPath.isEmpty() && options.grabGizmo) stylos::app::grabGizmoWhenReady(window, options.grabPath);
    else if (!options.grabPath.isEmpty() && options.grabAnnotation)
        stylos::app::grabAnnotationWhenReady(window, options.grabPath);
    else if (!options.grabPath.isEmpty() && options.grabPaint && options.grabDock)
        stylos::app::grabAssemblyPaintWhenReady(window, options.grabPath);
    else if (!options.grabPath.isEmpty() && options.grabPaint) stylos::app::grabPaintWhenReady(window, options.grabPath);
    else if (!options.grabPath.isEmpty() && options.grabDock) stylos::app::grabDockWhenReady(window, options.grabPath);
    else if (!options.grabPath.isEmpty()) stylos::app::grabWhenReady(window, options.grabPath);
    if (options.orbitFrames > 0) stylos::app::orbitWhenReady(window, options.orbitFrames);
    if (options.poseFrames > 0) stylos::app::poseWhenReady(window, options.poseFrames);
    window.show();
    window.projectActions().cleanOctreeCache();
    if (options.files.isEmpty()) window.openDemo();
    else window.projectActions().openPaths(options.files);
    return QApplication::exec();
}
