#include "CommandLine.h"

#include <charconv>
#include <iostream>

namespace stylos::cli {

CommandLine::CommandLine(std::string command, std::string synopsis, std::vector<OptionSpec> options)
    : m_command(std::move(command)), m_synopsis(std::move(synopsis)), m_options(std::move(options))
{
    m_options.push_back({"help", "", "show this help and exit", "h"});
}

const OptionSpec* CommandLine::find(const std::string& name) const
{
    for (const auto& o : m_options)
        if (o.name == name || (!o.shortName.empty() && o.shortName == name)) return &o;
    return nullptr;
}

bool CommandLine::parse(const std::vector<std::string>& args)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--") {
            m_positionals.insert(m_positionals.end(), args.begin() + i + 1, args.end());
            break;
        }
        if (a.size() < 2 || a[0] != '-' || (a[1] != '-' && a.size() != 2)) {
            m_positionals.push_back(a);
            continue;
        }
        std::string name = a.substr(a[1] == '-' ? 2 : 1);
        std::optional<std::string> inlineValue;
        if (const auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        const OptionSpec* spec = find(name);
        if (!spec) {
            m_error = "unknown option " + a;
            return false;
        }
        if (spec->name == "help") {
            m_help = true;
            continue;
        }
        if (spec->valueName.empty()) {
            if (inlineValue) {
                m_error = "option --" + spec->name + " takes no value";
                return false;
            }
            m_values[spec->name] = "";
            continue;
        }
        if (inlineValue) {
            m_values[spec->name] = *inlineValue;
        } else if (i + 1 < args.size()) {
            m_values[spec->name] = args[++i];
        } else {
            m_error = "option --" + spec->name + " needs a value (" + spec->valueName + ")";
            return false;
        }
    }
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
    return true;
}

bool CommandLine::integer(const std::string& name, long long& out)
{
    const auto v = value(name);
    if (!v) return true;
    const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
    if (ec != std::errc() || end != v->data() + v->size() || v->empty()) {
        m_error = "--" + name + " expects an integer, not \"" + *v + "\"";
        return false;
    }
    return true;
}

std::string CommandLine::usage() const
{
    std::string u = "usage: stylos-cli " + m_command + " " + m_synopsis + "\n\noptions:\n";
    for (const auto& o : m_options) {
        std::string left = "  ";
        if (!o.shortName.empty()) left += "-" + o.shortName + ", ";
        left += "--" + o.name;
        if (!o.valueName.empty()) left += " " + o.valueName;
        if (left.size() < 30) left.resize(30, ' ');
        else left += "  ";
        u += left + o.help + "\n";
    }
    return u;
}

int usageError(const CommandLine& cl, const std::string& message)
{
    std::cerr << "stylos-cli: " << message << "\n" << cl.usage();
    return ExitUsage;
}

} // namespace stylos::cli
