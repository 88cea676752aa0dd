#pragma once
/** @file
 * @brief A `.poct` file opened for reading: the file is memory-mapped (not read into memory), every
 *        section's checksum is verified, and a small child index is built (one 64-bit prefix count per
 *        64 cells of each inner level, ~1/8 byte per cell) so the children of any cell are found in
 *        constant time. Nothing else is materialised: cells are addressed by (level, index in
 *        breadth-first order) and their centres are computed during traversal.
 *
 * Failure modes (open): NotFound, Unreadable, Empty; UnknownFormat (bad magic); Unsupported (newer
 * version, unknown normal code); Truncated (file shorter than its sections); Malformed (a checksum that
 * does not match — the message names the section —, inconsistent level counts or child masks). A file
 * that opens is consistent: no access can then read out of bounds.
 * Thread-safety: an opened PackedOctree is immutable; any number of threads may read it.
 */
#include "stylos/core/octree/OctreeLevels.h"
#include "stylos/core/octree/PoctWriter.h"
#include "stylos/core/util/Result.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stylos::core::octree {

/** @brief One cell as level iteration and the cut deliver it. */
struct CellView {
    int level = 0;
    std::uint64_t index = 0;                  ///< breadth-first index within its level
    std::array<std::uint32_t, 3> coords{};    ///< integer coordinates at its level
    std::array<double, 3> centre{};           ///< metres
    double size = 0;                          ///< edge length, metres
    std::array<float, 3> normal{};            ///< unit
    std::uint8_t mask = 0;                    ///< child mask (0 for leaves)
};

/** @brief Read-only view of an attribute layer (data points into the mapped file). */
struct AttributeView {
    std::string name;
    AttributeType type = AttributeType::UInt8;
    std::uint8_t components = 1;
    std::span<const std::uint8_t> bytes;      ///< leaves × components × element size
};

/** @brief Whether @p firstBytes (at least the first 8 bytes of a file) start like a `.poct` file. */
bool isPoctSignature(std::span<const std::uint8_t> firstBytes);

class PackedOctree {
public:
    /**
     * @brief Maps and verifies @p path (see the file comment for the errors). Touches every byte
     *        once (checksums): a 174 MB file (67 M cells, 30 M-point drum at depth 13) opens in ~50 ms
     *        of CPU from the page cache (docs/file-format.md, "Speed").
     */
    static Result<PackedOctree> open(const std::filesystem::path& path);
    /** @brief The same from a file image in memory (tests, in-memory pipelines); takes ownership. */
    static Result<PackedOctree> fromBytes(std::vector<std::uint8_t> bytes, const std::string& name = "<memory>");

    PackedOctree(PackedOctree&&) noexcept;
    PackedOctree& operator=(PackedOctree&&) noexcept;
    ~PackedOctree();

    const OctreeDescription& description() const;
    const RootBox& box() const { return description().box; }
    int depth() const { return description().depth; }
    std::uint64_t cellCount(int level) const { return description().cellsPerLevel[static_cast<std::size_t>(level)]; }
    std::uint64_t totalCells() const;
    std::uint64_t fileBytes() const;
    const std::filesystem::path& path() const;

    /** @brief Child mask of a cell (0 at the leaf level). Precondition: index < cellCount(level). */
    std::uint8_t mask(int level, std::uint64_t index) const;
    /** @brief Normal code of a cell. */
    std::uint16_t normalCode(int level, std::uint64_t index) const;
    /** @brief Decoded unit normal of a cell (table lookup). */
    std::array<float, 3> normal(int level, std::uint64_t index) const;
    /**
     * @brief Index at level + 1 of the cell's first child (its children are consecutive, in slot order).
     *        Constant time (a prefix count and at most 8 popcounts). Precondition: level < depth().
     */
    std::uint64_t firstChild(int level, std::uint64_t index) const;

    /** @brief All child masks of @p level, in breadth-first order (empty at the leaf level); bulk access. */
    std::span<const std::uint8_t> levelMasks(int level) const;
    /** @brief All normal codes of @p level, in breadth-first order; bulk access. */
    std::span<const std::uint16_t> levelNormalCodes(int level) const;
    /** @brief Bytes of memory the child index takes (the file itself is mapped, not counted). */
    std::uint64_t indexBytes() const;

    /** @brief Attribute layers in file order. */
    std::vector<AttributeView> attributes() const;
    /** @brief The layer called @p name, if present. */
    std::optional<AttributeView> attribute(const std::string& name) const;

    /**
     * @brief The leaf's share of the surface as an edge, metres (core/octree/LeafSpacing.h): from the
     *        "spacing" layer when the file has it (Float32 × 1), else computed from the cells on the first
     *        call (one pass over the inner levels; thread-safe, 4 bytes per leaf kept). Precondition:
     *        leaf < cellCount(depth()).
     */
    float leafSpacing(std::uint64_t leaf) const;
    /** @brief Whether the file holds the "spacing" layer (else leafSpacing() computes it). */
    bool hasStoredLeafSpacing() const;

    /**
     * @brief Calls @p fn for every cell of @p level in breadth-first order (a depth-first walk down
     *        to the level, computing coordinates and centres on the way). Returns early when @p fn
     *        returns false.
     */
    void forEachCell(int level, const std::function<bool(const CellView&)>& fn) const;

    /** @brief The cell (level, index) with coordinates, centre, size, normal and mask filled in. */
    CellView cell(int level, std::uint64_t index, const std::array<std::uint32_t, 3>& coords) const;
    /** @brief The root cell. */
    CellView root() const;

    /** @brief Adapter for writePoct() (rewriting a file, e.g. with a new attribute layer). */
    const OctreeLevels& levels() const;

private:
    struct Impl;
    explicit PackedOctree(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

} // namespace stylos::core::octree
