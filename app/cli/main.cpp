// stylos-cli: batch tool of Stylos. See docs/cli.md and the command-line contract in the design.
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

void printUsage(std::FILE* out)
{
    std::fputs("usage: stylos-cli COMMAND [ARGS] (stylos-cli COMMAND --help for details)\n\n"
               "commands:\n"
               "  info FILE              format, point count, bounds and attributes of a point file;\n"
               "                         depth, cells per level and bytes of a .poct octree\n"
               "  generate KIND -o OUT   synthetic scan with known truth: drum, omphalos or fragment\n"
               "  normals IN -o OUT.ply  estimate normals (k-nearest PCA) for a scan that has none\n"
               "  build IN -o OUT.poct   build the packed point octree of a scan (or of --synthetic-drum N)\n"
               "  unroll IN -o OUT.png   the développée of a drum: fit, unroll, fill holes, shade (skydome)\n"
               "  ao IN -o OUT.ply|poct  3D skydome (ambient occlusion) of the octree's cells\n",
               out);
}

} // namespace

int main(int argc, char** argv)
{
    using namespace stylos::cli;
    if (argc < 2) {
        printUsage(stderr);
        return ExitUsage;
    }
    const std::string command = argv[1];
    const std::vector<std::string> args(argv + 2, argv + argc);
    installInterruptHandler();
    if (command == "--help" || command == "-h" || command == "help") {
        printUsage(stdout);
        return ExitOk;
    }
    if (command == "--version") {
        std::printf("stylos-cli %s\n", STYLOS_VERSION);
        return ExitOk;
    }
    if (command == "info") return runInfo(args);
    if (command == "generate") return runGenerate(args);
    if (command == "normals") return runNormals(args);
    if (command == "build") return runBuild(args);
    if (command == "unroll") return runUnroll(args);
    if (command == "ao") return runAo(args);
    std::fprintf(stderr, "stylos-cli: unknown command \"%s\"\n", command.c_str());
    printUsage(stderr);
    return ExitUsage;
}
