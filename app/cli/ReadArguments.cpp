#include "ReadArguments.h"

#include "AxisArgument.h"

#include <charconv>

namespace stylos::cli {

OptionSpec scanOption()
{
    return {"scan", "N", "E57 or PTX input: read only scan N (from 0, as `info` lists them; default: all, merged)"};
}

std::vector<OptionSpec> frameOptions()
{
    return {{"up", "AXIS", "the input's up axis, turned to +Z: +X, -X, +Y, -Y, +Z (default) or -Z (x, y, z: +)"},
            {"unit", "UNIT", "the input's length unit, converted to metres: mm, cm or m (default)"},
            {"offset", "X,Y,Z", "subtracted from every input point first, in the input's units (default 0,0,0)"}};
}

std::vector<OptionSpec> withFrameOptions(std::vector<OptionSpec> options)
{
    for (OptionSpec& spec : frameOptions()) options.push_back(std::move(spec));
    return options;
}

bool hasFrameOptions(const CommandLine& cl)
{
    return cl.value("up") || cl.value("unit") || cl.value("offset");
}

bool parseReadOptions(const CommandLine& cl, core::io::ReadOptions& read, std::string& problem)
{
    read.columns = cl.value("columns").value_or("");
    if (const auto scan = cl.value("scan")) {
        std::size_t n = 0;
        const auto [end, ec] = std::from_chars(scan->data(), scan->data() + scan->size(), n);
        if (scan->empty() || ec != std::errc() || end != scan->data() + scan->size()) {
            problem = "--scan needs a scan number (0, 1, ...), not \"" + *scan + "\"";
            return false;
        }
        read.scan = n;
    }
    if (const auto up = cl.value("up")) {
        const auto axis = core::io::upAxisFromName(*up);
        if (!axis) {
            problem = "--up must be one of " + core::io::upAxisChoices() + ", not \"" + *up + "\"";
            return false;
        }
        read.frame.up = *axis;
    }
    if (const auto unit = cl.value("unit")) {
        const auto parsed = core::io::lengthUnitFromName(*unit);
        if (!parsed) {
            problem = "--unit must be one of " + core::io::lengthUnitChoices() + ", not \"" + *unit + "\"";
            return false;
        }
        read.frame.unit = *parsed;
    }
    if (const auto offset = cl.value("offset")) {
        std::vector<double> values;
        if (!parseNumberList(*offset, "--offset", 3, values, problem)) return false;
        read.frame.offset = {values[0], values[1], values[2]};
    }
    return true;
}

} // namespace stylos::cli
