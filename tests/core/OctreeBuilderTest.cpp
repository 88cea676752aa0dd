// Both octree builders against each other and against the brute-force reference (ReferenceOctree.h), on
// generated drums (ordered and shuffled), on small real scans, and on every error path: limits,
// cancel, missing normals, bad arguments, an input that changes between passes.
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/normals/NormalFileEstimation.h"
#include "stylos/core/octree/ConstructionOctree.h"
#include "stylos/core/octree/LeafSpacing.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"

#include "ReferenceOctree.h"
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace stylos::core;
using namespace stylos::core::octree;
using stylos::test::ReferenceOctree;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

constexpr BuildMethod methods[] = {BuildMethod::Optimal, BuildMethod::Streaming};

/** A point source in memory (a PointReader over a batch), for hand-made inputs. */
class MemoryReader final : public io::PointReader {
public:
    MemoryReader(const io::PointBatch& points, io::PointSchema schema) : PointReader("memory-points", 0), m_points(points)
    {
        m_header.format = "memory";
        m_header.declaredPoints = points.size();
        m_header.schema = std::move(schema);
    }
    Result<std::size_t> read(io::PointBatch& batch, std::size_t maxPoints) override
    {
        const std::size_t n = std::min(maxPoints, m_points.size() - m_next);
        batch.reset(m_header.schema, n);
        auto take = [&](const auto& from, auto& to, std::size_t width) {
            if (!from.empty()) to.assign(from.begin() + std::ptrdiff_t(width * m_next), from.begin() + std::ptrdiff_t(width * (m_next + n)));
        };
        take(m_points.positions, batch.positions, 3);
        if (m_header.schema.hasNormals) take(m_points.normals, batch.normals, 3);
        if (m_header.schema.hasColors) take(m_points.colors, batch.colors, 3);
        m_next += n;
        m_pointsRead += n;
        return n;
    }
    std::uint64_t bytesConsumed() const override { return 0; }

private:
    const io::PointBatch& m_points;
    std::size_t m_next = 0;
};

PointSourceFactory memorySource(const io::PointBatch& points, bool normals = true, bool colours = false)
{
    return [&points, normals, colours]() -> Result<std::unique_ptr<io::PointReader>> {
        io::PointSchema schema;
        schema.hasNormals = normals;
        schema.hasColors = colours;
        return std::unique_ptr<io::PointReader>(std::make_unique<MemoryReader>(points, schema));
    };
}

PointSourceFactory fileSource(const fs::path& path)
{
    return [path] { return io::openPointReader(path); };
}

io::PointBatch readAll(const fs::path& path)
{
    auto reader = io::openPointReader(path);
    EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error().message);
    auto all = stylos::test::readAllPoints(**reader, 65536);
    EXPECT_TRUE(all.ok());
    return all.ok() ? std::move(all.value()) : io::PointBatch{};
}

BuildOptions optionsFor(BuildMethod method, int depth, unsigned threads = 2)
{
    BuildOptions o;
    o.method = method;
    o.depth = depth;
    o.threads = threads;
    return o;
}

std::unique_ptr<ConstructionOctree> buildOk(const PointSourceFactory& open, const BuildOptions& o,
                                            BuildReport* report = nullptr)
{
    auto tree = buildConstructionOctree(open, o, nullptr, report);
    EXPECT_TRUE(tree.ok()) << (tree.ok() ? "" : tree.error().message);
    return tree.ok() ? std::move(tree.value()) : nullptr;
}

/** Every level of @p a equals @p b's: description, masks, normals, colours. */
void expectSameOctree(const OctreeLevels& a, const OctreeLevels& b, const std::string& what)
{
    const OctreeDescription& da = a.description();
    const OctreeDescription& db = b.description();
    EXPECT_EQ(da.box, db.box) << what;
    EXPECT_EQ(da.depth, db.depth) << what;
    EXPECT_EQ(da.normalCode, db.normalCode) << what;
    EXPECT_EQ(da.points, db.points) << what;
    EXPECT_EQ(da.cellsPerLevel, db.cellsPerLevel) << what;
    EXPECT_EQ(da.hasColour, db.hasColour) << what;
    ASSERT_EQ(da, db) << what;
    for (int l = 0; l <= a.description().depth; ++l) {
        std::vector<std::uint8_t> ma, mb, ca, cb;
        std::vector<std::uint16_t> na, nb;
        a.visitLevel(l, [&](const CellBlock& k) {
            ma.insert(ma.end(), k.masks.begin(), k.masks.end());
            na.insert(na.end(), k.normals.begin(), k.normals.end());
            ca.insert(ca.end(), k.colours.begin(), k.colours.end());
        });
        b.visitLevel(l, [&](const CellBlock& k) {
            mb.insert(mb.end(), k.masks.begin(), k.masks.end());
            nb.insert(nb.end(), k.normals.begin(), k.normals.end());
            cb.insert(cb.end(), k.colours.begin(), k.colours.end());
        });
        ASSERT_EQ(ma, mb) << what << ": masks of level " << l;
        ASSERT_EQ(na, nb) << what << ": normals of level " << l;
        ASSERT_EQ(ca, cb) << what << ": colours of level " << l;
    }
}

/** Both builders on @p source equal the reference of @p points (input order) at @p depth. */
void expectBuildersMatchReference(const PointSourceFactory& source, const io::PointBatch& points, int depth,
                                  const std::string& what, NormalCodeKind kind = NormalCodeKind::Octahedral16)
{
    const ReferenceOctree reference = ReferenceOctree::fromBatch(points, depth, kind);
    for (BuildMethod m : methods) {
        BuildOptions o = optionsFor(m, depth);
        o.normalCode = kind;
        auto tree = buildOk(source, o);
        ASSERT_TRUE(tree);
        expectSameOctree(*tree, reference, what + " / " + buildMethodName(m));
    }
}

io::PointBatch shuffled(const io::PointBatch& points, std::uint64_t seed)
{
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::mt19937_64 random(seed);
    std::shuffle(order.begin(), order.end(), random);
    io::PointBatch out;
    for (std::size_t i : order) {
        out.positions.insert(out.positions.end(), &points.positions[3 * i], &points.positions[3 * i] + 3);
        if (!points.normals.empty()) out.normals.insert(out.normals.end(), &points.normals[3 * i], &points.normals[3 * i] + 3);
        if (!points.colors.empty()) out.colors.insert(out.colors.end(), &points.colors[3 * i], &points.colors[3 * i] + 3);
    }
    return out;
}

void writePly(const fs::path& path, const io::PointBatch& points, bool normals, bool colours = false)
{
    io::PointSchema schema;
    schema.hasNormals = normals;
    schema.hasColors = colours;
    auto writer = io::PlyWriter::create(path, schema);
    ASSERT_TRUE(writer.ok());
    io::PointBatch shaped = points;
    if (!normals) shaped.normals.clear();
    if (!colours) shaped.colors.clear();
    shaped.scalars.clear();
    if (shaped.size() > 0) {
        ASSERT_TRUE(writer->write(shaped).ok());
    }
    ASSERT_TRUE(writer->finish().ok());
}

/** Files in @p dir (names). */
std::vector<std::string> listing(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/** Small hand-made cloud with normals (and colours). */
io::PointBatch smallCloud(std::size_t n = 500, std::uint64_t seed = 1)
{
    io::PointBatch b;
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = u(random), y = u(random), z = 0.3 * u(random);
        b.positions.insert(b.positions.end(), {10 + x, -5 + y, 2 + z});
        b.normals.insert(b.normals.end(), {float(x), float(y), 1.0f});
        b.colors.insert(b.colors.end(), {std::uint8_t(i % 256), std::uint8_t((7 * i) % 256), std::uint8_t(200)});
    }
    return b;
}

class CancelAfter final : public ProgressSink {
public:
    explicit CancelAfter(int updates) : m_left(updates) {}
    void update(double fraction) override
    {
        EXPECT_GE(fraction, m_last);
        m_last = fraction;
        --m_left;
    }
    bool isCancelRequested() const override { return m_left <= 0; }
    double last() const { return m_last; }

private:
    int m_left;
    double m_last = 0;
};

} // namespace

/** A coarse generated drum with normals (8 mm: ~66,000 points) in @p dir, and its points. */
io::PointBatch generatedDrum(const TempDir& dir, const std::string& name)
{
    auto o = stylos::test::coarse(0.008, 3);
    o.writeNormals = true;
    stylos::test::generate(synth::SyntheticKind::Drum, o, dir / name);
    io::PointBatch points = readAll(dir / name);
    EXPECT_GT(points.size(), 50000u);
    return points;
}

TEST(OctreeBuilder, GeneratedDrumInScanOrderMatchesTheReference)
{
    TempDir dir;
    const io::PointBatch ordered = generatedDrum(dir, "drum.ply");
    for (int depth : {7, 11}) expectBuildersMatchReference(fileSource(dir / "drum.ply"), ordered, depth, "ordered drum");
}

TEST(OctreeBuilder, ShuffledGeneratedDrumMatchesTheReference)
{
    TempDir dir;
    const io::PointBatch mixed = shuffled(generatedDrum(dir, "drum.ply"), 17);
    writePly(dir / "shuffled.ply", mixed, true);
    for (int depth : {7, 11}) expectBuildersMatchReference(fileSource(dir / "shuffled.ply"), mixed, depth, "shuffled drum");
}

TEST(OctreeBuilder, BothBuildersWriteByteIdenticalFiles)
{
    TempDir dir;
    auto o = stylos::test::coarse(0.008, 5);
    o.writeNormals = true;
    stylos::test::generate(synth::SyntheticKind::Drum, o, dir / "drum.ply");
    writePly(dir / "shuffled.ply", shuffled(readAll(dir / "drum.ply"), 3), true);
    for (const char* input : {"drum.ply", "shuffled.ply"}) {
        std::vector<std::vector<char>> files;
        for (BuildMethod m : methods) {
            const fs::path out = dir / (std::string(input) + "." + buildMethodName(m) + ".poct");
            auto report = buildOctree(fileSource(dir / input), out, optionsFor(m, 9));
            ASSERT_TRUE(report.ok()) << report.error().message;
            EXPECT_EQ(report->fileBytes, fs::file_size(out));
            files.push_back(stylos::test::readBytes(out));
        }
        EXPECT_EQ(files[0], files[1]) << input;
    }
}

TEST(OctreeBuilder, WrittenFileHoldsTheReferenceAndItsSpacingWhateverTheThreads)
{
    // buildOctree pulls the tree while writing it, subtree by subtree on several threads, and computes the
    // spacing layer beside it: the file must hold exactly the reference's cells and the reference's spacing.
    TempDir dir;
    const io::PointBatch cloud = smallCloud(40000, 23);
    const ReferenceOctree reference = ReferenceOctree::fromBatch(cloud, 9, NormalCodeKind::Octahedral16);
    const AttributeLayer spacing = leafSpacingLayer(reference);
    ASSERT_EQ(spacing.bytes.size(), 4 * reference.description().cellsPerLevel.back());
    ASSERT_GT(reference.description().cellsPerLevel[4], 100u);  // many subtrees for the threads to share
    for (BuildMethod m : methods)
        for (unsigned threads : {1u, 2u, 3u}) {
            const std::string what = std::string(buildMethodName(m)) + ", " + std::to_string(threads) + " threads";
            const fs::path out = dir / ("t" + std::to_string(threads) + buildMethodName(m) + ".poct");
            auto report = buildOctree(memorySource(cloud, true, true), out, optionsFor(m, 9, threads));
            ASSERT_TRUE(report.ok()) << report.error().message;
            auto packed = PackedOctree::open(out);
            ASSERT_TRUE(packed.ok()) << packed.error().message;
            expectSameOctree(packed->levels(), reference, what);
            const auto layer = packed->attribute(LeafSpacingLayerName);
            ASSERT_TRUE(layer) << what;
            ASSERT_EQ(layer->bytes.size(), spacing.bytes.size()) << what;
            EXPECT_TRUE(std::equal(layer->bytes.begin(), layer->bytes.end(), spacing.bytes.begin())) << what;
        }
}

TEST(OctreeBuilder, ColourKindThreadsAndGivenBox)
{
    const io::PointBatch cloud = smallCloud(3000, 9);
    // Colour, both normal codes.
    for (NormalCodeKind kind : {NormalCodeKind::Octahedral16, NormalCodeKind::Paper15})
        expectBuildersMatchReference(memorySource(cloud, true, true), cloud, 8, "colour", kind);
    // Thread counts do not change the result.
    auto one = buildOk(memorySource(cloud, true, true), optionsFor(BuildMethod::Optimal, 8, 1));
    auto three = buildOk(memorySource(cloud, true, true), optionsFor(BuildMethod::Optimal, 8, 3));
    ASSERT_TRUE(one && three);
    expectSameOctree(*one, *three, "threads");
    // A given box skips the bounds pass; points outside it are clamped into the border cells.
    const RootBox box{{9.5, -5.5, 1.5}, 1.0};
    const ReferenceOctree reference = ReferenceOctree::fromBatch(cloud, 6, NormalCodeKind::Octahedral16, box);
    for (BuildMethod m : methods) {
        BuildOptions opt = optionsFor(m, 6);
        opt.box = box;
        BuildReport report;
        auto tree = buildOk(memorySource(cloud, true, true), opt, &report);
        ASSERT_TRUE(tree);
        expectSameOctree(*tree, reference, std::string("box / ") + buildMethodName(m));
        EXPECT_EQ(report.passes, m == BuildMethod::Optimal ? 7u : 1u);
    }
}

TEST(OctreeBuilder, ReportDescribesTheBuild)
{
    TempDir dir;
    const io::PointBatch cloud = smallCloud(2000, 4);
    for (BuildMethod m : methods) {
        const fs::path out = dir / (std::string(buildMethodName(m)) + ".poct");
        CancelAfter progress(1 << 30);  // never cancels; checks monotony
        auto report = buildOctree(memorySource(cloud), out, optionsFor(m, 7), &progress);
        ASSERT_TRUE(report.ok()) << report.error().message;
        EXPECT_EQ(progress.last(), 1.0);
        const ReferenceOctree reference = ReferenceOctree::fromBatch(cloud, 7);
        EXPECT_EQ(report->points, 2000u);
        EXPECT_EQ(report->cellsPerLevel, reference.description().cellsPerLevel);
        EXPECT_EQ(report->cells, std::accumulate(report->cellsPerLevel.begin(), report->cellsPerLevel.end(), std::uint64_t(0)));
        EXPECT_EQ(report->leaves, report->cellsPerLevel.back());
        EXPECT_EQ(report->depth, 7);
        EXPECT_EQ(report->method, m);
        EXPECT_EQ(report->passes, m == BuildMethod::Optimal ? 9u : 2u);  // bounds + 7 marking + leaves; bounds + insert
        EXPECT_GE(report->constructionBytes, 7 * report->cells);
        EXPECT_LE(report->constructionBytes, 7 * report->cells + 2 * 14336 + 1024);
        EXPECT_EQ(report->fileBytes, fs::file_size(out));
        EXPECT_GT(report->seconds, 0.0);
        EXPECT_FALSE(report->normalsEstimated);
        EXPECT_EQ(report->skippedPoints, 0u);
    }
}

/** A real scan (normals estimated first when it has none), in file order and shuffled, at @p depth. */
void expectRealScanMatches(const fs::path& scan, int depth, bool alsoShuffled = true)
{
    TempDir dir;
    fs::path source = scan;
    auto reader = io::openPointReader(scan);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    if (!(*reader)->header().schema.hasNormals) {
        source = dir / "with-normals.ply";
        auto estimated = normals::estimateNormalsForFile(scan, source);
        ASSERT_TRUE(estimated.ok()) << estimated.error().message;
    }
    const io::PointBatch points = readAll(source);
    expectBuildersMatchReference(fileSource(source), points, depth, scan.filename().string());
    if (!alsoShuffled) return;
    const io::PointBatch mixed = shuffled(points, 2);
    writePly(dir / "shuffled.ply", mixed, true, !mixed.colors.empty());
    expectBuildersMatchReference(fileSource(dir / "shuffled.ply"), mixed, depth, scan.filename().string() + " shuffled");
}

TEST(OctreeBuilder, RealScanKittenMatchesTheReference)
{
    SKIP_WITHOUT_SHARED_DATA();
    expectRealScanMatches(stylos::test::sharedData() / "formats" / "cgal_kitten.xyz", 8);
}

TEST(OctreeBuilder, RealScanBunnyMatchesTheReference)
{
    SKIP_WITHOUT_SHARED_DATA();
    expectRealScanMatches(stylos::test::sharedData() / "formats" / "bun000_ascii_rangegrid.ply", 10);
}

TEST(OctreeBuilder, RealScanIgeaMatchesTheReference)
{
    SKIP_WITHOUT_SHARED_DATA();
    expectRealScanMatches(stylos::test::sharedData() / "scans" / "igea_134k.ply", 10, false);  // the bunny is shuffled
}

TEST(OctreeBuilder, SourceWithoutNormalsIsRefusedButAFileGetsThemEstimated)
{
    const io::PointBatch cloud = smallCloud(800);
    TempDir dir;
    for (BuildMethod m : methods) {
        auto refused = buildOctree(memorySource(cloud, false), dir / "x.poct", optionsFor(m, 6));
        ASSERT_FALSE(refused.ok());
        EXPECT_EQ(refused.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(refused.error().message.find("no normals"), std::string::npos) << refused.error().message;
    }
    EXPECT_FALSE(fs::exists(dir / "x.poct"));
    writePly(dir / "plain.ply", cloud, false);
    for (BuildMethod m : methods) {
        const fs::path out = dir / (std::string(buildMethodName(m)) + ".poct");
        auto report = buildOctreeFile(dir / "plain.ply", out, optionsFor(m, 6));
        ASSERT_TRUE(report.ok()) << report.error().message;
        EXPECT_TRUE(report->normalsEstimated);
        EXPECT_EQ(report->points, 800u);
        EXPECT_TRUE(fs::exists(out));
    }
    // The temporary folder is gone; both files are the same.
    EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"optimal.poct", "plain.ply", "streaming.poct"}));
    EXPECT_EQ(stylos::test::readBytes(dir / "optimal.poct"), stylos::test::readBytes(dir / "streaming.poct"));
}

TEST(OctreeBuilder, BadArgumentsAndEmptySourcesAreRefused)
{
    TempDir dir;
    const io::PointBatch cloud = smallCloud(100);
    writePly(dir / "plain.ply", cloud, false);
    for (BuildMethod m : methods) {
        for (int depth : {0, -1, 22}) {
            auto r = buildOctree(memorySource(cloud), dir / "x.poct", optionsFor(m, depth));
            ASSERT_FALSE(r.ok());
            EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
            EXPECT_NE(r.error().message.find("depth " + std::to_string(depth)), std::string::npos) << r.error().message;
            auto f = buildOctreeFile(dir / "plain.ply", dir / "x.poct", optionsFor(m, depth));
            ASSERT_FALSE(f.ok());
            EXPECT_EQ(f.error().code, ErrorCode::InvalidArgument);
        }
        auto noThreads = buildOctree(memorySource(cloud), dir / "x.poct", optionsFor(m, 5, 0));
        ASSERT_FALSE(noThreads.ok());
        EXPECT_EQ(noThreads.error().code, ErrorCode::InvalidArgument);
        const io::PointBatch none;
        for (bool withBox : {false, true}) {
            BuildOptions o = optionsFor(m, 5);
            if (withBox) o.box = RootBox{};
            auto empty = buildOctree(memorySource(none), dir / "x.poct", o);
            ASSERT_FALSE(empty.ok());
            // Empty: the workbench says "the file is empty" (it said "these data and settings do not allow it").
            EXPECT_EQ(empty.error().code, ErrorCode::Empty);
            EXPECT_NE(empty.error().message.find("no points"), std::string::npos) << empty.error().message;
        }
        // Depths 1 and 21 work.
        for (int depth : {MinOctreeDepth, MaxOctreeDepth})
            expectBuildersMatchReference(memorySource(cloud, true, true), cloud, depth, "depth " + std::to_string(depth));
    }
    EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"plain.ply"}));
}

TEST(OctreeBuilder, MemoryLimitStopsTheBuildWithAMessageAndNoFile)
{
    TempDir dir;
    const io::PointBatch cloud = smallCloud(20000, 2);
    for (BuildMethod m : methods) {
        BuildOptions o = optionsFor(m, 12);
        o.memoryLimit = 200 << 10;  // 200 KiB: ~29,000 cells, the tree needs ~150,000
        auto r = buildOctree(memorySource(cloud), dir / "x.poct", o);
        ASSERT_FALSE(r.ok()) << buildMethodName(m);
        EXPECT_EQ(r.error().code, ErrorCode::OutOfBudget);
        const std::string& message = r.error().message;
        EXPECT_NE(message.find("the octree needs "), std::string::npos) << message;
        EXPECT_NE(message.find("memory limit (--memory-limit) is 200 KiB"), std::string::npos) << message;
        if (m == BuildMethod::Optimal) {
            EXPECT_NE(message.find(" at level "), std::string::npos) << message;
        }
        // Below one chunk: refused at once.
        o.memoryLimit = 1000;
        auto tiny = buildOctree(memorySource(cloud), dir / "x.poct", o);
        ASSERT_FALSE(tiny.ok());
        EXPECT_EQ(tiny.error().code, ErrorCode::OutOfBudget);
        // A limit that fits builds, and the structure stays within it.
        o.memoryLimit = 64 << 20;
        BuildReport report;
        ASSERT_TRUE(buildConstructionOctree(memorySource(cloud), o, nullptr, &report).ok());
        EXPECT_LE(report.constructionBytes, o.memoryLimit);
        // Room for the structure but not for the spacing layer written beside it (4 bytes a leaf): refused, no file.
        const std::uint64_t leaves = report.cellsPerLevel.back();
        o.memoryLimit = report.constructionBytes + 2 * leaves;
        auto spacing = buildOctree(memorySource(cloud), dir / "x.poct", o);
        ASSERT_FALSE(spacing.ok()) << buildMethodName(m);
        EXPECT_EQ(spacing.error().code, ErrorCode::OutOfBudget);
        EXPECT_NE(spacing.error().message.find("with its leaves' spacing layer (" + std::to_string(leaves) + " leaves × 4 bytes)"),
                  std::string::npos)
            << spacing.error().message;
        o.memoryLimit = report.constructionBytes + 4 * leaves;
        ASSERT_TRUE(buildOctree(memorySource(cloud), dir / "y.poct", o).ok()) << buildMethodName(m);
        std::filesystem::remove(dir / "y.poct");
    }
    EXPECT_TRUE(listing(dir.path()).empty());
}

TEST(OctreeBuilder, OptimalRefusesAtTheLevelThatDoesNotFit)
{
    // Exact sizes are known before allocating: with room for the first levels only, Optimal stops at
    // the first level that does not fit and says so; the bytes it needed are more than the limit.
    const io::PointBatch cloud = smallCloud(20000, 2);
    BuildOptions o = optionsFor(BuildMethod::Optimal, 12);
    o.memoryLimit = 200 << 10;
    auto r = buildConstructionOctree(memorySource(cloud), o);
    ASSERT_FALSE(r.ok());
    const std::string& message = r.error().message;
    const std::size_t at = message.find("at level ");
    ASSERT_NE(at, std::string::npos) << message;
    const int level = std::stoi(message.substr(at + 9));
    const ReferenceOctree reference = ReferenceOctree::fromBatch(cloud, 12);
    const auto& counts = reference.description().cellsPerLevel;
    auto cellsThrough = [&](int l) { return std::accumulate(counts.begin(), counts.begin() + l + 1, std::uint64_t(0)); };
    ASSERT_GE(level, 1);
    EXPECT_LE(7 * cellsThrough(level - 1), o.memoryLimit) << message;            // the levels before fitted
    EXPECT_GT(7 * cellsThrough(level) + 14336 + 512, o.memoryLimit) << message;   // this one could not
    EXPECT_NE(message.find("the octree needs "), std::string::npos);
}

TEST(OctreeBuilder, CancelLeavesNoFile)
{
    TempDir dir;
    const io::PointBatch cloud = smallCloud(50000, 3);
    writePly(dir / "plain.ply", cloud, false);
    for (BuildMethod m : methods) {
        for (int after : {1, 3, 6}) {
            CancelAfter cancel(after);
            auto r = buildOctree(memorySource(cloud), dir / "x.poct", optionsFor(m, 10), &cancel);
            ASSERT_FALSE(r.ok());
            EXPECT_EQ(r.error().code, ErrorCode::Cancelled) << r.error().message;
        }
        CancelAfter cancel(2);
        auto f = buildOctreeFile(dir / "plain.ply", dir / "x.poct", optionsFor(m, 10), &cancel);
        ASSERT_FALSE(f.ok());
        EXPECT_EQ(f.error().code, ErrorCode::Cancelled) << f.error().message;
    }
    EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"plain.ply"}));
}

/** Cancels once the progress passes @p threshold (the writing phase starts at 0.95). */
class CancelPast final : public ProgressSink {
public:
    explicit CancelPast(double threshold) : m_threshold(threshold) {}
    void update(double fraction) override { m_last = std::max(m_last, fraction); }
    bool isCancelRequested() const override { return m_last > m_threshold; }
    double last() const { return m_last; }

private:
    double m_threshold;
    double m_last = 0;
};

TEST(OctreeBuilder, CancelWhileWritingLeavesNoFile)
{
    TempDir dir;
    const io::PointBatch cloud = smallCloud(50000, 3);
    for (BuildMethod m : methods) {
        CancelPast cancel(0.95);
        auto r = buildOctree(memorySource(cloud), dir / "x.poct", optionsFor(m, 10), &cancel);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::Cancelled) << r.error().message;
        EXPECT_GT(cancel.last(), 0.95);
        EXPECT_LT(cancel.last(), 1.0);  // stopped inside the writing phase
    }
    EXPECT_TRUE(listing(dir.path()).empty());
}

TEST(OctreeBuilder, ReaderErrorsAndChangingInputsAreReported)
{
    TempDir dir;
    const io::PointBatch cloud = smallCloud(3000, 5);
    writePly(dir / "good.ply", cloud, true);
    // Truncated: the last records cut off.
    auto bytes = stylos::test::readBytes(dir / "good.ply");
    bytes.resize(bytes.size() - 100);
    stylos::test::writeBytes(dir / "cut.ply", bytes);
    for (BuildMethod m : methods) {
        auto r = buildOctree(fileSource(dir / "cut.ply"), dir / "x.poct", optionsFor(m, 8));
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::Truncated) << r.error().message;
        auto missing = buildOctreeFile(dir / "missing.ply", dir / "x.poct", optionsFor(m, 8));
        ASSERT_FALSE(missing.ok());
        EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
    }
    // Sources that yield other points on a later pass (Optimal re-reads them): another count, or the
    // same count elsewhere (a given box, the first points in its lower x half, the later in the upper).
    io::PointSchema schema;
    schema.hasNormals = true;
    const io::PointBatch fewer = smallCloud(2999, 5);
    int opened = 0;
    PointSourceFactory shrinking = [&]() -> Result<std::unique_ptr<io::PointReader>> {
        return std::unique_ptr<io::PointReader>(std::make_unique<MemoryReader>(opened++ < 2 ? cloud : fewer, schema));
    };
    auto r = buildOctree(shrinking, dir / "x.poct", optionsFor(BuildMethod::Optimal, 8));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Malformed);
    EXPECT_NE(r.error().message.find("changed between passes over the input (pass 3 read 2999 points, the first pass 3000)"),
              std::string::npos) << r.error().message;
    io::PointBatch left = cloud, right = cloud;
    for (std::size_t i = 0; i < cloud.size(); ++i) right.positions[3 * i] += 1.0;  // x in 9..11 → 10..12
    BuildOptions boxed = optionsFor(BuildMethod::Optimal, 8);
    boxed.box = RootBox{{8, -8, -2}, 6.0};  // x: 8..14, lower half 8..11
    opened = 0;
    PointSourceFactory moving = [&]() -> Result<std::unique_ptr<io::PointReader>> {
        return std::unique_ptr<io::PointReader>(std::make_unique<MemoryReader>(opened++ < 2 ? left : right, schema));
    };
    r = buildOctree(moving, dir / "x.poct", boxed);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Malformed);
    EXPECT_NE(r.error().message.find("changed between passes"), std::string::npos) << r.error().message;
    EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"cut.ply", "good.ply"}));
}
