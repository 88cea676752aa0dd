#include "DisplayCheck.h"

#include "CommandLine.h"

#include <QCoreApplication>

#include <cstdlib>
#include <cstring>
#include <iostream>

namespace stylos::app {

namespace {

bool isSet(const char* name)
{
    const char* value = std::getenv(name);
    return value != nullptr && value[0] != '\0';
}

} // namespace

bool hasDisplay(int argc, const char* const* argv)
{
    if (isSet("DISPLAY") || isSet("WAYLAND_DISPLAY") || isSet("QT_QPA_PLATFORM")) return true;
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "-platform") == 0 || std::strcmp(argv[i], "--platform") == 0) return true;
    return false;
}

int runWithoutDisplay(int argc, char* argv[], const char* version)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("stylos"));
    QCoreApplication::setApplicationVersion(QString::fromUtf8(version));
    (void)CommandLine::parse(app); // exits for --help, --version and usage errors
    std::cerr << "stylos: no display to open the workbench on (DISPLAY and WAYLAND_DISPLAY are not set).\n"
                 "  Run it on a desktop session, over `ssh -X`, or under a virtual display:\n"
                 "    xvfb-run -a stylos --grab shot.png     (a screenshot of the demo scene)\n"
                 "  The batch tool needs no display: `stylos-cli --help`.\n";
    return 1;
}

} // namespace stylos::app
