#include "stylos/core/cloud/LoadPointCloud.h"

#include "stylos/core/octree/PackedOctree.h"

#include <array>
#include <cmath>
#include <fstream>
#include <string>

namespace stylos::core::cloud {

namespace {

constexpr std::size_t kBatchPoints = 1 << 16;

std::uint64_t bytesFor(std::uint64_t points, bool normals) { return points * (normals ? 24u : 12u); }

Error overBudget(const std::filesystem::path& path, std::uint64_t points, bool normals, std::uint64_t limit)
{
    return Error::at(ErrorCode::OutOfBudget, path.string(), "",
                     "loading " + std::to_string(points) + " points needs " +
                         std::to_string(bytesFor(points, normals) >> 20) + " MiB, over the limit of " +
                         std::to_string(limit >> 20) + " MiB");
}

Result<PointCloud> loadOctree(const std::filesystem::path& path, const CloudLoadOptions& options,
                              ProgressSink* progress)
{
    auto octree = octree::PackedOctree::open(path);
    if (!octree) return octree.error();
    const int level = options.octreeLevel < 0 ? octree->depth() : options.octreeLevel;
    if (level > octree->depth())
        return Error::at(ErrorCode::InvalidArgument, path.string(), "",
                         "level " + std::to_string(level) + " is deeper than the octree (depth " +
                             std::to_string(octree->depth()) + ")");
    const std::uint64_t cells = octree->cellCount(level);
    if (options.maxBytes != 0 && bytesFor(cells, options.keepNormals) > options.maxBytes)
        return overBudget(path, cells, options.keepNormals, options.maxBytes);
    PointCloud cloud;
    cloud.source = path.string();
    const auto& box = octree->box();
    cloud.origin = Eigen::Vector3d(box.origin[0], box.origin[1], box.origin[2]);
    cloud.spacing = box.cellSize(level);
    cloud.positions.reserve(3 * cells);
    if (options.keepNormals) cloud.normals.reserve(3 * cells);
    bool cancelled = false;
    std::uint64_t seen = 0;
    octree->forEachCell(level, [&](const octree::CellView& cell) {
        cloud.addWorld(Eigen::Vector3d(cell.centre[0], cell.centre[1], cell.centre[2]));
        if (options.keepNormals) cloud.normals.insert(cloud.normals.end(), cell.normal.begin(), cell.normal.end());
        if (++seen % 65536 == 0 && progress) {
            progress->update(double(seen) / double(cells));
            if (progress->isCancelRequested()) {
                cancelled = true;
                return false;
            }
        }
        return true;
    });
    if (cancelled) return Error{ErrorCode::Cancelled, path.string() + ": cancelled"};
    return cloud;
}

Result<PointCloud> loadPoints(const std::filesystem::path& path, const CloudLoadOptions& options,
                              ProgressSink* progress)
{
    auto reader = io::openPointReader(path, options.read);
    if (!reader) return reader.error();
    io::PointReader& in = **reader;
    const bool normals = options.keepNormals && in.header().schema.hasNormals;
    PointCloud cloud;
    cloud.source = path.string();
    if (const auto declared = in.header().declaredPoints) {
        if (options.maxBytes != 0 && bytesFor(*declared, normals) > options.maxBytes)
            return overBudget(path, *declared, normals, options.maxBytes);
        cloud.positions.reserve(3 * *declared);
        if (normals) cloud.normals.reserve(3 * *declared);
    }
    io::PointBatch batch;
    bool originSet = false;
    for (;;) {
        auto n = in.read(batch, kBatchPoints);
        if (!n) return n.error();
        if (*n == 0) break;
        if (!originSet) {
            for (int a = 0; a < 3; ++a) cloud.origin[a] = std::round(batch.positions[std::size_t(a)]);
            originSet = true;
        }
        for (std::size_t i = 0; i < *n; ++i)
            cloud.addWorld({batch.positions[3 * i], batch.positions[3 * i + 1], batch.positions[3 * i + 2]});
        if (normals) cloud.normals.insert(cloud.normals.end(), batch.normals.begin(), batch.normals.end());
        if (options.maxBytes != 0 && bytesFor(cloud.size(), normals) > options.maxBytes)
            return overBudget(path, cloud.size(), normals, options.maxBytes);
        if (progress) {
            progress->update(in.fileBytes() ? double(in.bytesConsumed()) / double(in.fileBytes()) : 0.0);
            if (progress->isCancelRequested()) return Error{ErrorCode::Cancelled, path.string() + ": cancelled"};
        }
    }
    return cloud;
}

} // namespace

bool isPoctPath(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::array<std::uint8_t, 8> bytes{};
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()))) return false;
    return octree::isPoctSignature(bytes);
}

Result<PointCloud> loadPointCloud(const std::filesystem::path& path, const CloudLoadOptions& options,
                                  ProgressSink* progress)
{
    auto cloud = isPoctPath(path) ? loadOctree(path, options, progress) : loadPoints(path, options, progress);
    if (cloud && cloud->empty()) return Error::at(ErrorCode::Empty, path.string(), "", "holds no point");
    if (cloud && progress) progress->update(1.0);
    return cloud;
}

} // namespace stylos::core::cloud
