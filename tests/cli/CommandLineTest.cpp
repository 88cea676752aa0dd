// The command-line contract, common to every command (CommandLine over CLI11): --help prints the usage
// on stdout and exits 0; a usage error exits 2 with exactly one line on stderr naming the problem and
// nothing on stdout; options as --opt VALUE, --opt=VALUE, -o VALUE, -oVALUE, -o=VALUE; the last of a
// repeated option wins; "--" ends the options.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace fs = std::filesystem;
using stylos::test::CliRun;
using stylos::test::runCli;
using stylos::test::TempDir;

namespace {

const std::vector<std::string> CommandNames{"info", "generate", "normals", "build", "unroll", "ao", "annotate", "export"};

std::size_t lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

/** Exit 2, nothing on stdout, and stderr exactly @p line (the problem and where to look). */
void expectUsageLine(const CliRun& run, const std::string& line)
{
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_EQ(run.err, line + "\n");
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
}

/** Generates a tiny synthetic fragment, naming the output with @p outputArgs; whether it succeeded. */
bool generatedInto(const std::vector<std::string>& outputArgs)
{
    std::vector<std::string> args{"generate", "fragment", "--spacing", "0.05"};
    args.insert(args.end(), outputArgs.begin(), outputArgs.end());
    return runCli(args).exitCode == 0;
}

} // namespace

TEST(CliCommandLine, HelpOnEveryCommandPrintsTheUsageAndExitsZero)
{
    for (const std::string& command : CommandNames) {
        for (const char* help : {"--help", "-h"}) {
            const auto run = runCli({command, help});
            EXPECT_EQ(run.exitCode, 0) << command;
            EXPECT_TRUE(run.err.empty()) << command << ": " << run.err;
            EXPECT_NE(run.out.find("usage: stylos-cli " + command + " "), std::string::npos) << run.out;
            EXPECT_NE(run.out.find("\noptions:\n"), std::string::npos) << run.out;
            EXPECT_NE(run.out.find("\n  -h, --help                  show this help and exit\n"), std::string::npos)
                << run.out;
        }
    }
    const auto top = runCli({"--help"});
    EXPECT_EQ(top.exitCode, 0);
    EXPECT_EQ(top.out.rfind("usage: stylos-cli COMMAND [ARGS]", 0), 0u) << top.out;
    // One column for every summary, past the widest synopsis (it ran into "dock FRAGMENT --drum DRUM").
    EXPECT_NE(top.out.find("\n  ao IN -o OUT.ply|poct      3D skydome"), std::string::npos) << top.out;
    EXPECT_NE(top.out.find("\n  dock FRAGMENT --drum DRUM  dock a fragment"), std::string::npos) << top.out;
    EXPECT_NE(top.out.find("\n  export IN.poct -o OUT.ply  one point"), std::string::npos) << top.out;
    EXPECT_NE(top.out.find("scale bar,\n                             legend, caption"), std::string::npos) << top.out;
}

TEST(CliCommandLine, NoCommandOrAnUnknownOneIsOneLine)
{
    const std::string commands = " (commands: info, generate, normals, build, unroll, ao, guides, dock, annotate, export, plate; stylos-cli --help for details)";
    expectUsageLine(runCli({}), "stylos-cli: no command given" + commands);
    expectUsageLine(runCli({"frobnicate"}), "stylos-cli: unknown command \"frobnicate\"" + commands);
}

TEST(CliCommandLine, UsageErrorsAreOneLineNamingTheProblem)
{
    const std::string build = " (usage: stylos-cli build IN -o OUT.poct [options]  |  build --synthetic-drum POINTS -o "
                              "OUT.poct [options]; --help for the options)";
    const std::string info = " (usage: stylos-cli info FILE [--json]; --help for the options)";
    expectUsageLine(runCli({"build", "--depth", "abc", "x.ply", "-o", "y.poct"}),
                    "stylos-cli: --depth expects an integer, not \"abc\"" + build);
    expectUsageLine(runCli({"build", "--depth", "99999999999999999999", "x.ply", "-o", "y.poct"}),
                    "stylos-cli: --depth is out of range: 99999999999999999999" + build); // an integer, too large
    expectUsageLine(runCli({"build", "x.ply", "-o"}), "stylos-cli: option --output needs a value (OUT.poct)" + build);
    expectUsageLine(runCli({"build", "x.ply", "-o", "y.poct", "--depth"}),
                    "stylos-cli: option --depth needs a value (L)" + build);
    expectUsageLine(runCli({"info", "x.ply", "--json=1"}), "stylos-cli: option --json takes no value" + info);
    expectUsageLine(runCli({"info", "x.ply", "--bogus", "3"}), "stylos-cli: unknown option --bogus" + info);
    expectUsageLine(runCli({"info", "-depth", "x.ply"}), "stylos-cli: unknown option -depth" + info);
    expectUsageLine(runCli({"info", "--help", "--bogus"}), "stylos-cli: unknown option --bogus" + info);
    expectUsageLine(runCli({"info", "a.ply", "b.ply"}), "stylos-cli: info takes exactly one FILE" + info);
    // Every command refuses an unknown option the same way.
    for (const std::string& command : CommandNames) {
        const auto run = runCli({command, "--frobnicate"});
        EXPECT_EQ(run.exitCode, 2) << command;
        EXPECT_EQ(run.err.rfind("stylos-cli: unknown option --frobnicate (usage: stylos-cli " + command + " ", 0), 0u)
            << run.err;
        EXPECT_EQ(lines(run.err), 1u) << run.err;
    }
}

TEST(CliCommandLine, EveryFormOfAnOptionAndItsValue)
{
    TempDir dir;
    const std::string out = (dir / "f.ply").string();
    for (const std::vector<std::string>& form :
         {std::vector<std::string>{"-o", out}, {"-o" + out}, {"-o=" + out}, {"--output", out}, {"--output=" + out}}) {
        fs::remove(out);
        EXPECT_TRUE(generatedInto(form)) << form.front();
        EXPECT_TRUE(fs::exists(out)) << form.front();
    }
    // The last of a repeated option wins.
    const std::string first = (dir / "first.ply").string(), last = (dir / "last.ply").string();
    EXPECT_TRUE(generatedInto({"-o", first, "--output", last}));
    EXPECT_FALSE(fs::exists(first));
    EXPECT_TRUE(fs::exists(last));
    // --opt=value and --opt value give the same file; a negative number is a value, not an option.
    // (The same file name in two folders: the PLY header names its truth file.)
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    const std::string a = (dir / "a" / "s.ply").string(), b = (dir / "b" / "s.ply").string();
    ASSERT_EQ(runCli({"generate", "fragment", "-o", a, "--spacing=0.05", "--seed=3"}).exitCode, 0);
    ASSERT_EQ(runCli({"generate", "fragment", "-o", b, "--spacing", "0.05", "--seed", "3"}).exitCode, 0);
    EXPECT_EQ(stylos::test::readBytes(a), stylos::test::readBytes(b));
    ASSERT_EQ(runCli({"generate", "fragment", "-o", b, "--spacing", "0.05", "--seed", "4"}).exitCode, 0);
    EXPECT_NE(stylos::test::readBytes(a), stylos::test::readBytes(b));
    expectUsageLine(runCli({"generate", "fragment", "-o", out, "--seed", "-1"}),
                    "stylos-cli: --seed must be non-negative (usage: stylos-cli generate drum|omphalos|fragment -o "
                    "OUT.ply [options]; --help for the options)");
}

TEST(CliCommandLine, DoubleDashEndsTheOptions)
{
    TempDir dir;
    stylos::test::writeText(dir / "-o.xyz", "0 0 0\n1 0 0\n0 1 0\n");
    const fs::path before = fs::current_path();
    fs::current_path(dir.path()); // the command runs here, so the file's name starts with "-"
    const auto run = runCli({"info", "--json", "--", "-o.xyz"});
    const auto without = runCli({"info", "--json", "-o.xyz"});
    fs::current_path(before);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("\"points\":3"), std::string::npos) << run.out;
    EXPECT_EQ(without.exitCode, 2) << without.err; // -o is not an option of info
}

TEST(CliCommandLine, RuntimeFailuresExitOneWithOneLine)
{
    TempDir dir;
    const std::string missing = (dir / "missing.ply").string();
    const auto run = runCli({"info", missing});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.err.rfind("stylos-cli: " + missing, 0), 0u) << run.err;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_TRUE(run.out.empty());
}

TEST(CliCommandLine, AnOutputThatCannotBeWrittenIsFoundBeforeTheWork)
{
    // Every command that writes a file: a folder in its place, or a folder that does not exist, is exit 1 with
    // one line naming it, before any work (a build of millions of points used to end on it).
    TempDir dir;
    const std::string scan = (dir / "scan.ply").string();
    ASSERT_EQ(runCli({"generate", "fragment", "-o", scan, "--spacing", "0.01"}).exitCode, 0);
    const std::string octree = (dir / "scan.poct").string();
    ASSERT_EQ(runCli({"build", scan, "-o", octree, "--depth", "6"}).exitCode, 0);
    const auto folderNamed = [&](const std::string& name) {
        std::filesystem::create_directory(dir / name);
        return (dir / name).string();
    };
    const std::string nowhere = (dir / "nowhere").string();
    const std::vector<std::vector<std::string>> commands{
        {"generate", "drum", "-o", "%.ply"},
        {"normals", scan, "-o", "%.ply"},
        {"build", scan, "-o", "%.poct"},
        {"ao", octree, "-o", "%.ply"},
        {"unroll", scan, "-o", "%.png"},
        {"guides", scan, "-o", "%.json"},
        {"export", octree, "-o", "%.ply"},
        {"plate", octree, "-o", "%.pdf", "--scale", "10"},
        {"annotate", octree, "--layer", "material", "--raster", scan, "--map", scan, "-o", "%.poct"},
    };
    for (const auto& command : commands) {
        for (const bool isFolder : {true, false}) {
            std::vector<std::string> args = command;
            const auto at = std::find_if(args.begin(), args.end(), [](const std::string& a) { return a[0] == '%'; });
            const std::string ext(at->begin() + 1, at->end());
            const std::string out = isFolder ? folderNamed(args[0] + ext) : nowhere + "/out" + ext;
            *at = out;
            const auto run = runCli(args);
            EXPECT_EQ(run.exitCode, 1) << args[0] << ": " << run.err;
            const std::string expected = isFolder ? out + " is a folder; name a file"
                                                  : out + ": the folder " + nowhere + " does not exist";
            EXPECT_EQ(run.err, "stylos-cli: " + expected + "\n") << args[0];
            EXPECT_TRUE(run.out.empty()) << args[0];
        }
    }
    EXPECT_FALSE(std::filesystem::exists(nowhere));
}
