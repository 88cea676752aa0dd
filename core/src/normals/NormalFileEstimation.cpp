#include "stylos/core/normals/NormalFileEstimation.h"

#include "NormalJob.h"
#include "ScanGroups.h"
#include "TilePlan.h"
#include "TileSpool.h"
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>
#include <string>
#include <vector>

namespace stylos::core::normals {
namespace {

using detail::TileBox;
using detail::TilePlan;
using detail::TileSpool;

constexpr std::size_t kBatchPoints = 65536;
constexpr std::size_t kSampleSize = 65536;
constexpr double kTileFill = 0.8; ///< plan tiles to this fraction of the budget (the sample's counts vary)
constexpr double kPass1 = 0.10, kPass2 = 0.30; ///< progress at the end of passes 1 and 2 (when tiled)

Error cancelled() { return Error{ErrorCode::Cancelled, "normal estimation: cancelled"}; }

/** splitmix64: a tiny, portable generator (std distributions differ between libraries). */
std::uint64_t nextRandom(std::uint64_t& state)
{
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

std::size_t ownRecordBytes(const io::PointSchema& schema)
{
    return 3 * sizeof(double) + (schema.hasColors ? 3 : 0) + schema.scalarNames.size() * sizeof(double);
}

/** Memory per point held for estimation: its record, its normal (and quality) and the kernel (and, scan by
 *  scan, the copies of runNormalJobPerScan). */
std::size_t heldBytesPerPoint(const io::PointSchema& schema, bool quality, bool perScan)
{
    return ownRecordBytes(schema) + 3 * sizeof(float) + (quality ? sizeof(float) : 0) + normalEstimationBytesPerPoint() +
           (perScan ? detail::PerScanBytesPerPoint : 0);
}

std::size_t haloBytesPerPoint(bool perScan)
{
    return 3 * sizeof(double) + normalEstimationBytesPerPoint() +
           (perScan ? sizeof(double) + detail::PerScanBytesPerPoint : 0);
}

/** Pass 1's findings. */
struct CloudSummary {
    io::PointSchema schema;
    std::uint64_t points = 0;
    std::uint64_t skipped = 0;
    std::array<double, 6> bounds{};
    std::array<double, 3> sum{};
    std::vector<double> sample;
    bool held = true;       ///< the whole cloud is in `all`
    io::PointBatch all;     ///< positions, colours, scalars (input normals dropped)
    /** The scan column (detail::findScanColumn) when NormalFileOptions::perScan: its ids are checked in pass 1. */
    std::optional<std::size_t> scanColumn;
    detail::ScanCensus census;
    std::vector<std::uint16_t> sampleScans; ///< the sample's scan ids while the census is valid
    /** Neighbours are taken scan by scan: a valid scan column with two scans or more. */
    bool perScan() const { return scanColumn && census.valid() && census.scans() > 1; }
};

void appendBatch(io::PointBatch& to, const io::PointBatch& from)
{
    to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
    to.colors.insert(to.colors.end(), from.colors.begin(), from.colors.end());
    to.scalars.resize(from.scalars.size());
    for (std::size_t s = 0; s < from.scalars.size(); ++s)
        to.scalars[s].insert(to.scalars[s].end(), from.scalars[s].begin(), from.scalars[s].end());
}

Result<CloudSummary> summarise(const std::filesystem::path& input, const NormalFileOptions& options,
                               ProgressSink* progress, double progressEnd)
{
    auto opened = io::openPointReader(input, options.read);
    if (!opened) return opened.error();
    io::PointReader& reader = **opened;
    CloudSummary cloud;
    cloud.schema = reader.header().schema;
    if (options.perScan) cloud.scanColumn = detail::findScanColumn(cloud.schema.scalarNames);
    // The copies of the scan-by-scan estimation are charged once a second scan is met.
    std::size_t heldBytes = heldBytesPerPoint(cloud.schema, options.writeQuality, false);
    cloud.bounds = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                    std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
    std::uint64_t random = 0x5354594c4f53ULL; // fixed seed: the same file gives the same tiles
    const std::uint64_t declared = reader.header().declaredPoints.value_or(0);
    if (declared > 0 && declared * heldBytes <= options.memoryBudget) { // no doubling past the budget
        cloud.all.positions.reserve(3 * declared);
        if (cloud.schema.hasColors) cloud.all.colors.reserve(3 * declared);
        cloud.all.scalars.resize(cloud.schema.scalarNames.size());
        for (auto& column : cloud.all.scalars) column.reserve(declared);
    }
    io::PointBatch batch;
    for (;;) {
        if (progress && progress->isCancelRequested()) return cancelled();
        auto got = reader.read(batch, kBatchPoints);
        if (!got) return got.error();
        if (*got == 0) break;
        if (cloud.scanColumn) {
            for (double id : batch.scalars[*cloud.scanColumn])
                if (!cloud.census.add(id)) break;
            heldBytes = heldBytesPerPoint(cloud.schema, options.writeQuality, cloud.perScan());
        }
        const bool scanned = cloud.scanColumn && cloud.census.valid();
        for (std::size_t i = 0; i < batch.size(); ++i, ++cloud.points) {
            const double* p = &batch.positions[3 * i];
            for (int d = 0; d < 3; ++d) {
                cloud.bounds[d] = std::min(cloud.bounds[d], p[d]);
                cloud.bounds[3 + d] = std::max(cloud.bounds[3 + d], p[d]);
                cloud.sum[d] += p[d];
            }
            std::size_t slot = kSampleSize;
            if (cloud.points < kSampleSize) {
                cloud.sample.insert(cloud.sample.end(), p, p + 3);
                if (scanned) cloud.sampleScans.push_back(std::uint16_t(batch.scalars[*cloud.scanColumn][i]));
            } else if ((slot = nextRandom(random) % (cloud.points + 1)) < kSampleSize) {
                std::copy(p, p + 3, cloud.sample.begin() + std::ptrdiff_t(3 * slot));
                if (scanned) cloud.sampleScans[slot] = std::uint16_t(batch.scalars[*cloud.scanColumn][i]);
            }
        }
        if (cloud.held && (cloud.points * heldBytes <= options.memoryBudget)) {
            appendBatch(cloud.all, batch);
        } else if (cloud.held) {
            cloud.held = false;
            cloud.all = io::PointBatch{};
        }
        if (progress && reader.fileBytes() > 0)
            progress->update(progressEnd * double(reader.bytesConsumed()) / double(reader.fileBytes()));
    }
    cloud.skipped = reader.pointsSkipped();
    if (cloud.points == 0) cloud.bounds = {};
    return cloud;
}

/** Writes @p count points (positions, normals, quality, colours, scalars) to @p writer in batches. */
Status writePoints(io::PlyWriter& writer, const io::PointSchema& outSchema, std::size_t count,
                   const std::vector<double>& positions, const std::vector<float>& normals,
                   const std::vector<float>& quality, const std::vector<std::uint8_t>& colors,
                   const std::vector<std::vector<double>>& scalars)
{
    io::PointBatch batch;
    for (std::size_t begin = 0; begin < count; begin += kBatchPoints) {
        const std::size_t end = std::min(count, begin + kBatchPoints);
        batch.reset(outSchema, end - begin);
        batch.positions.assign(positions.begin() + std::ptrdiff_t(3 * begin), positions.begin() + std::ptrdiff_t(3 * end));
        batch.normals.assign(normals.begin() + std::ptrdiff_t(3 * begin), normals.begin() + std::ptrdiff_t(3 * end));
        if (outSchema.hasColors)
            batch.colors.assign(colors.begin() + std::ptrdiff_t(3 * begin), colors.begin() + std::ptrdiff_t(3 * end));
        for (std::size_t s = 0; s < scalars.size(); ++s)
            batch.scalars[s].assign(scalars[s].begin() + std::ptrdiff_t(begin), scalars[s].begin() + std::ptrdiff_t(end));
        if (!quality.empty())
            batch.scalars.back().assign(quality.begin() + std::ptrdiff_t(begin), quality.begin() + std::ptrdiff_t(end));
        if (Status status = writer.write(batch); !status) return status;
    }
    return {};
}

void addReport(NormalReport& total, const NormalReport& part)
{
    total.points += part.points;
    total.degenerate += part.degenerate;
    total.truncated += part.truncated;
}

/** The smallest tiling whose densest tile (with halo, by the sample) fits the budget. */
Result<TilePlan> planTiles(const CloudSummary& cloud, const NormalFileOptions& options, double margin)
{
    const double scale = double(cloud.points) / double(cloud.sample.size() / 3);
    const double ownBytes = double(heldBytesPerPoint(cloud.schema, options.writeQuality, cloud.perScan()));
    const double haloBytes = double(haloBytesPerPoint(cloud.perScan()));
    const double budget = kTileFill * double(options.memoryBudget);
    unsigned levels = 1;
    while (levels < 20 && double(cloud.points) * ownBytes > budget * double(1u << levels)) ++levels;
    double needed = 0;
    int stalled = 0;
    std::vector<std::uint32_t> halo;
    for (; levels <= 20; ++levels) {
        TilePlan plan(cloud.sample, cloud.bounds, levels, margin);
        std::vector<double> bytes(plan.size(), 0.0);
        for (std::size_t i = 0; i < cloud.sample.size() / 3; ++i) {
            const double* p = &cloud.sample[3 * i];
            bytes[plan.ownTile(p)] += ownBytes;
            plan.haloTiles(p, halo);
            for (std::uint32_t t : halo) bytes[t] += haloBytes;
        }
        const double densest = *std::max_element(bytes.begin(), bytes.end()) * scale;
        if (densest <= budget) return plan;
        // Once halos dominate, splitting no longer helps: give up after two levels without 5 % gain.
        stalled = (needed > 0 && densest >= 0.95 * needed) ? stalled + 1 : 0;
        if (stalled == 2) break;
        needed = needed > 0 ? std::min(needed, densest) : densest;
    }
    return Error{ErrorCode::OutOfBudget,
                 "normal estimation: a memory budget of " + std::to_string(options.memoryBudget >> 10) +
                     " KiB is too small for this cloud: its densest tile with its halo needs about " +
                     std::to_string(static_cast<std::uint64_t>(needed / kTileFill) >> 10) + " KiB"};
}

Result<NormalFileReport> runTiled(const std::filesystem::path& output, const CloudSummary& cloud,
                                  const std::filesystem::path& input, const NormalFileOptions& options,
                                  const detail::NormalJob& frame, io::PlyWriter& writer,
                                  const io::PointSchema& outSchema, ProgressSink* progress)
{
    NormalFileReport report;
    // Scan by scan, a neighbourhood reaches as far as its own scan's density asks.
    report.margin = cloud.perScan()
        ? detail::perScanHaloMargin(cloud.sample, cloud.sampleScans, cloud.census, cloud.points, options.normals.neighbours)
        : detail::estimateHaloMargin(cloud.sample, cloud.points, options.normals.neighbours);
    auto planned = planTiles(cloud, options, report.margin);
    if (!planned) return planned.error();
    const TilePlan& plan = *planned;
    report.tiles = plan.size();
    const std::size_t recordBytes = ownRecordBytes(cloud.schema);
    const std::size_t bufferBytes = std::clamp<std::size_t>(options.memoryBudget / (4 * plan.size()), 4096, 1u << 20);
    auto made = TileSpool::create(options.temporaryDirectory.empty() ? output.parent_path() : options.temporaryDirectory,
                                  output.filename().string(), plan.size(), recordBytes, cloud.perScan() ? 4 : 3,
                                  bufferBytes);
    if (!made) return made.error();
    TileSpool& spool = **made;

    // Pass 2: each point to its tile, its position to the halos it falls in.
    auto opened = io::openPointReader(input, options.read);
    if (!opened) return opened.error();
    io::PointReader& reader = **opened;
    io::PointBatch batch;
    std::vector<unsigned char> record(recordBytes);
    std::vector<std::uint32_t> halo;
    double haloRecord[4];
    for (;;) {
        if (progress && progress->isCancelRequested()) return cancelled();
        auto got = reader.read(batch, kBatchPoints);
        if (!got) return got.error();
        if (*got == 0) break;
        for (std::size_t i = 0; i < batch.size(); ++i) {
            const double* p = &batch.positions[3 * i];
            unsigned char* out = record.data();
            std::memcpy(out, p, 3 * sizeof(double));
            out += 3 * sizeof(double);
            if (cloud.schema.hasColors) {
                std::memcpy(out, &batch.colors[3 * i], 3);
                out += 3;
            }
            for (const auto& column : batch.scalars) {
                std::memcpy(out, &column[i], sizeof(double));
                out += sizeof(double);
            }
            if (Status status = spool.appendOwn(plan.ownTile(p), record.data()); !status) return status.error();
            plan.haloTiles(p, halo);
            std::copy_n(p, 3, haloRecord);
            if (cloud.perScan()) haloRecord[3] = batch.scalars[*cloud.scanColumn][i];
            for (std::uint32_t t : halo)
                if (Status status = spool.appendHalo(t, haloRecord); !status) return status.error();
        }
        if (progress && reader.fileBytes() > 0)
            progress->update(kPass1 + (kPass2 - kPass1) * double(reader.bytesConsumed()) / double(reader.fileBytes()));
    }
    if (Status status = spool.flush(); !status) return status.error();

    // Pass 3: one tile at a time.
    std::vector<double> positions;
    std::vector<std::uint8_t> colors;
    std::vector<std::vector<double>> scalars(cloud.schema.scalarNames.size());
    std::vector<float> normals, quality;
    std::vector<double> scanIds;
    std::uint64_t done = 0;
    for (std::uint32_t t = 0; t < plan.size(); ++t) {
        positions.clear();
        colors.clear();
        for (auto& column : scalars) column.clear();
        Status status = spool.read(t, TileSpool::Part::Own, [&](const unsigned char* in, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i, in += recordBytes) {
                const unsigned char* field = in;
                double xyz[3];
                std::memcpy(xyz, field, sizeof xyz);
                positions.insert(positions.end(), xyz, xyz + 3);
                field += sizeof xyz;
                if (cloud.schema.hasColors) {
                    colors.insert(colors.end(), field, field + 3);
                    field += 3;
                }
                for (auto& column : scalars) {
                    double value;
                    std::memcpy(&value, field, sizeof value);
                    column.push_back(value);
                    field += sizeof value;
                }
            }
        });
        if (!status) return status.error();
        const std::size_t own = positions.size() / 3;
        if (cloud.perScan()) scanIds.assign(scalars[*cloud.scanColumn].begin(), scalars[*cloud.scanColumn].end());
        status = spool.read(t, TileSpool::Part::Halo, [&](const unsigned char* in, std::size_t count) {
            const std::size_t at = positions.size();
            positions.resize(at + 3 * count);
            if (!cloud.perScan()) {
                std::memcpy(&positions[at], in, 3 * count * sizeof(double));
                return;
            }
            for (std::size_t i = 0; i < count; ++i, in += 4 * sizeof(double)) {
                double values[4];
                std::memcpy(values, in, sizeof values);
                std::copy_n(values, 3, &positions[at + 3 * i]);
                scanIds.push_back(values[3]);
            }
        });
        if (!status) return status.error();
        report.haloPoints += positions.size() / 3 - own;
        report.peakTilePoints = std::max(report.peakTilePoints, positions.size() / 3);

        normals.assign(3 * own, 0.0f);
        quality.assign(options.writeQuality ? own : 0, 0.0f);
        detail::NormalJob job = frame;
        job.positions = positions;
        job.queryCount = own;
        job.normals = normals;
        job.quality = quality;
        job.cloudPoints = cloud.points;
        const TileBox& box = plan.box(t);
        job.validBox = std::array<double, 6>{box.lo[0] - plan.margin(), box.lo[1] - plan.margin(),
                                             box.lo[2] - plan.margin(), box.hi[0] + plan.margin(),
                                             box.hi[1] + plan.margin(), box.hi[2] + plan.margin()};
        const double share = 1.0 - kPass2;
        SubProgress tileProgress(progress, kPass2 + share * double(done) / double(cloud.points),
                                    kPass2 + share * double(done + own) / double(cloud.points));
        auto estimated = cloud.perScan() ? detail::runNormalJobPerScan(job, scanIds, cloud.census, options.normals, &tileProgress)
                                         : detail::runNormalJob(job, options.normals, &tileProgress);
        if (!estimated) return estimated.error();
        addReport(report.normals, *estimated);
        if (Status written = writePoints(writer, outSchema, own, positions, normals, quality, colors, scalars); !written)
            return written.error();
        spool.discard(t);
        done += own;
    }
    return report;
}

} // namespace

Result<NormalFileReport> estimateNormalsForFile(const std::filesystem::path& input, const std::filesystem::path& output,
                                                const NormalFileOptions& options, ProgressSink* progress)
{
    if (auto error = detail::checkNormalOptions(options.normals)) return *error;
    if (options.memoryBudget < (64u << 10))
        return Error{ErrorCode::InvalidArgument, "normal estimation: the memory budget must be at least 64 KiB"};
    try {
        auto summarised = summarise(input, options, progress, kPass1);
        if (!summarised) return summarised.error();
        CloudSummary& cloud = *summarised;

        io::PointSchema outSchema{true, cloud.schema.hasColors, cloud.schema.scalarNames};
        io::PlyWriterOptions writerOptions;
        writerOptions.scalarTypes.assign(outSchema.scalarNames.size(), io::PlyScalarType::Float64);
        if (options.writeQuality) {
            std::string name = "surface_variation";
            while (std::find(outSchema.scalarNames.begin(), outSchema.scalarNames.end(), name) != outSchema.scalarNames.end())
                name += "_estimated";
            outSchema.scalarNames.push_back(name);
            writerOptions.scalarTypes.push_back(io::PlyScalarType::Float32);
        }
        writerOptions.comments.push_back("normals estimated by Stylos: PCA of the " +
                                         std::to_string(options.normals.neighbours) + " nearest points" +
                                         (cloud.perScan() ? " of the same " + cloud.schema.scalarNames[*cloud.scanColumn]
                                                          : std::string()));
        auto created = io::PlyWriter::create(output, outSchema, writerOptions);
        if (!created) return created.error();
        io::PlyWriter& writer = *created;

        // The search frame and orientation centre of the whole cloud, shared by all tiles.
        detail::NormalJob frame;
        for (int d = 0; d < 3; ++d) {
            frame.origin[d] = cloud.points ? 0.5 * (cloud.bounds[d] + cloud.bounds[3 + d]) : 0.0;
            frame.centre[d] = cloud.points ? cloud.sum[d] / double(cloud.points) : 0.0;
        }
        if (options.normals.centre) frame.centre = *options.normals.centre;

        NormalFileReport report;
        if (cloud.held) {
            const std::size_t n = cloud.points;
            std::vector<float> normals(3 * n), quality(options.writeQuality ? n : 0);
            detail::NormalJob job = frame;
            job.positions = cloud.all.positions;
            job.queryCount = n;
            job.normals = normals;
            job.quality = quality;
            SubProgress estimateProgress(progress, kPass1, 0.95);
            auto estimated = cloud.perScan()
                ? detail::runNormalJobPerScan(job, cloud.all.scalars[*cloud.scanColumn], cloud.census, options.normals,
                                              &estimateProgress)
                : detail::runNormalJob(job, options.normals, &estimateProgress);
            if (!estimated) return estimated.error();
            report.normals = *estimated;
            report.peakTilePoints = n;
            if (Status written = writePoints(writer, outSchema, n, cloud.all.positions, normals, quality,
                                             cloud.all.colors, cloud.all.scalars);
                !written)
                return written.error();
        } else {
            auto tiled = runTiled(output, cloud, input, options, frame, writer, outSchema, progress);
            if (!tiled) return tiled.error();
            report = *tiled;
        }
        report.normals.centre = frame.centre;
        report.skippedPoints = cloud.skipped;
        if (cloud.perScan()) {
            report.scanColumn = cloud.schema.scalarNames[*cloud.scanColumn];
            report.scans = cloud.census.scans();
        }
        if (progress && progress->isCancelRequested()) return cancelled();
        if (Status finished = writer.finish(); !finished) return finished.error();
        if (progress) progress->update(1.0);
        return report;
    } catch (const std::bad_alloc&) {
        return Error{ErrorCode::OutOfBudget, "normal estimation: out of memory reading " + input.string()};
    }
}

} // namespace stylos::core::normals
