#include "AoScratchFolder.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

namespace stylos::cli {

namespace fs = std::filesystem;

AoScratchFolder::~AoScratchFolder()
{
    std::error_code ignored;
    if (!m_path.empty()) fs::remove_all(m_path, ignored);
}

core::Status AoScratchFolder::create(const fs::path& output)
{
    const fs::path parent = output.has_parent_path() ? output.parent_path() : fs::path(".");
    std::string hidden(".");
    hidden.append(output.filename().string()).append(".ao-XXXXXX");
    const std::string pattern = (parent / hidden).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!::mkdtemp(name.data()))
        return core::Error::at(core::ErrorCode::WriteFailed, parent.string(), "",
                               std::string("cannot create a temporary folder for the octree: ") + std::strerror(errno));
    m_path = name.data();
    return {};
}

} // namespace stylos::cli
