// stylos-cli: batch tool of Stylos. See docs/cli.md and the command-line contract in the design.
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace stylos::cli;

struct Command {
    const char* name;
    int (*run)(const std::vector<std::string>&);
    const char* synopsis; ///< the left column of the command list
    const char* summary;
};

constexpr Command Commands[] = {
    {"info", runInfo, "info FILE", "format, point count, bounds and attributes of a point file;\n"
                                   "depth, cells per level and bytes of a .poct octree"},
    {"generate", runGenerate, "generate KIND -o OUT", "synthetic scan with known truth: drum, omphalos or fragment"},
    {"normals", runNormals, "normals IN -o OUT.ply", "estimate normals (k-nearest PCA) for a scan that has none"},
    {"build", runBuild, "build IN -o OUT.poct", "build the packed point octree of a scan (or of --synthetic-drum N)"},
    {"unroll", runUnroll, "unroll IN -o OUT.png", "the développée of a drum: fit, unroll, fill holes, shade (skydome)"},
    {"ao", runAo, "ao IN -o OUT.ply|poct", "3D skydome (ambient occlusion) of the octree's cells"},
    {"guides", runGuides, "guides DRUM -o G.json", "guides of an intact drum: axis, leading radius, flutes and their lines"},
    {"dock", runDock, "dock FRAGMENT --drum DRUM", "dock a fragment against a drum's guides: flute snap and registration"},
    {"annotate", runAnnotate, "annotate IN.poct ...", "label the leaves from a label raster painted on a développée"},
    {"export", runExport, "export IN.poct -o OUT.ply", "one point per leaf with its annotation and ambient layers"},
    {"plate", runPlate, "plate IN -o OUT.pdf", "a publication plate at 1:N: développée or orthographic view, scale bar,\n"
                                           "legend, caption; PDF, SVG, TIFF or PNG"},
};

void printUsage()
{
    std::puts("usage: stylos-cli COMMAND [ARGS] (stylos-cli COMMAND --help for details)\n\ncommands:");
    std::size_t column = 0; // the widest synopsis and two spaces
    for (const Command& c : Commands) column = std::max(column, std::strlen(c.synopsis) + 2);
    for (const Command& c : Commands) {
        std::string summary = c.summary;
        for (std::size_t at = summary.find('\n'); at != std::string::npos; at = summary.find('\n', at + 1))
            summary.insert(at + 1, column + 2, ' ');
        std::printf("  %-*s%s\n", int(column), c.synopsis, summary.c_str());
    }
}

/** One line on stderr naming the problem and the commands; the usage-error exit code. */
int commandError(const std::string& problem)
{
    std::string names;
    for (const Command& c : Commands) names += (names.empty() ? "" : ", ") + std::string(c.name);
    std::fprintf(stderr, "stylos-cli: %s (commands: %s; stylos-cli --help for details)\n", problem.c_str(),
                 names.c_str());
    return ExitUsage;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) return commandError("no command given");
    const std::string command = argv[1];
    const std::vector<std::string> args(argv + 2, argv + argc);
    installInterruptHandler();
    if (command == "--help" || command == "-h" || command == "help") {
        printUsage();
        return ExitOk;
    }
    if (command == "--version") {
        std::printf("stylos-cli %s\n", STYLOS_VERSION);
        return ExitOk;
    }
    for (const Command& c : Commands)
        if (command == c.name) return c.run(args);
    return commandError("unknown command \"" + command + "\"");
}
