#include "TemporaryImageFile.h"
#include "stylos/core/util/AtomicTextFile.h"

#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <system_error>

namespace fs = std::filesystem;

namespace stylos::core::image {

namespace {

Error failure(const fs::path& target, const std::string& problem)
{
    return Error::at(ErrorCode::WriteFailed, target.string(), "", problem);
}

std::string randomHex16()
{
    std::random_device device;
    const std::uint64_t bits = (std::uint64_t(device()) << 32) ^ std::uint64_t(device());
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(bits));
    return text;
}

} // namespace

TemporaryImageFile::TemporaryImageFile(fs::path target, fs::path temporary)
    : m_target(std::move(target)), m_temporary(std::move(temporary))
{
}

TemporaryImageFile::TemporaryImageFile(TemporaryImageFile&& other) noexcept
    : m_target(std::move(other.m_target)), m_temporary(std::move(other.m_temporary)), m_active(other.m_active)
{
    other.m_active = false;
}

TemporaryImageFile::~TemporaryImageFile()
{
    if (!m_active) return;
    std::error_code ignored;
    fs::remove(m_temporary, ignored);
}

Result<TemporaryImageFile> TemporaryImageFile::beside(const fs::path& target)
{
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    const fs::file_status folderStatus = fs::status(folder, ec);
    if (!fs::exists(folderStatus))
        return failure(target, "the folder " + folder.string() + " does not exist");
    if (!fs::is_directory(folderStatus))
        return failure(target, folder.string() + " is not a folder");
    if (fs::is_directory(fs::status(target, ec)))
        return failure(target, "the target is a folder");

    const std::string name = target.filename().string();
    const std::string extension = target.extension().string();
    const std::string stem = name.substr(0, name.size() - extension.size());
    for (int attempt = 0; attempt < 16; ++attempt) {
        fs::path temporary = folder / ("." + stem + ".tmp-" + randomHex16() + extension);
        if (!fs::exists(fs::symlink_status(temporary, ec))) return TemporaryImageFile(target, std::move(temporary));
    }
    return failure(target, "no free temporary file name in " + folder.string());
}

Status TemporaryImageFile::commit()
{
    keepModeOf(m_target, m_temporary);
    std::error_code ec;
    fs::rename(m_temporary, m_target, ec);
    if (ec) {
        // The destructor removes the temporary.
        return failure(m_target, "cannot move the finished image into place: " + ec.message());
    }
    m_active = false;
    return {};
}

} // namespace stylos::core::image
