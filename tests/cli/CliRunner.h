#pragma once
// Runs stylos-cli with arguments and captures its exit code, stdout and stderr.
#include <string>
#include <vector>

namespace stylos::test {

struct CliRun {
    int exitCode = -1;
    std::string out;
    std::string err;
};

CliRun runCli(const std::vector<std::string>& args);

} // namespace stylos::test
