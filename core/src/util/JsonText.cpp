#include "stylos/core/util/JsonText.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

namespace stylos::core {

namespace {

/**
 * nlohmann's DOM builder, told not to throw, that keeps where and why the parse failed: its parse_error()
 * receives both the syntax errors and the number overflow (out_of_range 406) with the byte reached.
 */
class RecordingDomParser : public nlohmann::detail::json_sax_dom_parser<nlohmann::json> {
public:
    explicit RecordingDomParser(nlohmann::json& root) : json_sax_dom_parser(root, false) {}

    template <class Exception>
    bool parse_error(std::size_t position, const std::string& /*lastToken*/, const Exception& error)
    {
        failedAt = position;
        // "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error …" → "syntax error …";
        // "[json.exception.out_of_range.406] number overflow parsing '1e400'" → "number overflow parsing '1e400'".
        std::string what = error.what();
        if (const auto bracket = what.find("] "); bracket != std::string::npos) what = what.substr(bracket + 2);
        if (what.rfind("parse error", 0) == 0) {
            const auto colon = what.find(": ");
            what = colon == std::string::npos ? std::string("syntax error") : what.substr(colon + 2);
        }
        detail = what;
        return false;
    }

    std::optional<std::size_t> failedAt;
    std::string detail;
};

} // namespace

std::string textPosition(std::string_view text, std::size_t byte)
{
    const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

Result<nlohmann::json> parseJsonText(std::string_view text, const std::string& source)
{
    nlohmann::json root;
    RecordingDomParser parser(root);
    const bool ok = nlohmann::json::sax_parse(text, &parser);
    if (!ok || parser.failedAt || root.is_discarded())
        return Error::at(ErrorCode::Malformed, source, textPosition(text, parser.failedAt.value_or(text.size() + 1)),
                         "not valid JSON: " + (parser.detail.empty() ? std::string("syntax error") : parser.detail));
    return root;
}

Result<nlohmann::json> readJsonFile(const std::filesystem::path& path)
{
    const std::string name = path.string();
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) return Error::at(ErrorCode::NotFound, name, {}, "no such file");
    if (std::filesystem::is_directory(status)) return Error::at(ErrorCode::Unreadable, name, {}, "is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error::at(ErrorCode::Unreadable, name, {}, std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return Error::at(ErrorCode::Unreadable, name, {}, "read failed");
    return parseJsonText(text.str(), name);
}

} // namespace stylos::core
