#include "stylos/core/octree/PackedOctree.h"

#include "PoctChildIndex.h"
#include "PoctLayout.h"
#include "stylos/core/octree/LeafSpacing.h"
#include "stylos/core/util/Hash64.h"
#include "stylos/core/util/MappedFile.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>
#include <mutex>

namespace stylos::core::octree {

namespace fs = std::filesystem;

bool isPoctSignature(std::span<const std::uint8_t> firstBytes)
{
    return firstBytes.size() >= poct::Magic.size() &&
           std::memcmp(firstBytes.data(), poct::Magic.data(), poct::Magic.size()) == 0;
}

/** The mapped file, its parsed header and the child index; also the levels() adapter. */
struct PackedOctree::Impl final : OctreeLevels {
    fs::path path;
    MappedFile mapped;                     ///< the file (open())
    std::vector<std::uint8_t> memory;      ///< or the image (fromBytes())
    std::span<const std::uint8_t> bytes;
    poct::Header header;
    OctreeDescription desc;
    std::vector<std::span<const std::uint8_t>> masks;     ///< per inner level
    std::vector<std::span<const std::uint16_t>> normals;  ///< per level
    std::span<const std::uint8_t> colours;                ///< the "colour" layer, if any
    poct::ChildIndex index;
    const std::array<float, 3>* decode = nullptr;
    std::uint16_t codeMask = 0xFFFF;
    std::uint64_t total = 0;
    std::span<const std::uint8_t> spacingLayer;           ///< the "spacing" layer, if stored
    mutable std::once_flag spacingOnce;
    mutable std::vector<float> spacingComputed;           ///< computed on first use when not stored

    const OctreeDescription& description() const override { return desc; }

    void visitLevel(int level, const std::function<void(const CellBlock&)>& sink) const override
    {
        assert(level >= 0 && level <= desc.depth && "PackedOctree::levels(): level out of range");
        constexpr std::size_t Block = 32768;
        const auto l = static_cast<std::size_t>(level);
        const std::size_t n = normals[l].size();
        const bool leaf = level == desc.depth;
        for (std::size_t begin = 0; begin < n; begin += Block) {
            const std::size_t count = std::min(Block, n - begin);
            CellBlock block;
            if (!leaf) block.masks = masks[l].subspan(begin, count);
            block.normals = normals[l].subspan(begin, count);
            if (leaf && !colours.empty()) block.colours = colours.subspan(3 * begin, 3 * count);
            sink(block);
        }
    }

    /** Checks the image in `bytes` and sets up everything else. */
    Status load(const std::string& name);
};

Status PackedOctree::Impl::load(const std::string& name)
{
    auto parsed = poct::parseHeader(bytes, name);
    if (!parsed) return parsed.error();
    header = std::move(parsed.value());
    for (const poct::SectionEntry& e : header.sections) {
        if (xxh64(bytes.data() + e.offset, e.length) != e.checksum)
            return Error::at(ErrorCode::Malformed, name, "bytes " + std::to_string(e.offset) + ".." +
                                                             std::to_string(e.offset + e.length),
                             "checksum mismatch in section \"" + e.name + "\": the file is corrupted");
    }
    desc.box = header.box;
    desc.depth = header.depth;
    desc.normalCode = header.normalCode;
    desc.points = header.points;
    desc.cellsPerLevel = header.cellsPerLevel;
    const std::uint8_t* maskBase = bytes.data() + header.sections[0].offset;
    const auto* normalBase = reinterpret_cast<const std::uint16_t*>(bytes.data() + header.sections[1].offset);
    std::uint64_t maskAt = 0, normalAt = 0;
    for (int l = 0; l <= desc.depth; ++l) {
        const std::uint64_t c = desc.cellsPerLevel[static_cast<std::size_t>(l)];
        if (l < desc.depth) {
            masks.emplace_back(maskBase + maskAt, c);
            maskAt += c;
        }
        normals.emplace_back(normalBase + normalAt, c);
        normalAt += c;
        total += c;
    }
    for (std::size_t s = 2; s < header.sections.size(); ++s)
        if (header.sections[s].name == "colour") {
            colours = bytes.subspan(header.sections[s].offset, header.sections[s].length);
            desc.hasColour = true;
        } else if (const auto& e = header.sections[s]; e.name == LeafSpacingLayerName && e.type == AttributeType::Float32 &&
                   e.components == 1 && e.length == 4 * desc.cellsPerLevel.back()) {
            spacingLayer = bytes.subspan(e.offset, e.length);
        }
    auto built = poct::ChildIndex::build(masks, desc.cellsPerLevel, header.sections[0].offset, name);
    if (!built) return built.error();
    index = std::move(built.value());
    decode = normalDecodeTable(desc.normalCode);
    codeMask = desc.normalCode == NormalCodeKind::Paper15 ? 0x7FFF : 0xFFFF;
    return {};
}

Result<PackedOctree> PackedOctree::open(const fs::path& path)
{
    auto mapped = MappedFile::open(path, true);
    if (!mapped) return mapped.error();
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    impl->mapped = std::move(mapped.value());
    impl->bytes = impl->mapped.bytes();
    if (auto s = impl->load(path.string()); !s) return s.error();
    return PackedOctree(std::move(impl));
}

Result<PackedOctree> PackedOctree::fromBytes(std::vector<std::uint8_t> bytes, const std::string& name)
{
    auto impl = std::make_unique<Impl>();
    impl->path = name;
    impl->memory = std::move(bytes);
    impl->bytes = impl->memory;
    if (auto s = impl->load(name); !s) return s.error();
    return PackedOctree(std::move(impl));
}

PackedOctree::PackedOctree(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
PackedOctree::PackedOctree(PackedOctree&&) noexcept = default;
PackedOctree& PackedOctree::operator=(PackedOctree&&) noexcept = default;
PackedOctree::~PackedOctree() = default;

const OctreeDescription& PackedOctree::description() const { return m_impl->desc; }
std::uint64_t PackedOctree::totalCells() const { return m_impl->total; }
std::uint64_t PackedOctree::fileBytes() const { return m_impl->bytes.size(); }
const fs::path& PackedOctree::path() const { return m_impl->path; }
const OctreeLevels& PackedOctree::levels() const { return *m_impl; }
std::uint64_t PackedOctree::indexBytes() const { return m_impl->index.bytes(); }

std::uint8_t PackedOctree::mask(int level, std::uint64_t index) const
{
    if (level >= m_impl->desc.depth) return 0;
    return m_impl->masks[static_cast<std::size_t>(level)][index];
}

std::uint16_t PackedOctree::normalCode(int level, std::uint64_t index) const
{
    return m_impl->normals[static_cast<std::size_t>(level)][index];
}

std::array<float, 3> PackedOctree::normal(int level, std::uint64_t index) const
{
    return m_impl->decode[normalCode(level, index) & m_impl->codeMask];
}

std::uint64_t PackedOctree::firstChild(int level, std::uint64_t index) const
{
    assert(level >= 0 && level < m_impl->desc.depth && "PackedOctree::firstChild(): not an inner level");
    return m_impl->index.firstChild(level, index);
}

std::span<const std::uint8_t> PackedOctree::levelMasks(int level) const
{
    if (level >= m_impl->desc.depth) return {};
    return m_impl->masks[static_cast<std::size_t>(level)];
}

std::span<const std::uint16_t> PackedOctree::levelNormalCodes(int level) const
{
    return m_impl->normals[static_cast<std::size_t>(level)];
}

std::vector<AttributeView> PackedOctree::attributes() const
{
    std::vector<AttributeView> out;
    const auto& sections = m_impl->header.sections;
    for (std::size_t s = 2; s < sections.size(); ++s)
        out.push_back({sections[s].name, sections[s].type, sections[s].components,
                       m_impl->bytes.subspan(sections[s].offset, sections[s].length)});
    return out;
}

float PackedOctree::leafSpacing(std::uint64_t leaf) const
{
    assert(leaf < cellCount(depth()) && "PackedOctree::leafSpacing(): leaf out of range");
    const Impl& impl = *m_impl;
    if (impl.spacingLayer.empty()) {
        std::call_once(impl.spacingOnce, [&impl] { impl.spacingComputed = computeLeafSpacing(impl); });
        return impl.spacingComputed[leaf];
    }
    float h = 0;
    std::memcpy(&h, impl.spacingLayer.data() + 4 * leaf, 4); // little-endian file, little-endian host
    return h;
}

bool PackedOctree::hasStoredLeafSpacing() const { return !m_impl->spacingLayer.empty(); }

std::optional<AttributeView> PackedOctree::attribute(const std::string& name) const
{
    for (AttributeView& v : attributes())
        if (v.name == name) return std::move(v);
    return std::nullopt;
}

CellView PackedOctree::cell(int level, std::uint64_t index, const std::array<std::uint32_t, 3>& coords) const
{
    CellView c;
    c.level = level;
    c.index = index;
    c.coords = coords;
    c.centre = box().cellCentre(level, coords[0], coords[1], coords[2]);
    c.size = box().cellSize(level);
    c.normal = normal(level, index);
    c.mask = mask(level, index);
    return c;
}

CellView PackedOctree::root() const
{
    return cell(0, 0, {0, 0, 0});
}

void PackedOctree::forEachCell(int level, const std::function<bool(const CellView&)>& fn) const
{
    assert(level >= 0 && level <= depth() && "PackedOctree::forEachCell(): level out of range");
    const Impl& m = *m_impl;
    const RootBox& b = box();
    const std::uint16_t* codes = m.normals[static_cast<std::size_t>(level)].data();
    const std::uint8_t* levelMasks = level < depth() ? m.masks[static_cast<std::size_t>(level)].data() : nullptr;
    CellView c;
    c.level = level;
    c.size = b.cellSize(level);
    auto emit = [&](std::uint64_t index, std::uint32_t x, std::uint32_t y, std::uint32_t z) {
        c.index = index;
        c.coords = {x, y, z};
        c.centre = {b.origin[0] + (double(x) + 0.5) * c.size, b.origin[1] + (double(y) + 0.5) * c.size,
                    b.origin[2] + (double(z) + 0.5) * c.size};
        c.normal = m.decode[codes[index] & m.codeMask];
        c.mask = levelMasks ? levelMasks[index] : 0;
        return fn(c);
    };
    if (level == 0) {
        emit(0, 0, 0, 0);
        return;
    }
    // Depth-first walk in slot order: it meets the cells of each level in breadth-first order, so
    // a counter per level gives their indices (every inner cell has descendants down to the leaves).
    struct Frame {
        std::uint8_t remaining;   ///< child slots still to visit
        std::uint32_t x, y, z;    ///< the cell's coordinates
    };
    std::array<Frame, MaxOctreeDepth + 1> stack{};
    std::array<std::uint64_t, MaxOctreeDepth + 1> next{};  ///< next index to hand out, per level
    std::array<const std::uint8_t*, MaxOctreeDepth + 1> masks{};
    for (int l = 0; l < level; ++l) masks[static_cast<std::size_t>(l)] = m.masks[static_cast<std::size_t>(l)].data();
    stack[0] = {masks[0][0], 0, 0, 0};
    int top = 0;  // stack[top] is a cell of level `top`
    while (top >= 0) {
        Frame& f = stack[static_cast<std::size_t>(top)];
        if (f.remaining == 0) {
            --top;
            continue;
        }
        const unsigned slot = static_cast<unsigned>(std::countr_zero(f.remaining));
        f.remaining = static_cast<std::uint8_t>(f.remaining & (f.remaining - 1));
        const auto childLevel = static_cast<std::size_t>(top + 1);
        const std::uint32_t x = 2 * f.x + (slot & 1u), y = 2 * f.y + ((slot >> 1) & 1u), z = 2 * f.z + (slot >> 2);
        const std::uint64_t childIndex = next[childLevel]++;
        if (static_cast<int>(childLevel) == level) {
            if (!emit(childIndex, x, y, z)) return;
            continue;
        }
        stack[childLevel] = {masks[childLevel][childIndex], x, y, z};
        top = static_cast<int>(childLevel);
    }
}

} // namespace stylos::core::octree
