#include "stylos/core/util/Hash64.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace stylos::core {

namespace {

constexpr std::uint64_t Prime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t Prime2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::uint64_t Prime3 = 0x165667B19E3779F9ull;
constexpr std::uint64_t Prime4 = 0x85EBCA77C2B2AE63ull;
constexpr std::uint64_t Prime5 = 0x27D4EB2F165667C5ull;

inline std::uint64_t load64(const std::uint8_t* p)
{
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    if constexpr (std::endian::native == std::endian::big) {
        std::uint64_t r = 0;
        for (int i = 0; i < 8; ++i) r |= std::uint64_t(p[i]) << (8 * i);
        v = r;
    }
    return v;
}

inline std::uint32_t load32(const std::uint8_t* p)
{
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

/** One lane step: accumulate 8 input bytes. */
inline std::uint64_t accumulate(std::uint64_t acc, std::uint64_t lane)
{
    acc += lane * Prime2;
    acc = std::rotl(acc, 31);
    return acc * Prime1;
}

/** Folds one lane accumulator into the converged value. */
inline std::uint64_t mergeAccumulator(std::uint64_t h, std::uint64_t acc)
{
    h ^= accumulate(0, acc);
    return h * Prime1 + Prime4;
}

/** Consumes whole 32-byte stripes of @p p; returns the bytes consumed. */
inline std::size_t consumeStripes(std::array<std::uint64_t, 4>& acc, const std::uint8_t* p, std::size_t size)
{
    std::uint64_t a0 = acc[0], a1 = acc[1], a2 = acc[2], a3 = acc[3];
    std::size_t done = 0;
    for (; done + 32 <= size; done += 32) {
        a0 = accumulate(a0, load64(p + done));
        a1 = accumulate(a1, load64(p + done + 8));
        a2 = accumulate(a2, load64(p + done + 16));
        a3 = accumulate(a3, load64(p + done + 24));
    }
    acc = {a0, a1, a2, a3};
    return done;
}

inline std::array<std::uint64_t, 4> initialAccumulators(std::uint64_t seed)
{
    return {seed + Prime1 + Prime2, seed + Prime2, seed, seed - Prime1};
}

/** Convergence, length, the remaining (< 32) bytes and the final avalanche. */
std::uint64_t finish(const std::array<std::uint64_t, 4>& acc, std::uint64_t seed, std::uint64_t length,
                     const std::uint8_t* tail, std::size_t tailSize)
{
    std::uint64_t h;
    if (length >= 32) {
        h = std::rotl(acc[0], 1) + std::rotl(acc[1], 7) + std::rotl(acc[2], 12) + std::rotl(acc[3], 18);
        for (std::uint64_t a : acc) h = mergeAccumulator(h, a);
    } else {
        h = seed + Prime5;
    }
    h += length;
    std::size_t i = 0;
    for (; i + 8 <= tailSize; i += 8) {
        h ^= accumulate(0, load64(tail + i));
        h = std::rotl(h, 27) * Prime1 + Prime4;
    }
    if (i + 4 <= tailSize) {
        h ^= std::uint64_t(load32(tail + i)) * Prime1;
        h = std::rotl(h, 23) * Prime2 + Prime3;
        i += 4;
    }
    for (; i < tailSize; ++i) {
        h ^= std::uint64_t(tail[i]) * Prime5;
        h = std::rotl(h, 11) * Prime1;
    }
    h ^= h >> 33;
    h *= Prime2;
    h ^= h >> 29;
    h *= Prime3;
    h ^= h >> 32;
    return h;
}

} // namespace

std::uint64_t xxh64(const void* data, std::size_t size, std::uint64_t seed)
{
    const auto* p = static_cast<const std::uint8_t*>(data);
    auto acc = initialAccumulators(seed);
    const std::size_t done = size >= 32 ? consumeStripes(acc, p, size) : 0;
    return finish(acc, seed, size, p + done, size - done);
}

Hash64::Hash64(std::uint64_t seed) : m_seed(seed), m_acc(initialAccumulators(seed)) {}

void Hash64::update(const void* data, std::size_t size)
{
    if (size == 0) return;
    const auto* p = static_cast<const std::uint8_t*>(data);
    m_length += size;
    if (m_buffered > 0) {
        const std::size_t take = std::min(size, m_buffer.size() - m_buffered);
        std::memcpy(m_buffer.data() + m_buffered, p, take);
        m_buffered += take;
        p += take;
        size -= take;
        if (m_buffered < m_buffer.size()) return;
        consumeStripes(m_acc, m_buffer.data(), m_buffer.size());
        m_buffered = 0;
    }
    const std::size_t done = consumeStripes(m_acc, p, size);
    if (done < size) {
        std::memcpy(m_buffer.data(), p + done, size - done);
        m_buffered = size - done;
    }
}

std::uint64_t Hash64::digest() const
{
    return finish(m_acc, m_seed, m_length, m_buffer.data(), m_buffered);
}

} // namespace stylos::core
