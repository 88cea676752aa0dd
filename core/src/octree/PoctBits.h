#pragma once
// Internal: bit counting for child masks. std::popcount compiles to a library call (__popcountdi2)
// when the build does not target a CPU with POPCNT (the default x86-64 baseline), which made it the
// largest cost of opening a file; this portable SWAR count inlines to a dozen instructions.
#include <cstdint>

namespace stylos::core::octree::poct {

/** Number of set bits of @p w. */
inline unsigned popcount64(std::uint64_t w)
{
    w = w - ((w >> 1) & 0x5555555555555555ull);
    w = (w & 0x3333333333333333ull) + ((w >> 2) & 0x3333333333333333ull);
    w = (w + (w >> 4)) & 0x0F0F0F0F0F0F0F0Full;
    return static_cast<unsigned>((w * 0x0101010101010101ull) >> 56);
}

/** Number of set bits of a child mask. */
inline unsigned popcount8(std::uint8_t m)
{
    unsigned v = m;
    v = v - ((v >> 1) & 0x55u);
    v = (v & 0x33u) + ((v >> 2) & 0x33u);
    return (v + (v >> 4)) & 0x0Fu;
}

} // namespace stylos::core::octree::poct
