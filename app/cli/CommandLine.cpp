#include "CommandLine.h"

#include <unistd.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <iostream>

namespace stylos::cli {

namespace {

/** The help's layout: "usage: stylos-cli COMMAND SYNOPSIS", then "options:" with "-o, --output OUT". */
class UsageFormatter : public CLI::Formatter {
public:
    explicit UsageFormatter(std::string synopsis) : m_synopsis(std::move(synopsis)) { column_width(30); }

    std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const override
    {
        return make_usage(app, {}) + make_groups(app, mode);
    }
    std::string make_usage(const CLI::App*, std::string) const override { return "usage: " + m_synopsis + "\n"; }
    std::string make_option_name(const CLI::Option* option, bool) const override
    {
        std::string name;
        for (const auto& s : option->get_snames()) name += "-" + s + ", ";
        for (const auto& l : option->get_lnames()) name += "--" + l + ", ";
        return name.substr(0, name.size() - 2);
    }

private:
    std::string m_synopsis;
};

/** "-o=VALUE" as "-o VALUE" (CLI11 would keep the "=" in the value). */
std::vector<std::string> splitShortAssignments(const std::vector<std::string>& args)
{
    std::vector<std::string> out;
    for (const std::string& a : args) {
        if (a.size() > 3 && a[0] == '-' && a[1] != '-' && a[2] == '=') {
            out.push_back(a.substr(0, 2));
            out.push_back(a.substr(3));
        } else {
            out.push_back(a);
        }
    }
    return out;
}

} // namespace

CommandLine::CommandLine(std::string command, std::string synopsis, std::vector<OptionSpec> options)
    : m_command(std::move(command)), m_synopsis(std::move(synopsis)), m_options(std::move(options)),
      m_app(std::make_unique<CLI::App>())
{
    m_options.push_back({"help", "", "show this help and exit", "h"});
    m_app->formatter(std::make_shared<UsageFormatter>(this->synopsis()));
    m_app->set_help_flag(); // --help is an ordinary flag here: the command prints its own introduction
    m_app->allow_extras();  // unknown options come back in remaining(), named in our message
    m_app->option_defaults()->group("options");
    m_app->add_option("positionals", m_positionals)->group("");
    for (const OptionSpec& o : m_options) {
        const std::string names = (o.shortName.empty() ? "" : "-" + o.shortName + ",") + "--" + o.name;
        if (o.valueName.empty())
            m_app->add_flag(names, o.help);
        else
            m_app->add_option(names, o.help)->type_name(o.valueName)->multi_option_policy(
                CLI::MultiOptionPolicy::TakeLast);
    }
}

CommandLine::~CommandLine() = default;

const OptionSpec* CommandLine::find(const std::string& argument) const
{
    const std::string name = argument.substr(std::min(argument.find_first_not_of('-'), argument.size()));
    for (const auto& o : m_options)
        if (o.name == name || (!o.shortName.empty() && o.shortName == name)) return &o;
    return nullptr;
}

bool CommandLine::parse(const std::vector<std::string>& args)
{
    std::vector<std::string> reversed = splitShortAssignments(args);
    std::reverse(reversed.begin(), reversed.end()); // CLI11 takes the arguments last first
    m_app->clear();
    m_positionals.clear();
    m_values.clear();
    try {
        m_app->parse(reversed);
    } catch (const CLI::ArgumentMismatch& e) {
        // An option that takes a value takes the next argument whatever it is: only the last can lack one.
        const OptionSpec* spec = args.empty() ? nullptr : find(args.back());
        m_error = spec ? "option --" + spec->name + " needs a value (" + spec->valueName + ")" : std::string(e.what());
        return false;
    } catch (const CLI::ParseError& e) {
        m_error = e.what();
        return false;
    }
    for (const std::string& extra : m_app->remaining()) {
        if (extra == "--") continue;
        m_error = "unknown option " + extra;
        return false;
    }
    for (const OptionSpec& o : m_options) {
        const CLI::Option* option = m_app->get_option("--" + o.name);
        if (option->count() == 0) continue;
        const std::vector<std::string>& results = option->results();
        if (o.valueName.empty() &&
            std::any_of(results.begin(), results.end(), [](const std::string& r) { return r != "true"; })) {
            m_error = "option --" + o.name + " takes no value";
            return false;
        }
        m_values[o.name] = o.valueName.empty() ? std::string() : results.back();
    }
    m_help = flag("help");
    return true;
}

std::optional<std::string> CommandLine::value(const std::string& name) const
{
    const auto it = m_values.find(name);
    if (it == m_values.end()) return std::nullopt;
    return it->second;
}

bool CommandLine::number(const std::string& name, double& out)
{
    const auto v = value(name);
    if (!v) return true;
    const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
    if (ec != std::errc() || end != v->data() + v->size() || v->empty()) {
        m_error = "--" + name + " expects a number, not \"" + *v + "\"";
        return false;
    }
    if (!std::isfinite(out)) { // no option takes nan or inf: refused here, as a usage error, once for all
        m_error = "--" + name + " expects a finite number, not \"" + *v + "\"";
        return false;
    }
    return true;
}

bool CommandLine::integer(const std::string& name, long long& out)
{
    const auto v = value(name);
    if (!v) return true;
    const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
    if (ec == std::errc::result_out_of_range && end == v->data() + v->size()) {
        m_error = "--" + name + " is out of range: " + *v;
        return false;
    }
    if (ec != std::errc() || end != v->data() + v->size() || v->empty()) {
        m_error = "--" + name + " expects an integer, not \"" + *v + "\"";
        return false;
    }
    return true;
}

std::string CommandLine::usage() const
{
    return m_app->help();
}

std::string CommandLine::synopsis() const
{
    return "stylos-cli " + m_command + " " + m_synopsis;
}

int usageError(const CommandLine& cl, const std::string& message)
{
    std::cerr << "stylos-cli: " << message << " (usage: " << cl.synopsis() << "; --help for the options)\n";
    return ExitUsage;
}

int failure(const std::string& message)
{
    std::cerr << "stylos-cli: " << message << "\n";
    return ExitFailure;
}

std::string outputProblem(const std::filesystem::path& target)
{
    namespace fs = std::filesystem;
    std::error_code ignored;
    if (fs::is_directory(target, ignored)) return target.string() + " is a folder; name a file";
    // A file made read-only is not replaced (a write through a renamed temporary file would go round its mode, even as
    // root): its owner's write bit, or this user's right to write it. Whatever the folder, "out.poct" included.
    if (const fs::file_status existing = fs::status(target, ignored); fs::is_regular_file(existing) &&
        ((existing.permissions() & fs::perms::owner_write) == fs::perms::none || ::access(target.c_str(), W_OK) != 0))
        return target.string() + " is read-only; make it writable or name another file";
    const fs::path folder = target.parent_path();
    if (folder.empty()) return {};
    std::error_code error;
    const fs::file_status status = fs::status(folder, error);
    if (error && error != std::errc::no_such_file_or_directory) // e.g. a folder on the way that cannot be searched
        return target.string() + ": cannot reach the folder " + folder.string() + ": " + error.message();
    if (fs::exists(status) && !fs::is_directory(status))
        return target.string() + ": " + folder.string() + " is a file, not a folder";
    if (!fs::is_directory(status)) return target.string() + ": the folder " + folder.string() + " does not exist";
    return {};
}

std::string lowerExtension(const std::filesystem::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b)
{
    std::error_code error;
    return std::filesystem::equivalent(a, b, error) && !error;
}

} // namespace stylos::cli
