#pragma once
/** @file
 * @brief The `stylos` command line: FILES to load (none: the demo scene), --grab OUT.png for automation,
 *        --help and --version (handled by QCommandLineParser, which exits).
 */
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace stylos::app {

struct CommandLine {
    QStringList files;  ///< point files to load; empty: open the demo scene
    QString grabPath;   ///< non-empty: render the window to this PNG once loading ends, then exit

    /** Parses the application's arguments; exits the process for --help, --version and usage errors. */
    static CommandLine parse(const QCoreApplication& app);
};

} // namespace stylos::app
