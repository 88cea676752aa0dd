#pragma once
// A small argument parser for stylos-cli commands: positionals, --flags and --options VALUE
// (or --option=VALUE). Usage errors end the program with exit code 2, per the command-line contract.
#include <map>
#include <optional>
#include <string>
#include <vector>

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

    /** Parses @p args (after the command word). Returns false with error() set on a usage error. */
    bool parse(const std::vector<std::string>& args);
    const std::string& error() const { return m_error; }
    bool helpRequested() const { return m_help; }
    std::string usage() const;

    const std::vector<std::string>& positionals() const { return m_positionals; }
    bool flag(const std::string& name) const { return m_values.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;

    /** Typed values; false with error() set when the text is not a valid number. */
    bool number(const std::string& name, double& out);
    bool integer(const std::string& name, long long& out);

private:
    const OptionSpec* find(const std::string& name) const;
    std::string m_command;
    std::string m_synopsis;
    std::vector<OptionSpec> m_options;
    std::vector<std::string> m_positionals;
    std::map<std::string, std::string> m_values;
    std::string m_error;
    bool m_help = false;
};

/** Exit codes of the command-line contract. */
enum ExitCode { ExitOk = 0, ExitFailure = 1, ExitUsage = 2 };

/** Prints "stylos-cli COMMAND: message" and the usage hint to stderr; returns ExitUsage. */
int usageError(const CommandLine& cl, const std::string& message);

} // namespace stylos::cli
