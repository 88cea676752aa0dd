#pragma once
/** @file
 * @brief ASCII lower case for names and extensions the readers and writers compare ("PLY" and "ply" alike).
 *        Thread-safety: pure functions.
 */
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

namespace stylos::core {

/** @brief @p text in ASCII lower case. */
inline std::string lowerCase(std::string_view text)
{
    std::string s(text);
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

/** @brief ".PLY" → ".ply": @p path's extension with its dot, in lower case ("" for none). */
inline std::string lowerExtension(const std::filesystem::path& path) { return lowerCase(path.extension().string()); }

} // namespace stylos::core
