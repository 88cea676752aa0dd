#include "stylos/core/util/AtomicTextFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

namespace stylos::core {

Status writeTextFileAtomically(const std::filesystem::path& path, std::string_view text)
{
    std::filesystem::path temporary = path;
    temporary += ".part";
    auto failed = [&](const std::string& problem) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        return Error::at(ErrorCode::WriteFailed, path.string(), {}, problem);
    };
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) return failed("cannot create " + temporary.string() + ": " + std::strerror(errno));
        out.write(text.data(), std::streamsize(text.size()));
        out.close();
        if (!out) return failed("write failed");
    }
    keepModeOf(path, temporary);
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) return failed("cannot rename into place: " + error.message());
    return {};
}

void keepModeOf(const std::filesystem::path& target, const std::filesystem::path& temporary)
{
    std::error_code ec;
    if (const std::filesystem::file_status existing = std::filesystem::status(target, ec); !ec && std::filesystem::is_regular_file(existing))
        std::filesystem::permissions(temporary, existing.permissions() & std::filesystem::perms::all, ec);
}

} // namespace stylos::core
