#include "stylos/core/io/E57Structure.h"

#include <pugixml.hpp>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace stylos::core::io {

namespace {

template <typename T>
T loadLe(const char* p)
{
    T v;
    std::memcpy(&v, p, sizeof v); // little-endian host, as every reader assumes
    return v;
}

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

template <typename T>
bool parseNumber(std::string_view text, T& out)
{
    text = trimmed(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    if (text.empty()) return false;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size();
}

/** Reads the XML tree; every failure is a Malformed error about one element. */
class XmlScans {
public:
    XmlScans(std::string file, std::string position) : m_file(std::move(file)), m_position(std::move(position)) {}

    Error fail(const std::string& problem) const { return Error::at(ErrorCode::Malformed, m_file, m_position, problem); }

    /** An element's value as a double: Float, Integer or ScaledInteger (raw × scale + offset); empty text is 0. */
    bool number(const pugi::xml_node& node, double& out, std::string& problem) const
    {
        const std::string_view type = node.attribute("type").value();
        const std::string_view text = trimmed(node.child_value());
        if (type == "Float") {
            out = 0;
            if (text.empty() || parseNumber(text, out)) return true;
        } else if (type == "Integer" || type == "ScaledInteger") {
            std::int64_t raw = 0;
            if (!text.empty() && !parseNumber(text, raw)) {
                problem = "element <" + std::string(node.name()) + ">: \"" + std::string(text) + "\" is not an integer";
                return false;
            }
            out = double(raw);
            if (type == "ScaledInteger") out = out * node.attribute("scale").as_double(1.0) + node.attribute("offset").as_double(0.0);
            return true;
        }
        problem = "element <" + std::string(node.name()) + "> (type \"" + std::string(type) + "\") is not a number";
        return false;
    }

    /** Attribute @p name of @p node as a T (an integer or a number), @p fallback when it is absent. */
    template <typename T>
    bool attribute(const pugi::xml_node& node, const char* name, T fallback, T& out, std::string& problem) const
    {
        const pugi::xml_attribute a = node.attribute(name);
        out = fallback;
        if (!a) return true;
        if (parseNumber(std::string_view(a.value()), out)) return true;
        problem = "prototype field <" + std::string(node.name()) + ">: attribute " + name + "=\"" + a.value() +
                  (std::is_integral_v<T> ? "\" is not an integer" : "\" is not a number");
        return false;
    }

    /** Depth-first leaves of a prototype, as libE57Format numbers its bytestreams. */
    bool fields(const pugi::xml_node& node, const std::string& prefix, std::vector<E57Field>& out, std::string& problem) const
    {
        for (const pugi::xml_node& child : node.children()) {
            if (child.type() != pugi::node_element) continue;
            const std::string name = prefix + child.name();
            const std::string_view type = child.attribute("type").value();
            if (type == "Structure") {
                if (!fields(child, name + "/", out, problem)) return false;
                continue;
            }
            E57Field f;
            f.name = name;
            if (type == "Float") {
                f.type = E57Field::Type::Float;
                f.singlePrecision = std::string_view(child.attribute("precision").value()) == "single";
                const double big = std::numeric_limits<double>::max();
                if (!attribute(child, "minimum", -big, f.floatMinimum, problem) ||
                    !attribute(child, "maximum", big, f.floatMaximum, problem))
                    return false;
            } else if (type == "Integer" || type == "ScaledInteger") {
                f.type = type == "Integer" ? E57Field::Type::Integer : E57Field::Type::ScaledInteger;
                if (!attribute(child, "minimum", std::numeric_limits<std::int64_t>::min(), f.minimum, problem) ||
                    !attribute(child, "maximum", std::numeric_limits<std::int64_t>::max(), f.maximum, problem))
                    return false;
                if (f.type == E57Field::Type::ScaledInteger &&
                    (!attribute(child, "scale", 1.0, f.scale, problem) ||
                     !attribute(child, "offset", 0.0, f.offset, problem)))
                    return false;
                if (f.minimum > f.maximum) {
                    problem = "prototype field <" + name + ">: minimum " + std::to_string(f.minimum) +
                              " is above maximum " + std::to_string(f.maximum);
                    return false;
                }
            } else {
                problem = "prototype field <" + name + "> has type \"" + std::string(type) +
                          "\"; only Float, ScaledInteger and Integer fields are read";
                return false;
            }
            out.push_back(std::move(f));
        }
        return true;
    }

    /** The pose: rotation quaternion (w, x, y, z) and translation, as a 3×4 [R | t]. */
    bool pose(const pugi::xml_node& node, ScanInfo& info, const std::string& scanName, std::string& problem) const
    {
        if (!node) return true;
        std::array<double, 4> q{1, 0, 0, 0};
        std::array<double, 3> t{0, 0, 0};
        if (const pugi::xml_node r = node.child("rotation")) {
            const char* names[] = {"w", "x", "y", "z"};
            for (int k = 0; k < 4; ++k) {
                q[k] = 0;
                if (const pugi::xml_node c = r.child(names[k]); c && !number(c, q[k], problem)) return false;
            }
        }
        if (const pugi::xml_node tr = node.child("translation")) {
            const char* names[] = {"x", "y", "z"};
            for (int k = 0; k < 3; ++k)
                if (const pugi::xml_node c = tr.child(names[k]); c && !number(c, t[k], problem)) return false;
        }
        const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(norm > 0) || !std::isfinite(norm)) {
            problem = scanName + ": the pose's rotation quaternion is zero or not finite";
            return false;
        }
        info.quaternion = q;
        const double w = q[0] / norm, x = q[1] / norm, y = q[2] / norm, z = q[3] / norm;
        info.pose = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),     t[0],
                     2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),     t[1],
                     2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y), t[2]};
        return true;
    }

    template <std::size_t N>
    bool limits(const pugi::xml_node& node, const char* const (&names)[N], std::optional<std::array<double, N>>& out,
                const std::array<double, N>& defaults, std::string& problem) const
    {
        if (!node) return true;
        std::array<double, N> values = defaults;
        for (std::size_t k = 0; k < N; ++k)
            if (const pugi::xml_node c = node.child(names[k]); c && !number(c, values[k], problem)) return false;
        out = values;
        return true;
    }

    Result<E57Scan> scan(const pugi::xml_node& node, std::size_t index) const
    {
        E57Scan s;
        s.info.name = trimmed(node.child_value("name"));
        s.info.guid = trimmed(node.child_value("guid"));
        const std::string label = "scan " + std::to_string(index) +
                                  (s.info.name.empty() ? std::string() : " (\"" + s.info.name + "\")");
        std::string problem;
        if (!pose(node.child("pose"), s.info, label, problem)) return fail(problem);

        const pugi::xml_node points = node.child("points");
        if (!points || std::string_view(points.attribute("type").value()) != "CompressedVector")
            return fail(label + " has no <points> compressed vector");
        if (!parseNumber(std::string_view(points.attribute("fileOffset").value()), s.sectionOffset))
            return fail(label + ": <points> has no valid fileOffset");
        if (!parseNumber(std::string_view(points.attribute("recordCount").value()), s.recordCount))
            return fail(label + ": <points> has no valid recordCount");
        s.info.points = s.recordCount;
        const pugi::xml_node prototype = points.child("prototype");
        if (!prototype) return fail(label + ": <points> has no <prototype>");
        if (!fields(prototype, "", s.fields, problem)) return fail(label + ": " + problem);

        static const char* const intensityNames[] = {"intensityMinimum", "intensityMaximum"};
        static const char* const colorNames[] = {"colorRedMinimum",   "colorRedMaximum",  "colorGreenMinimum",
                                                 "colorGreenMaximum", "colorBlueMinimum", "colorBlueMaximum"};
        if (!limits(node.child("intensityLimits"), intensityNames, s.intensityLimits, {0, 0}, problem) ||
            !limits(node.child("colorLimits"), colorNames, s.colorLimits, {0, 0, 0, 0, 0, 0}, problem))
            return fail(label + ": " + problem);
        return s;
    }

private:
    std::string m_file, m_position;
};

} // namespace

Result<E57FileHeader> E57FileHeader::parse(const char* bytes, std::uint64_t fileSize, const std::string& file)
{
    auto fail = [&](ErrorCode code, const char* where, const std::string& problem) {
        return Error::at(code, file, where, problem);
    };
    if (std::memcmp(bytes, "ASTM-E57", 8) != 0)
        return fail(ErrorCode::Malformed, "byte 0", "not an E57 file: it does not start with the signature \"ASTM-E57\"");
    E57FileHeader h;
    h.versionMajor = loadLe<std::uint32_t>(bytes + 8);
    h.versionMinor = loadLe<std::uint32_t>(bytes + 12);
    h.physicalLength = loadLe<std::uint64_t>(bytes + 16);
    h.xmlOffset = loadLe<std::uint64_t>(bytes + 24);
    h.xmlLength = loadLe<std::uint64_t>(bytes + 32);
    h.pageSize = loadLe<std::uint64_t>(bytes + 40);
    if (h.versionMajor != 1)
        return fail(ErrorCode::Unsupported, "byte 8",
                    "E57 version " + std::to_string(h.versionMajor) + "." + std::to_string(h.versionMinor) +
                        " is not read (only version 1.x)");
    if (h.pageSize != 1024)
        return fail(ErrorCode::Unsupported, "byte 40",
                    "page size " + std::to_string(h.pageSize) + " is not read (the standard's is 1024)");
    if (h.physicalLength > fileSize)
        return fail(ErrorCode::Truncated, "byte 16",
                    "the header announces " + std::to_string(h.physicalLength) + " bytes but the file has " +
                        std::to_string(fileSize) + " (it was cut short)");
    if (h.physicalLength != fileSize || fileSize % 1024 != 0)
        return fail(ErrorCode::Malformed, "byte 16",
                    "the header announces " + std::to_string(h.physicalLength) + " bytes but the file has " +
                        std::to_string(fileSize) + " (not whole 1024-byte pages)");
    if (h.xmlLength == 0 || h.xmlOffset % 1024 >= 1020 || h.xmlOffset >= fileSize ||
        (h.xmlOffset / 1024 * 1020 + h.xmlOffset % 1024) + h.xmlLength > fileSize / 1024 * 1020)
        return fail(ErrorCode::Malformed, "byte 24",
                    "the XML section (offset " + std::to_string(h.xmlOffset) + ", " + std::to_string(h.xmlLength) +
                        " bytes) does not lie inside the file");
    return h;
}

unsigned E57Field::bits() const
{
    if (type == Type::Float) return singlePrecision ? 32 : 64;
    const std::uint64_t range = std::uint64_t(maximum) - std::uint64_t(minimum);
    return static_cast<unsigned>(std::bit_width(range));
}

double E57Field::valueMinimum() const
{
    if (type == Type::Float) return floatMinimum;
    const double raw = double(minimum);
    return type == Type::Integer ? raw : raw * scale + offset;
}

double E57Field::valueMaximum() const
{
    if (type == Type::Float) return floatMaximum;
    const double raw = double(maximum);
    return type == Type::Integer ? raw : raw * scale + offset;
}

int E57Scan::field(const std::string& name) const
{
    for (std::size_t i = 0; i < fields.size(); ++i)
        if (fields[i].name == name) return static_cast<int>(i);
    return -1;
}

Result<std::vector<E57Scan>> parseE57Xml(const char* xml, std::size_t size, const std::string& file,
                                         const std::string& position)
{
    XmlScans reader(file, position);
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(xml, size, pugi::parse_default, pugi::encoding_utf8);
    if (!parsed)
        return reader.fail(std::string("the XML is not well formed (") + parsed.description() + " at character " +
                           std::to_string(parsed.offset) + ")");
    const pugi::xml_node root = doc.child("e57Root");
    if (!root) return reader.fail("the XML has no <e57Root> element");
    std::vector<E57Scan> scans;
    std::size_t index = 0;
    for (const pugi::xml_node& child : root.child("data3D").children()) {
        if (child.type() != pugi::node_element) continue;
        auto scan = reader.scan(child, index++);
        if (!scan) return scan.error();
        scans.push_back(std::move(scan).value());
    }
    return scans;
}

} // namespace stylos::core::io
