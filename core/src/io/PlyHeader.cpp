#include "stylos/core/io/PlyHeader.h"

#include <charconv>

namespace stylos::core::io {

namespace {

struct TypeName {
    const char* name;
    PlyType type;
};
constexpr TypeName typeNames[] = {
    {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
};

std::vector<std::string_view> splitWords(std::string_view line)
{
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
        if (j > i) words.push_back(line.substr(i, j - i));
        i = j;
    }
    return words;
}

} // namespace

std::size_t plyTypeSize(PlyType type)
{
    switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
    }
    return 0;
}

std::optional<PlyType> plyTypeFromName(std::string_view name)
{
    for (const auto& t : typeNames)
        if (name == t.name) return t.type;
    return std::nullopt;
}

const char* plyTypeName(PlyType type)
{
    switch (type) {
    case PlyType::Int8: return "char";
    case PlyType::UInt8: return "uchar";
    case PlyType::Int16: return "short";
    case PlyType::UInt16: return "ushort";
    case PlyType::Int32: return "int";
    case PlyType::UInt32: return "uint";
    case PlyType::Float32: return "float";
    case PlyType::Float64: return "double";
    }
    return "?";
}

bool PlyElement::hasLists() const
{
    for (const auto& p : properties)
        if (p.isList) return true;
    return false;
}

std::size_t PlyElement::recordBytes() const
{
    std::size_t bytes = 0;
    for (const auto& p : properties) bytes += plyTypeSize(p.type);
    return bytes;
}

int PlyElement::find(std::string_view wanted) const
{
    for (std::size_t i = 0; i < properties.size(); ++i)
        if (properties[i].name == wanted) return static_cast<int>(i);
    return -1;
}

Result<PlyHeader> PlyHeader::parse(BufferedFile& file, const std::string& fileName)
{
    constexpr std::uint64_t maxHeaderLines = 100000;
    PlyHeader header;
    std::string_view line;
    std::uint64_t lineNo = 0;
    auto fail = [&](ErrorCode code, const std::string& problem) {
        return Error::at(code, fileName, "line " + std::to_string(lineNo), problem);
    };

    if (!file.readLine(line)) return Error::at(ErrorCode::Empty, fileName, "", "the file is empty");
    ++lineNo;
    if (line != "ply") return fail(ErrorCode::Malformed, "not a PLY file: the first line is not \"ply\"");

    bool haveFormat = false;
    for (;;) {
        if (!file.readLine(line))
            return fail(ErrorCode::Truncated, "the header ends without \"end_header\"");
        ++lineNo;
        if (lineNo > maxHeaderLines || file.lineTooLong())
            return fail(ErrorCode::Malformed, "the header is unreasonably long (no \"end_header\" found)");
        const auto words = splitWords(line);
        if (words.empty()) continue;
        const std::string_view key = words[0];

        if (key == "end_header") {
            if (!file.lineTerminated())
                return fail(ErrorCode::Truncated, "the file ends right after \"end_header\", without its line break");
            break;
        }
        if (key == "comment") {
            header.comments.emplace_back(line.size() > 8 ? line.substr(8) : std::string_view{});
            continue;
        }
        if (key == "obj_info") continue;
        if (key == "format") {
            if (words.size() != 3) return fail(ErrorCode::Malformed, "the format line needs an encoding and a version");
            if (words[1] == "ascii") header.encoding = PlyEncoding::Ascii;
            else if (words[1] == "binary_little_endian") header.encoding = PlyEncoding::BinaryLittleEndian;
            else if (words[1] == "binary_big_endian") header.encoding = PlyEncoding::BinaryBigEndian;
            else return fail(ErrorCode::Malformed, "unknown encoding \"" + std::string(words[1]) + "\"");
            if (words[2] != "1.0" && words[2] != "1")
                return fail(ErrorCode::Unsupported, "PLY version " + std::string(words[2]) + " (only 1.0 is defined)");
            haveFormat = true;
            continue;
        }
        if (key == "element") {
            if (words.size() != 3) return fail(ErrorCode::Malformed, "an element line needs a name and a count");
            PlyElement element;
            element.name = std::string(words[1]);
            const auto countWord = words[2];
            const auto [end, ec] = std::from_chars(countWord.data(), countWord.data() + countWord.size(), element.count);
            if (ec != std::errc() || end != countWord.data() + countWord.size())
                return fail(ErrorCode::Malformed, "the count of element \"" + element.name + "\" is not a non-negative integer");
            if (element.name == "vertex") {
                if (header.vertexElement >= 0) return fail(ErrorCode::Malformed, "a second \"vertex\" element");
                header.vertexElement = static_cast<int>(header.elements.size());
            }
            header.elements.push_back(std::move(element));
            continue;
        }
        if (key == "property") {
            if (header.elements.empty()) return fail(ErrorCode::Malformed, "a property before any element");
            PlyProperty property;
            if (words.size() >= 2 && words[1] == "list") {
                if (words.size() != 5) return fail(ErrorCode::Malformed, "a list property needs a count type, an item type and a name");
                const auto countType = plyTypeFromName(words[2]);
                const auto itemType = plyTypeFromName(words[3]);
                if (!countType || !itemType)
                    return fail(ErrorCode::Malformed, "unknown type in \"" + std::string(line) + "\"");
                if (*countType == PlyType::Float32 || *countType == PlyType::Float64)
                    return fail(ErrorCode::Malformed, "a list count cannot be a floating-point type");
                property.isList = true;
                property.countType = *countType;
                property.type = *itemType;
                property.name = std::string(words[4]);
            } else {
                if (words.size() != 3) return fail(ErrorCode::Malformed, "a property needs a type and a name");
                const auto type = plyTypeFromName(words[1]);
                if (!type) return fail(ErrorCode::Malformed, "unknown property type \"" + std::string(words[1]) + "\"");
                property.type = *type;
                property.name = std::string(words[2]);
            }
            auto& element = header.elements.back();
            if (element.find(property.name) >= 0)
                return fail(ErrorCode::Malformed, "property \"" + property.name + "\" appears twice in element \"" + element.name + "\"");
            element.properties.push_back(std::move(property));
            continue;
        }
        return fail(ErrorCode::Malformed, "unknown header keyword \"" + std::string(key) + "\"");
    }

    if (!haveFormat) return fail(ErrorCode::Malformed, "the header has no \"format\" line");
    if (header.vertexElement < 0) return fail(ErrorCode::Malformed, "the header has no \"vertex\" element");
    const auto& vertex = header.elements[header.vertexElement];
    for (const char* axis : {"x", "y", "z"}) {
        const int i = vertex.find(axis);
        if (i < 0) return fail(ErrorCode::Malformed, std::string("the vertex element has no \"") + axis + "\" property");
        if (vertex.properties[i].isList)
            return fail(ErrorCode::Malformed, std::string("the vertex property \"") + axis + "\" is a list");
    }
    header.headerLines = lineNo;
    header.dataOffset = file.offset();
    return header;
}

} // namespace stylos::core::io
