#pragma once
// The stylos-cli commands; each takes the arguments after its name and returns the exit code.
#include <string>
#include <vector>

namespace stylos::cli {

int runInfo(const std::vector<std::string>& args);
int runGenerate(const std::vector<std::string>& args);
int runNormals(const std::vector<std::string>& args);
int runBuild(const std::vector<std::string>& args);
int runUnroll(const std::vector<std::string>& args);
int runAo(const std::vector<std::string>& args);
int runGuides(const std::vector<std::string>& args);
int runDock(const std::vector<std::string>& args);
int runAnnotate(const std::vector<std::string>& args);
int runExport(const std::vector<std::string>& args);
int runPlate(const std::vector<std::string>& args);

} // namespace stylos::cli
