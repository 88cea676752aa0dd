#include "PoctInfo.h"

#include "CommandLine.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/octree/PackedOctree.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace stylos::cli {

namespace oct = core::octree;

const char* normalCodeName(oct::NormalCodeKind kind)
{
    return kind == oct::NormalCodeKind::Paper15 ? "paper15" : "octahedral16";
}

std::optional<oct::NormalCodeKind> normalCodeFromName(const std::string& name)
{
    if (name == "octahedral16") return oct::NormalCodeKind::Octahedral16;
    if (name == "paper15") return oct::NormalCodeKind::Paper15;
    return std::nullopt;
}

namespace {

/** The first @p n bytes of @p path (fewer when the file is shorter or unreadable). */
std::vector<std::uint8_t> firstBytes(const std::filesystem::path& path, std::size_t n)
{
    std::vector<std::uint8_t> bytes(n);
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(n));
    bytes.resize(in ? n : static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    return bytes;
}

/** The format version of a file that opened (little-endian uint32 after the 8-byte signature). */
std::uint32_t formatVersion(const std::filesystem::path& path)
{
    const auto b = firstBytes(path, 12);
    if (b.size() < 12) return 0;
    return std::uint32_t(b[8]) | std::uint32_t(b[9]) << 8 | std::uint32_t(b[10]) << 16 | std::uint32_t(b[11]) << 24;
}

const char* typeName(oct::AttributeType type)
{
    switch (type) {
    case oct::AttributeType::UInt8: return "uint8";
    case oct::AttributeType::UInt16: return "uint16";
    case oct::AttributeType::Float32: return "float32";
    }
    return "unknown";
}

nlohmann::json toJson(const std::string& file, const oct::PackedOctree& octree)
{
    const auto& d = octree.description();
    const std::uint64_t cells = octree.totalCells();
    nlohmann::json j;
    j["file"] = file;
    j["format"] = "poct";
    j["version"] = formatVersion(octree.path());
    j["points"] = d.points;
    j["depth"] = d.depth;
    j["normal_code"] = normalCodeName(d.normalCode);
    j["root_box"] = {{"origin", d.box.origin}, {"size", d.box.size}};
    const std::array<double, 3> max{d.box.origin[0] + d.box.size, d.box.origin[1] + d.box.size,
                                    d.box.origin[2] + d.box.size};
    j["bounds"] = {{"min", d.box.origin}, {"max", max}};
    j["cells_per_level"] = d.cellsPerLevel;
    j["cells"] = cells;
    j["leaves"] = d.cellsPerLevel.back();
    j["file_bytes"] = octree.fileBytes();
    j["bytes_per_cell"] = cells > 0 ? static_cast<double>(octree.fileBytes()) / static_cast<double>(cells) : 0.0;
    nlohmann::json names = nlohmann::json::array(), layers = nlohmann::json::array();
    for (const auto& a : octree.attributes()) {
        names.push_back(a.name);
        layers.push_back({{"name", a.name}, {"type", typeName(a.type)}, {"components", a.components},
                          {"bytes", a.bytes.size()}});
    }
    j["attributes"] = names;
    j["layers"] = layers;
    return j;
}

void printText(const nlohmann::json& j)
{
    const auto& box = j["root_box"];
    std::printf("file:        %s\nformat:      poct (version %u)\npoints:      %llu\ndepth:       %d\n"
                "normal code: %s\nroot box:    origin (%.6f, %.6f, %.6f), size %.6f m\n",
                j["file"].get<std::string>().c_str(), j["version"].get<unsigned>(),
                j["points"].get<unsigned long long>(), j["depth"].get<int>(),
                j["normal_code"].get<std::string>().c_str(), box["origin"][0].get<double>(),
                box["origin"][1].get<double>(), box["origin"][2].get<double>(), box["size"].get<double>());
    std::printf("cells:       %llu (leaves %llu)\n", j["cells"].get<unsigned long long>(),
                j["leaves"].get<unsigned long long>());
    const auto& levels = j["cells_per_level"];
    for (std::size_t l = 0; l < levels.size(); ++l)
        std::printf("  level %2zu:  %llu\n", l, levels[l].get<unsigned long long>());
    std::printf("file bytes:  %llu (%.3f bytes per cell)\n", j["file_bytes"].get<unsigned long long>(),
                j["bytes_per_cell"].get<double>());
    std::string layers;
    for (const auto& l : j["layers"])
        layers += (layers.empty() ? "" : ", ") + l["name"].get<std::string>() + " (" +
                  l["type"].get<std::string>() + " x " + std::to_string(l["components"].get<int>()) + ")";
    std::printf("attributes:  %s\n", layers.empty() ? "(none)" : layers.c_str());
}

} // namespace

bool isPoctFile(const std::filesystem::path& path)
{
    return core::io::hasPoctExtension(path) || core::cloud::isPoctPath(path);
}

int runPoctInfo(const std::string& file, bool json)
{
    auto octree = oct::PackedOctree::open(file);
    if (!octree) {
        std::cerr << "stylos-cli: " << octree.error().message << "\n";
        return ExitFailure;
    }
    const nlohmann::json j = toJson(file, *octree);
    if (json) std::cout << j.dump() << "\n";
    else printText(j);
    return ExitOk;
}

} // namespace stylos::cli
