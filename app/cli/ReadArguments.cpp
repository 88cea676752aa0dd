#include "ReadArguments.h"

#include <charconv>

namespace stylos::cli {

OptionSpec scanOption()
{
    return {"scan", "N", "E57 or PTX input: read only scan N (from 0, as `info` lists them; default: all, merged)"};
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
    return true;
}

} // namespace stylos::cli
