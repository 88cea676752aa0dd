#include "stylos/core/util/ScratchFolder.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

namespace stylos::core {

namespace fs = std::filesystem;

ScratchFolder::~ScratchFolder()
{
    std::error_code ignored;
    if (!m_path.empty()) fs::remove_all(m_path, ignored);
}

Status ScratchFolder::create(const fs::path& output, const std::string& tag)
{
    const fs::path parent = output.has_parent_path() ? output.parent_path() : fs::path(".");
    std::string hidden(".");
    hidden.append(output.filename().string()).append(".").append(tag).append("-XXXXXX");
    const std::string pattern = (parent / hidden).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!::mkdtemp(name.data()))
        return Error::at(ErrorCode::WriteFailed, parent.string(), "",
                               std::string("cannot create a temporary folder for intermediate files: ") + std::strerror(errno));
    m_path = name.data();
    return {};
}

} // namespace stylos::core
