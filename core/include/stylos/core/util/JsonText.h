#pragma once
/** @file
 * @brief Reading JSON text into a tree without exceptions: the one place the project's JSON files (project,
 *        legend, plate layout, développée sidecar, guides) are parsed, so that every kind of bad text comes
 *        back as the same Malformed error. nlohmann's parser throws not only parse_error but out_of_range for
 *        a number too large for a double (e.g. 1e400); both are caught here, with where they happened.
 *
 * Messages: "SOURCE: line L, column C: not valid JSON: DETAIL", DETAIL being nlohmann's (e.g. "syntax error
 * while parsing value - invalid literal; last read: 'x'", "number overflow parsing '1e400'").
 * Thread-safety: reentrant.
 */
#include "stylos/core/util/Result.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace stylos::core {

/** @brief "line L, column C" (1-based) of the byte at 1-based offset @p byte of @p text. */
std::string textPosition(std::string_view text, std::size_t byte);

/** @brief @p text as a JSON tree; Malformed naming @p source, the line and column, and the problem. */
Result<nlohmann::json> parseJsonText(std::string_view text, const std::string& source);

/**
 * @brief Reads the file @p path whole and parses it: NotFound ("no such file"), Unreadable ("is a directory",
 *        "cannot open: …", "read failed"), Malformed as parseJsonText(), each naming the path.
 */
Result<nlohmann::json> readJsonFile(const std::filesystem::path& path);

} // namespace stylos::core
