#include "CommandLine.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace stylos::app {

CommandLine CommandLine::parse(const QCoreApplication& app)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "stylos::app::CommandLine", "Stylos, a workbench for very large 3D scans of monuments. With no file, "
                                    "opens the demo scene."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption grab(
        QStringLiteral("grab"),
        QCoreApplication::translate("stylos::app::CommandLine",
                                    "Wait until loading ends, save the window as a PNG image to <file> and exit "
                                    "(status 1 if a file could not be loaded)."),
        QCoreApplication::translate("stylos::app::CommandLine", "file"));
    parser.addOption(grab);
    parser.addPositionalArgument(
        QStringLiteral("files"),
        QCoreApplication::translate("stylos::app::CommandLine",
                                    "Point files to load (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ)."),
        QStringLiteral("[files...]"));
    parser.process(app);

    CommandLine result;
    result.files = parser.positionalArguments();
    result.grabPath = parser.value(grab);
    return result;
}

} // namespace stylos::app
