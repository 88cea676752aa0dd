#pragma once
// The argument parser of every stylos-cli command, a facade over CLI11 (Debian's libcli11-dev):
// positionals, --flags and --options VALUE (or --option=VALUE; short forms -o VALUE, -oVALUE, -o=VALUE),
// "--" ending the options; a repeated option keeps its last value. The commands read the values as
// text and convert them here (number(), integer()) so that each bad value is named in one message.
// Usage errors print one line and end the program with exit code 2, per the command-line contract.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace stylos::cli {

struct OptionSpec {
    std::string name;      ///< without the leading "--"
    std::string valueName; ///< empty for a flag
    std::string help;
    std::string shortName = {}; ///< e.g. "o" for -o
};

class CommandLine {
public:
    CommandLine(std::string command, std::string synopsis, std::vector<OptionSpec> options);
    ~CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    /** Parses @p args (after the command word). Returns false with error() set on a usage error. */
    bool parse(const std::vector<std::string>& args);
    const std::string& error() const { return m_error; }
    bool helpRequested() const { return m_help; }
    /** "usage: stylos-cli COMMAND SYNOPSIS", then every option with its help: what --help prints. */
    std::string usage() const;
    /** "stylos-cli COMMAND SYNOPSIS", one line. */
    std::string synopsis() const;

    const std::vector<std::string>& positionals() const { return m_positionals; }
    bool flag(const std::string& name) const { return m_values.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;

    /** Typed values; false with error() set when the text is not a valid number (or, for number(), not finite). */
    bool number(const std::string& name, double& out);
    bool integer(const std::string& name, long long& out);

private:
    const OptionSpec* find(const std::string& argument) const;
    std::string m_command;
    std::string m_synopsis;
    std::vector<OptionSpec> m_options;
    std::unique_ptr<CLI::App> m_app;
    std::vector<std::string> m_positionals;
    std::map<std::string, std::string> m_values;
    std::string m_error;
    bool m_help = false;
};

/** Exit codes of the command-line contract. */
enum ExitCode { ExitOk = 0, ExitFailure = 1, ExitUsage = 2 };

/**
 * Prints one line to stderr, "stylos-cli: message (usage: stylos-cli COMMAND SYNOPSIS; --help for the
 * options)", and returns ExitUsage.
 */
int usageError(const CommandLine& cl, const std::string& message);

/** Prints one line to stderr, "stylos-cli: message", and returns ExitFailure. */
int failure(const std::string& message);

/**
 * What keeps @p target from being written, checked by every command before its work (so a long build does not
 * end on it): "TARGET is a folder; name a file", "TARGET: the folder F does not exist", "TARGET: F is a file, not a
 * folder", "TARGET: cannot reach the folder F: REASON" or "TARGET is read-only; …" (an existing file without its
 * owner's write bit, or one this user may not write); empty when none.
 * Reported with failure() (exit 1, the output not writable), like a write that fails later.
 */
std::string outputProblem(const std::filesystem::path& target);

/** The extension of @p path in lower case, with its dot (".ply"); empty without one. */
std::string lowerExtension(const std::filesystem::path& path);

/** Whether @p a and @p b name the same existing file (links and other spellings resolved). */
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b);

} // namespace stylos::cli
