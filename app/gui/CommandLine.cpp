#include "CommandLine.h"

#include "stylos/core/io/PointFileFormat.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>

namespace stylos::app {

namespace {
QString tr(const char* text) { return QCoreApplication::translate("stylos::app::CommandLine", text); }

[[noreturn]] void usageError(const QString& message)
{
    std::fprintf(stderr, "stylos: %s\n", qPrintable(message));
    std::exit(2);
}
} // namespace

CommandLine CommandLine::parse(const QCoreApplication& app)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Stylos, a workbench for very large 3D scans of monuments. With no file, opens the demo scene."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption grab(QStringLiteral("grab"),
                                  tr("Wait until the scene and its tasks are ready and the view is refined, save "
                                     "the window as a PNG image to <file> and exit (status 1 if something failed)."),
                                  tr("file"));
    const QCommandLineOption orbit(QStringLiteral("orbit-benchmark"),
                                   tr("Orbit the camera for <frames> frames at 1280 × 800 once the scene is ready, "
                                      "print the frame times as JSON and exit."),
                                   tr("frames"));
    const QCommandLineOption pose(QStringLiteral("pose-benchmark"),
                                  tr("Turn the first fragment, a change of its pose every frame, for <frames> "
                                     "frames at 1280 × 800 once the scene is ready, print the frame times as JSON "
                                     "and exit."),
                                  tr("frames"));
    const QCommandLineOption gizmo(QStringLiteral("gizmo"),
                                   tr("With --grab: first fit the first fragment's drum guides, dock against it and "
                                      "show the Move tool on the second fragment, in the drum's frame."));
    const QCommandLineOption dock(QStringLiteral("dock"),
                                  tr("With --grab: first fit the first fragment's drum guides, dock the second fragment "
                                     "to its flutes from where it stands and show its contact readout."));
    const QCommandLineOption annotation(QStringLiteral("annotation"),
                                        tr("With --grab: first label three regions of the first fragment with the 3D "
                                           "lasso (preserved marble, fractured marble, plaster) and show the "
                                           "Annotation shading."));
    parser.addOption(grab);
    parser.addOption(gizmo);
    parser.addOption(annotation);
    parser.addOption(dock);
    const QCommandLineOption paint(QStringLiteral("paint"),
                                   tr("With --grab: first compute the first fragment's développée and paint a few "
                                      "annotation regions on it (marble, fractured marble, plaster; a claw-chisel "
                                      "area in the tool-mark layer). With --dock too: after the dock, the développée "
                                      "of the second fragment's assembly, painted across the drum and the fragment."));
    parser.addOption(paint);
    const QCommandLineOption plate(QStringLiteral("plate"),
                                   tr("With --grab: paint as --paint, then write the first fragment's plate (its "
                                      "développée and front view at 1:N) to BASE.pdf and BASE.png, and grab the Export "
                                      "plate dialog."),
                                   QStringLiteral("BASE"));
    parser.addOption(plate);
    parser.addOption(orbit);
    parser.addOption(pose);
    QStringList formats;
    for (const std::string& extension : core::io::importableExtensions())
        formats << QString::fromStdString(extension).toUpper(); // what is read (a LAZ is refused with what to do)
    parser.addPositionalArgument(
        QStringLiteral("files"), tr("A project (.stylos), or scans to import (%1).").arg(formats.join(QStringLiteral(", "))),
        QStringLiteral("[files...]"));
    parser.process(app);

    CommandLine result;
    result.files = parser.positionalArguments();
    result.grabPath = parser.value(grab);
    result.grabGizmo = parser.isSet(gizmo);
    if (result.grabGizmo && result.grabPath.isEmpty()) usageError(tr("--gizmo goes with --grab"));
    result.grabDock = parser.isSet(dock);
    if (result.grabDock && result.grabPath.isEmpty()) usageError(tr("--dock goes with --grab"));
    if (result.grabDock && result.grabGizmo) usageError(tr("--dock and --gizmo do not go together"));
    result.grabAnnotation = parser.isSet(annotation);
    if (result.grabAnnotation && (result.grabPath.isEmpty() || result.grabDock || result.grabGizmo))
        usageError(tr("--annotation goes with --grab alone"));
    result.grabPaint = parser.isSet(paint);
    if (result.grabPaint && result.grabPath.isEmpty()) usageError(tr("--paint goes with --grab"));
    if (result.grabPaint && (result.grabGizmo || result.grabAnnotation))
        usageError(tr("--paint does not go with --gizmo or --annotation"));
    result.plateBase = parser.value(plate);
    if (!result.plateBase.isEmpty() && (result.grabPath.isEmpty() || result.grabPaint || result.grabDock ||
                                        result.grabGizmo || result.grabAnnotation))
        usageError(tr("--plate goes with --grab alone"));
    if (parser.isSet(orbit)) {
        bool ok = false;
        result.orbitFrames = parser.value(orbit).toInt(&ok);
        if (!ok || result.orbitFrames < 1 || result.orbitFrames > 100000)
            usageError(tr("--orbit-benchmark: '%1' is not a frame count (1 to 100000)").arg(parser.value(orbit)));
        if (result.files.size() != 1) usageError(tr("--orbit-benchmark needs exactly one file"));
        if (!result.grabPath.isEmpty()) usageError(tr("--grab and --orbit-benchmark do not go together"));
    }
    if (parser.isSet(pose)) {
        bool ok = false;
        result.poseFrames = parser.value(pose).toInt(&ok);
        if (!ok || result.poseFrames < 1 || result.poseFrames > 100000)
            usageError(tr("--pose-benchmark: '%1' is not a frame count (1 to 100000)").arg(parser.value(pose)));
        if (result.files.size() != 1) usageError(tr("--pose-benchmark needs exactly one file"));
        if (!result.grabPath.isEmpty() || result.orbitFrames > 0)
            usageError(tr("--pose-benchmark goes with neither --grab nor --orbit-benchmark"));
    }
    return result;
}

} // namespace stylos::app
