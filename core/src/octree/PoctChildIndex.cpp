#include "PoctChildIndex.h"

#include "PoctBits.h"

#include <bit>
#include <cassert>
#include <cstring>

namespace stylos::core::octree::poct {

namespace {

constexpr std::uint64_t Ones = 0x0101010101010101ull;
constexpr std::uint64_t Highs = 0x8080808080808080ull;

/** Up to 8 bytes at @p p (fewer when @p available < 8), the missing high bytes set to @p fill. */
inline std::uint64_t loadWord(const std::uint8_t* p, std::uint64_t available, std::uint8_t fill)
{
    std::uint64_t w;
    if (available >= 8) {
        std::memcpy(&w, p, 8);
        return w;
    }
    std::uint8_t tmp[8];
    std::memset(tmp, fill, 8);
    std::memcpy(tmp, p, static_cast<std::size_t>(available));
    std::memcpy(&w, tmp, 8);
    return w;
}

inline bool hasZeroByte(std::uint64_t w)
{
    return ((w - Ones) & ~w & Highs) != 0;
}

} // namespace

Result<ChildIndex> ChildIndex::build(const std::vector<std::span<const std::uint8_t>>& masks,
                                     const std::vector<std::uint64_t>& cellsPerLevel, std::uint64_t masksOffset,
                                     const std::string& file)
{
    ChildIndex index;
    index.m_masks = masks;
    index.m_prefix.resize(masks.size());
    std::uint64_t levelOffset = masksOffset;
    for (std::size_t l = 0; l < masks.size(); ++l) {
        const std::uint8_t* m = masks[l].data();
        const std::uint64_t n = masks[l].size();
        assert(n == cellsPerLevel[l] && "ChildIndex::build(): masks do not match the cell count");
        auto& prefix = index.m_prefix[l];
        prefix.reserve(n / 64 + 2);
        std::uint64_t children = 0;
        auto noChildren = [&](std::uint64_t from) {
            std::uint64_t at = from;
            while (m[at] != 0) ++at;
            return Error::at(ErrorCode::Malformed, file, "byte " + std::to_string(levelOffset + at),
                             "level " + std::to_string(l) + ": inner cell " + std::to_string(at) + " has no children");
        };
        std::uint64_t j = 0;
        for (; j + 64 <= n; j += 64) {  // whole blocks of 64 cells: no branches but one
            prefix.push_back(children);
            std::uint64_t zero = 0;
            for (int k = 0; k < 8; ++k) {
                std::uint64_t w;
                std::memcpy(&w, m + j + 8 * k, 8);
                zero |= (w - Ones) & ~w & Highs;
                children += popcount64(w);
            }
            if (zero) return noChildren(j);
        }
        for (; j < n; j += 8) {  // the last partial block
            if (j % 64 == 0) prefix.push_back(children);
            const std::uint64_t w = loadWord(m + j, n - j, 0xFF);
            if (hasZeroByte(w)) return noChildren(j);
            children += static_cast<std::uint64_t>(popcount64(w)) - 8 * (j + 8 > n ? j + 8 - n : 0);
        }
        prefix.push_back(children);
        if (children != cellsPerLevel[l + 1])
            return Error::at(ErrorCode::Malformed, file, "byte " + std::to_string(levelOffset),
                             "level " + std::to_string(l) + ": child masks give " + std::to_string(children) +
                                 " children but level " + std::to_string(l + 1) + " has " +
                                 std::to_string(cellsPerLevel[l + 1]) + " cells");
        levelOffset += n;
    }
    return index;
}

std::uint64_t ChildIndex::firstChild(int level, std::uint64_t index) const
{
    const auto& masks = m_masks[static_cast<std::size_t>(level)];
    assert(index < masks.size() && "ChildIndex::firstChild(): index out of range");
    const std::uint8_t* m = masks.data();
    std::uint64_t count = m_prefix[static_cast<std::size_t>(level)][index >> 6];
    std::uint64_t j = index & ~std::uint64_t(63);
    for (; j + 8 <= index; j += 8) {
        std::uint64_t w;
        std::memcpy(&w, m + j, 8);
        count += static_cast<std::uint64_t>(popcount64(w));
    }
    if (j < index) {
        const std::uint64_t keep = index - j; // 1..7 bytes
        const std::uint64_t w = loadWord(m + j, masks.size() - j, 0) & ((std::uint64_t(1) << (8 * keep)) - 1);
        count += static_cast<std::uint64_t>(popcount64(w));
    }
    return count;
}

std::uint64_t ChildIndex::bytes() const
{
    std::uint64_t b = 0;
    for (const auto& p : m_prefix) b += 8 * p.size();
    return b;
}

} // namespace stylos::core::octree::poct
