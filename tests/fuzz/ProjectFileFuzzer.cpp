// libFuzzer harness: the project file reader (scene/ProjectFile.cpp: ProjectFile::fromJson, with the legend
// and plate it holds) on arbitrary text. A project that loads must save and load back to an equal scene.
#include "FuzzSupport.h"

#include "stylos/core/scene/ProjectFile.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos::core::scene;
    const std::filesystem::path project = stylos::fuzz::scratchFolder() / "project.stylos";
    auto loaded = ProjectFile::fromJson(std::string_view(reinterpret_cast<const char*>(data), size), project);
    if (!loaded) return 0;
    const std::string saved = ProjectFile::toJson(loaded->scene, project);
    auto again = ProjectFile::fromJson(saved, project);
    if (!again) stylos::fuzz::broken("a project that loads does not load back once saved");
    if (!(again->scene == loaded->scene)) stylos::fuzz::broken("a project saved and loaded back differs");
    return 0;
}
