// One LAS 1.4 (format 6) point per leaf: material as classification, toolmark and ambient as extra bytes.
#include "stylos/core/annotation/LeafLas.h"
#include "stylos/core/util/AtomicTextFile.h"

#include "stylos/core/annotation/LeafExport.h"
#include "stylos/core/annotation/LeafLabels.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

namespace stylos::core::annotation {

namespace {

namespace fs = std::filesystem;

constexpr double kScale = 0.0001; // 0.1 mm
constexpr std::size_t kHeaderSize = 375;
constexpr std::size_t kVlrHeader = 54;
constexpr std::size_t kFormat6Length = 30;

template <typename T>
void put(std::vector<std::uint8_t>& out, std::size_t at, T value)
{
    std::memcpy(out.data() + at, &value, sizeof value);
}

void putText(std::vector<std::uint8_t>& out, std::size_t at, const std::string& text, std::size_t width)
{
    std::memcpy(out.data() + at, text.data(), std::min(text.size(), width));
}

std::vector<std::uint8_t> vlr(const std::string& user, std::uint16_t record, const std::string& description,
                              const std::vector<std::uint8_t>& payload)
{
    std::vector<std::uint8_t> out(kVlrHeader + payload.size(), 0);
    putText(out, 2, user, 16);
    put<std::uint16_t>(out, 18, record);
    put<std::uint16_t>(out, 20, std::uint16_t(payload.size()));
    putText(out, 22, description, 32);
    std::copy(payload.begin(), payload.end(), out.begin() + kVlrHeader);
    return out;
}

/** One Extra Bytes descriptor (192 bytes). */
std::vector<std::uint8_t> extraBytes(std::uint8_t dataType, const std::string& name, const std::string& description)
{
    std::vector<std::uint8_t> d(192, 0);
    d[2] = dataType;
    putText(d, 4, name, 32);
    putText(d, 160, description, 32);
    return d;
}

} // namespace

Result<std::uint64_t> exportLeafLas(const octree::PackedOctree& octree, const std::vector<std::string>& layers,
                                    const Legend& legend, const fs::path& output, ProgressSink* progress)
{
    const std::string file = octree.path().string();
    const std::uint64_t leaves = leafCount(octree);
    auto read = readLeafColumns(octree, layers, output);
    if (!read) return read.error();
    // Material becomes the classification byte; the other layers extra bytes, in the order asked.
    std::vector<std::uint8_t> material;
    std::vector<LeafColumn> extras;
    for (LeafColumn& c : *read) {
        if (c.name != "material") {
            extras.push_back(std::move(c));
            continue;
        }
        material = std::move(c.labels);
        const auto high = std::find_if(material.begin(), material.end(), [](std::uint8_t id) { return id > 255 - kLasClassOffset; });
        if (high != material.end())
            return Error::at(ErrorCode::InvalidArgument, file, {}, "material class " + std::to_string(*high) +
                                                                       " is above 191, the last a LAS classification can hold");
    }

    // VLRs: the classification lookup, the extra bytes, the legend.
    std::vector<std::vector<std::uint8_t>> vlrs;
    if (!material.empty()) {
        std::vector<std::uint8_t> lookup;
        for (const LegendClass& c : legend.material) {
            if (c.id > 255 - kLasClassOffset) continue;
            std::vector<std::uint8_t> entry(16, 0);
            entry[0] = std::uint8_t(kLasClassOffset + c.id);
            putText(entry, 1, c.name, 15);
            lookup.insert(lookup.end(), entry.begin(), entry.end());
        }
        vlrs.push_back(vlr("LASF_Spec", 0, "Classification lookup", lookup));
    }
    std::size_t extraLength = 0;
    if (!extras.empty()) {
        std::vector<std::uint8_t> descriptors;
        for (const LeafColumn& c : extras) {
            const bool floats = c.isFloat();
            const auto d = extraBytes(floats ? 9 : 1, c.name,
                                      floats ? "fraction of the sky (3D skydome)" : "Stylos tool-mark class id");
            descriptors.insert(descriptors.end(), d.begin(), d.end());
            extraLength += floats ? 4 : 1;
        }
        vlrs.push_back(vlr("LASF_Spec", 4, "Extra bytes", descriptors));
    }
    {
        const std::string json = legend.toJson().dump();
        vlrs.push_back(vlr("Stylos", 1, "Annotation legend (JSON)", std::vector<std::uint8_t>(json.begin(), json.end())));
    }
    std::size_t vlrBytes = 0;
    for (const auto& v : vlrs) vlrBytes += v.size();

    // Bounds of the leaf centres and the header.
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    octree.forEachCell(octree.depth(), [&](const octree::CellView& c) {
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c.centre[std::size_t(k)]), hi[k] = std::max(hi[k], c.centre[std::size_t(k)]);
        return true;
    });
    if (leaves == 0) lo[0] = lo[1] = lo[2] = hi[0] = hi[1] = hi[2] = 0;
    const auto& origin = octree.box().origin;
    const double offset[3] = {std::floor(origin[0]), std::floor(origin[1]), std::floor(origin[2])};
    const std::size_t recordLength = kFormat6Length + extraLength;
    std::vector<std::uint8_t> header(kHeaderSize, 0);
    putText(header, 0, "LASF", 4);
    put<std::uint16_t>(header, 6, 0x10); // WKT bit: required for formats 6–10
    header[24] = 1;
    header[25] = 4;
    putText(header, 26, "Stylos leaves", 32);
    putText(header, 58, "stylos-cli export", 32);
    put<std::uint16_t>(header, 94, std::uint16_t(kHeaderSize));
    put<std::uint32_t>(header, 96, std::uint32_t(kHeaderSize + vlrBytes));
    put<std::uint32_t>(header, 100, std::uint32_t(vlrs.size()));
    header[104] = 6;
    put<std::uint16_t>(header, 105, std::uint16_t(recordLength));
    for (int k = 0; k < 3; ++k) put<double>(header, 131 + 8 * std::size_t(k), kScale);
    for (int k = 0; k < 3; ++k) put<double>(header, 155 + 8 * std::size_t(k), offset[k]);
    for (int k = 0; k < 3; ++k) {
        put<double>(header, 179 + 16 * std::size_t(k), hi[k]);
        put<double>(header, 187 + 16 * std::size_t(k), lo[k]);
    }
    put<std::uint64_t>(header, 247, leaves);
    put<std::uint64_t>(header, 255, leaves); // all are first returns

    const fs::path partial = output.parent_path() / ("." + output.filename().string() + ".partial");
    auto fail = [&](const std::string& why) -> Error {
        std::error_code ec;
        fs::remove(partial, ec);
        return Error::at(ErrorCode::WriteFailed, output.string(), {}, why);
    };
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) return fail("cannot create the file");
    out.write(reinterpret_cast<const char*>(header.data()), std::streamsize(header.size()));
    for (const auto& v : vlrs) out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size()));

    std::vector<std::uint8_t> chunk;
    constexpr std::size_t kChunk = 65536;
    chunk.reserve(kChunk * recordLength);
    bool cancelled = false, outOfRange = false;
    std::vector<std::uint8_t> record(recordLength, 0);
    octree.forEachCell(octree.depth(), [&](const octree::CellView& c) {
        std::fill(record.begin(), record.end(), 0);
        for (int k = 0; k < 3; ++k) {
            const double steps = std::round((c.centre[std::size_t(k)] - offset[k]) / kScale);
            if (std::abs(steps) > 2147483647.0) outOfRange = true;
            put<std::int32_t>(record, 4 * std::size_t(k), std::int32_t(std::clamp(steps, -2147483648.0, 2147483647.0)));
        }
        record[14] = 0x11; // return 1 of 1
        if (!material.empty() && material[c.index] != 0) record[16] = std::uint8_t(kLasClassOffset + material[c.index]);
        std::size_t at = kFormat6Length;
        for (const LeafColumn& e : extras) {
            if (e.isFloat()) put<float>(record, at, e.floats[c.index]), at += 4;
            else record[at++] = e.labels[c.index];
        }
        chunk.insert(chunk.end(), record.begin(), record.end());
        if (chunk.size() >= kChunk * recordLength) {
            out.write(reinterpret_cast<const char*>(chunk.data()), std::streamsize(chunk.size()));
            chunk.clear();
            if (progress) {
                progress->update(double(c.index + 1) / double(std::max<std::uint64_t>(1, leaves)));
                if (progress->isCancelRequested()) return !(cancelled = true);
            }
        }
        return true;
    });
    if (cancelled) {
        out.close();
        std::error_code ec;
        fs::remove(partial, ec);
        return Error{ErrorCode::Cancelled, "the LAS export of " + file + " was cancelled"};
    }
    if (outOfRange) {
        out.close();
        return fail("a leaf is farther than 214 km from the offset: LAS cannot hold it at 0.1 mm");
    }
    out.write(reinterpret_cast<const char*>(chunk.data()), std::streamsize(chunk.size()));
    out.close();
    if (!out) return fail("writing failed (disk full?)");
    keepModeOf(output, partial);
    std::error_code ec;
    fs::rename(partial, output, ec);
    if (ec) return fail("cannot rename the finished file into place: " + ec.message());
    if (progress) progress->update(1.0);
    return leaves;
}

} // namespace stylos::core::annotation
