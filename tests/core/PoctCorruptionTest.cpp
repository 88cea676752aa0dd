// Corrupted and truncated .poct files are refused with the right error, never a crash: truncation at
// every length, a flipped byte (and a flipped bit) at every offset, and files whose checksums were
// recomputed after the damage ("re-signed"), so that the structural checks behind the checksums are
// exercised too. The layout is read here from docs/file-format.md's offsets, not from the code.
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "TestSupport.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Hash64.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

using namespace stylos::core;
using namespace stylos::core::octree;
using stylos::test::ReferenceOctree;
using stylos::test::TempDir;
using stylos::test::valueAt;

namespace {

template <typename T>
void set(std::vector<std::uint8_t>& b, std::size_t offset, T v)
{
    std::memcpy(b.data() + offset, &v, sizeof v);
}

/** The documented layout of a file image. */
struct Layout {
    std::size_t headerBytes = 0;
    int depth = 0;
    std::size_t table = 0;  ///< offset of the section table
    struct Section { std::string name; std::size_t entry, offset, length; };
    std::vector<Section> sections;

    bool valid = false;  ///< false when (damaged) sizes point outside the image

    explicit Layout(const std::vector<std::uint8_t>& b)
    {
        if (b.size() < 64) return;
        headerBytes = valueAt<std::uint32_t>(b, 12);
        depth = b[56];
        table = 64 + 8 * (static_cast<std::size_t>(depth) + 1);
        const auto count = valueAt<std::uint32_t>(b, 60);
        if (headerBytes < 8 || headerBytes > b.size() || table + 48 * std::uint64_t(count) > b.size()) return;
        for (std::uint32_t s = 0; s < count; ++s) {
            const std::size_t e = table + 48 * s;
            const char* name = reinterpret_cast<const char*>(b.data() + e);
            sections.push_back({std::string(name, strnlen(name, 16)), e,
                                static_cast<std::size_t>(valueAt<std::uint64_t>(b, e + 24)),
                                static_cast<std::size_t>(valueAt<std::uint64_t>(b, e + 32))});
        }
        valid = true;
    }
    const Section& section(const std::string& name) const
    {
        for (const auto& s : sections)
            if (s.name == name) return s;
        throw std::runtime_error("no section " + name);
    }
};

/** Recomputes every section checksum, then the header checksum. */
void resign(std::vector<std::uint8_t>& b)
{
    const Layout layout(b);
    if (!layout.valid) return;
    for (const auto& s : layout.sections)
        if (s.offset <= b.size() && s.length <= b.size() - s.offset)
            set<std::uint64_t>(b, s.entry + 40, xxh64(b.data() + s.offset, s.length));
    set<std::uint64_t>(b, layout.headerBytes - 8, xxh64(b.data(), layout.headerBytes - 8));
}

/** A real file: depth 5, colour, and a 2 × UInt16 layer; a few KB. */
std::vector<std::uint8_t> sampleFile(const TempDir& dir)
{
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> p;
    std::vector<float> n;
    std::vector<std::uint8_t> c;
    for (int i = 0; i < 400; ++i) {
        p.insert(p.end(), {u(rng), u(rng), u(rng) * u(rng)});
        n.insert(n.end(), {0.1f, 0.2f, 1.0f});
        c.insert(c.end(), {std::uint8_t(i), std::uint8_t(2 * i), 9});
    }
    const ReferenceOctree ref(p, n, c, 5);
    std::vector<std::uint8_t> cls(4 * ref.cellCount(5));
    for (std::size_t i = 0; i < cls.size(); ++i) cls[i] = static_cast<std::uint8_t>(i);
    const std::vector<AttributeLayer> layers{{"class", AttributeType::UInt16, 2, cls}};
    const auto path = dir / "sample.poct";
    auto r = writePoct(ref, path, layers);
    EXPECT_TRUE(r.ok()) << r.error().message;
    const auto bytes = stylos::test::readBytes(path);
    return {bytes.begin(), bytes.end()};
}

Error openError(std::vector<std::uint8_t> bytes)
{
    auto r = PackedOctree::fromBytes(std::move(bytes), "bad.poct");
    if (r.ok()) return Error{ErrorCode::Cancelled, "opened"};
    return r.error();
}

} // namespace

TEST(PoctCorruption, SampleOpens)
{
    TempDir dir;
    const auto bytes = sampleFile(dir);
    ASSERT_TRUE(PackedOctree::fromBytes(bytes).ok());
    const Layout layout(bytes);
    ASSERT_EQ(layout.sections.size(), 4u);
    EXPECT_EQ(layout.sections[2].name, "colour");
    EXPECT_EQ(layout.sections[3].name, "class");
    EXPECT_GT(bytes.size(), 2000u);
}

TEST(PoctCorruption, TruncationAtEveryLength)
{
    TempDir dir;
    const auto bytes = sampleFile(dir);
    for (std::size_t size = 0; size < bytes.size(); ++size) {
        const Error e = openError(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + static_cast<long>(size)));
        EXPECT_EQ(e.code, size == 0 ? ErrorCode::Empty : ErrorCode::Truncated) << size << ": " << e.message;
        EXPECT_EQ(e.message.rfind("bad.poct: ", 0), 0u) << e.message;
    }
    // And a few through the file system.
    for (std::size_t size : {std::size_t(0), std::size_t(5), std::size_t(63), std::size_t(100), bytes.size() - 1}) {
        const auto path = dir / ("cut" + std::to_string(size) + ".poct");
        stylos::test::writeBytes(path, std::vector<char>(bytes.begin(), bytes.begin() + static_cast<long>(size)));
        auto r = PackedOctree::open(path);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, size == 0 ? ErrorCode::Empty : ErrorCode::Truncated) << r.error().message;
        EXPECT_NE(r.error().message.find(path.string()), std::string::npos);
    }
}

TEST(PoctCorruption, FlippedByteOrBitAtEveryOffset)
{
    TempDir dir;
    const auto bytes = sampleFile(dir);
    const Layout layout(bytes);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        for (std::uint8_t flip : {std::uint8_t(0xFF), std::uint8_t(1u << (i % 8))}) {
            auto bad = bytes;
            bad[i] ^= flip;
            const Error e = openError(std::move(bad));
            const std::string where = std::to_string(i) + " ^ " + std::to_string(flip) + ": " + e.message;
            if (i < 8) {
                EXPECT_EQ(e.code, ErrorCode::UnknownFormat) << where;
            } else if (i < 12) {
                EXPECT_TRUE(e.code == ErrorCode::Unsupported || e.code == ErrorCode::Malformed) << where;
            } else {
                ASSERT_EQ(e.code, ErrorCode::Malformed) << where;
                const Layout::Section* in = nullptr;
                for (const auto& s : layout.sections)
                    if (i >= s.offset && i < s.offset + s.length) in = &s;
                if (in) {
                    EXPECT_NE(e.message.find("checksum mismatch in section \"" + in->name + "\""), std::string::npos)
                        << where;
                } else if (i >= layout.headerBytes) {
                    EXPECT_NE(e.message.find("padding"), std::string::npos) << where;
                }
            }
        }
    }
}

TEST(PoctCorruption, FlipsThroughTheFileSystem)
{
    TempDir dir;
    const auto bytes = sampleFile(dir);
    const Layout layout(bytes);
    for (const auto& s : layout.sections) {
        auto bad = bytes;
        bad[s.offset + s.length / 2] ^= 0x10;
        const auto path = dir / (s.name + ".poct");
        stylos::test::writeBytes(path, std::vector<char>(bad.begin(), bad.end()));
        auto r = PackedOctree::open(path);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::Malformed);
        EXPECT_EQ(r.error().message.rfind(path.string() + ": bytes " + std::to_string(s.offset) + "..", 0), 0u)
            << r.error().message;
        EXPECT_NE(r.error().message.find("\"" + s.name + "\""), std::string::npos) << r.error().message;
    }
}

TEST(PoctCorruption, ResignedStructuralDamage)
{
    TempDir dir;
    const auto bytes = sampleFile(dir);
    const Layout layout(bytes);
    const auto& masks = layout.section("masks");
    auto expectError = [&](std::vector<std::uint8_t> bad, ErrorCode code, const std::string& fragment) {
        resign(bad);
        const Error e = openError(std::move(bad));
        EXPECT_EQ(e.code, code) << e.message;
        EXPECT_NE(e.message.find(fragment), std::string::npos) << e.message;
    };
    {   // An inner cell without children.
        auto bad = bytes;
        bad[masks.offset + masks.length - 1] = 0;
        expectError(bad, ErrorCode::Malformed, "has no children");
    }
    {   // One child too many on a cell of the last inner level.
        auto bad = bytes;
        std::size_t at = masks.offset + masks.length - 1;
        while (bad[at] == 0xFF) --at;
        bad[at] = static_cast<std::uint8_t>(bad[at] | (bad[at] + 1)); // sets the lowest clear bit
        expectError(bad, ErrorCode::Malformed, "child masks give");
    }
    {   // Cell counts that contradict the section lengths.
        auto bad = bytes;
        set<std::uint64_t>(bad, 64 + 8 * 5, valueAt<std::uint64_t>(bad, 64 + 8 * 5) + 1);
        expectError(bad, ErrorCode::Malformed, "length");
    }
    {   // A level with more cells than 8 × its parent level.
        auto bad = bytes;
        set<std::uint64_t>(bad, 64 + 8, 9);
        expectError(bad, ErrorCode::Malformed, "level 1 cannot have 9 cells");
    }
    {   // Bytes after the last section.
        auto bad = bytes;
        bad.push_back(0);
        expectError(bad, ErrorCode::Malformed, "1 unexpected bytes after the last section");
    }
    {   // Unknown normal code, unknown element type, reserved bytes, version 0, bad box, bad offset.
        auto bad = bytes;
        bad[57] = 7;
        expectError(bad, ErrorCode::Unsupported, "unknown normal code 7");
        bad = bytes;
        bad[layout.section("class").entry + 17] = 9;
        expectError(bad, ErrorCode::Unsupported, "unknown element type 9");
        bad = bytes;
        bad[layout.section("class").entry + 20] = 1;
        expectError(bad, ErrorCode::Malformed, "reserved bytes");
        bad = bytes;
        bad[58] = 1;
        expectError(bad, ErrorCode::Malformed, "reserved bytes");
        bad = bytes;
        set<std::uint32_t>(bad, 8, 0);
        expectError(bad, ErrorCode::Malformed, "version 0");
        bad = bytes;
        set<double>(bad, 40, -1.0);
        expectError(bad, ErrorCode::Malformed, "root box");
        bad = bytes;
        set<std::uint64_t>(bad, layout.section("colour").entry + 24, layout.section("colour").offset + 64);
        expectError(bad, ErrorCode::Malformed, "offset");
        bad = bytes;
        std::memcpy(bad.data() + layout.section("class").entry, "colour", 6);
        expectError(bad, ErrorCode::Malformed, "duplicate");
    }
}

TEST(PoctCorruption, ResignedRandomHeaderDamageNeverCrashes)
{
    TempDir dir;
    const auto bytes = sampleFile(dir);
    const Layout layout(bytes);
    std::mt19937_64 rng(99);
    int opened = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        auto bad = bytes;
        const int flips = 1 + static_cast<int>(rng() % 4);
        for (int f = 0; f < flips; ++f) {
            // Anywhere in the header after the version, the masks, or anywhere at all.
            const std::size_t region = rng() % 3;
            const std::size_t at = region == 0 ? 12 + rng() % (layout.headerBytes - 20)
                                   : region == 1
                                       ? layout.section("masks").offset + rng() % layout.section("masks").length
                                       : rng() % bad.size();
            bad[at] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
        }
        if (rng() % 2) resign(bad);
        auto r = PackedOctree::fromBytes(std::move(bad), "fuzz.poct");
        if (!r.ok()) continue;
        // What opens must be consistent: walk it all.
        ++opened;
        const PackedOctree& o = *r;
        std::uint64_t cells = 0;
        o.forEachCell(o.depth(), [&](const CellView&) { return ++cells, true; });
        EXPECT_EQ(cells, o.cellCount(o.depth()));
        for (int l = 0; l < o.depth(); ++l)
            EXPECT_LE(o.firstChild(l, o.cellCount(l) - 1), o.cellCount(l + 1) - 1);
        for (const auto& a : o.attributes()) {
            const std::size_t element = a.type == AttributeType::UInt8 ? 1 : a.type == AttributeType::UInt16 ? 2 : 4;
            EXPECT_EQ(a.bytes.size(), o.cellCount(o.depth()) * a.components * element);
        }
    }
    std::printf("%d of 3000 damaged images opened (damage that left the file consistent)\n", opened);
}
