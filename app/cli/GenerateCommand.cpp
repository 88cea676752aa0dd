// stylos-cli generate drum|omphalos|fragment -o OUT.ply [--spacing M] [--seed N] [--design-seed N] [--scans K] [--noise M] [--taper M]
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"

#include "stylos/core/synth/SyntheticScan.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace stylos::cli {

int runGenerate(const std::vector<std::string>& args)
{
    CommandLine cl("generate", "drum|omphalos|fragment -o OUT.ply [options]",
                   {{"output", "OUT.ply", "the binary PLY to write (its truth goes to OUT.truth.json)", "o"},
                    {"spacing", "M", "sample spacing in metres (default 0.002; 0.0005 gives ~17 M points for the drum)"},
                    {"seed", "N", "random seed (default 1): the same seed gives the same file"},
                    {"design-seed", "N", "seed of the drum's design (flutes, breaks): a drum and a fragment with the same design seed come from the same drum (default: --seed)"},
                    {"scans", "K", "number of overlapping scans (default 3)"},
                    {"noise", "M", "sensor noise sigma in metres (default 0.00033)"},
                    {"taper", "M", "drum and fragment: how much smaller the radius is at the upper bed, metres (default 0: a cylinder)"},
                    {"normals", "", "also write the true surface normals"},
                    {"json", "", "print one JSON object on stdout"}});
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Synthetic scans with known truth (a JSON sidecar beside the PLY).\n" << cl.usage();
        return ExitOk;
    }
    if (cl.positionals().size() != 1) return usageError(cl, "generate takes exactly one KIND: drum, omphalos or fragment");
    const auto kind = core::synth::syntheticKindFromName(cl.positionals()[0]);
    if (!kind) return usageError(cl, "unknown kind \"" + cl.positionals()[0] + "\" (drum, omphalos or fragment)");
    const auto output = cl.value("output");
    if (!output || output->empty()) return usageError(cl, "generate needs -o OUT.ply");
    if (lowerExtension(*output) != ".ply") return usageError(cl, "the output must be a .ply file, not \"" + *output + "\"");
    if (const std::string problem = outputProblem(*output); !problem.empty()) return failure(problem);
    // Its truth sidecar too (a read-only OUT.truth.json was replaced without a word).
    if (const std::string problem = outputProblem(core::synth::truthPathFor(*output)); !problem.empty())
        return failure(problem);

    core::synth::SyntheticOptions options;
    long long seed = static_cast<long long>(options.seed), scans = options.scans, designSeed = 0;
    if (!cl.number("spacing", options.spacing) || !cl.integer("seed", seed) || !cl.integer("scans", scans) ||
        !cl.integer("design-seed", designSeed) ||
        !cl.number("noise", options.noise) || !cl.number("taper", options.taper))
        return usageError(cl, cl.error());
    if (!(options.spacing > 0)) return usageError(cl, "--spacing must be a positive number of metres");
    if (!(options.noise >= 0)) return usageError(cl, "--noise must be zero or a positive number of metres");
    if (seed < 0) return usageError(cl, "--seed must be non-negative");
    if (designSeed < 0) return usageError(cl, "--design-seed must be non-negative");
    if (cl.value("design-seed")) options.designSeed = static_cast<std::uint64_t>(designSeed);
    if (scans < 1 || scans > 64) return usageError(cl, "--scans must be between 1 and 64");
    options.seed = static_cast<std::uint64_t>(seed);
    options.scans = static_cast<int>(scans);
    options.writeNormals = cl.flag("normals");

    ConsoleProgress progress("generating " + *output);
    const auto start = std::chrono::steady_clock::now();
    auto report = core::synth::generateScan(*kind, options, *output, &progress);
    if (!report) {
        // An option value the generator cannot take (a taper past a fifth of the radius, a spacing too fine) is a
        // usage error, as the ranges checked above.
        if (report.error().code == core::ErrorCode::InvalidArgument) return usageError(cl, report.error().message);
        return failure(report.error().message);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (cl.flag("json")) {
        nlohmann::json j{{"kind", cl.positionals()[0]}, {"output", *output},
                         {"truth", report->truthPath.string()}, {"points", report->points},
                         {"spacing", options.spacing}, {"seed", options.seed}, {"seconds", seconds}};
        std::cout << j.dump() << "\n";
    } else {
        std::printf("wrote %llu points to %s (truth: %s) in %.2f s\n", static_cast<unsigned long long>(report->points),
                    output->c_str(), report->truthPath.string().c_str(), seconds);
    }
    return ExitOk;
}

} // namespace stylos::cli
