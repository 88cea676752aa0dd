#pragma once
/** @file
 * @brief XXH64, the 64-bit xxHash of Yann Collet (published specification, "xxHash fast digest
 *        algorithm", version 0.1.1): a fast non-cryptographic checksum, used for the sections of
 *        `.poct` files. Implemented here from the specification; agrees with the reference on its
 *        published test vectors (tests/core/Hash64Test.cpp). Several GB/s on one core.
 *        Pure functions and a small value type; thread-safe (one Hash64 object per thread).
 */
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace stylos::core {

/** @brief XXH64 of @p size bytes at @p data with @p seed. @p data may be null when @p size is 0. */
std::uint64_t xxh64(const void* data, std::size_t size, std::uint64_t seed = 0);

/** @brief XXH64 of a byte span. */
inline std::uint64_t xxh64(std::span<const std::uint8_t> bytes, std::uint64_t seed = 0)
{
    return xxh64(bytes.data(), bytes.size(), seed);
}

/**
 * @brief Incremental XXH64: feed the input in pieces of any size with update(); digest() gives the
 *        same value as xxh64() of the concatenation (and may be called at any point; update() may
 *        continue after it).
 */
class Hash64 {
public:
    explicit Hash64(std::uint64_t seed = 0);

    /** @brief Appends @p size bytes at @p data (null allowed when @p size is 0). */
    void update(const void* data, std::size_t size);
    void update(std::span<const std::uint8_t> bytes) { update(bytes.data(), bytes.size()); }

    /** @brief XXH64 of everything appended so far. */
    std::uint64_t digest() const;

    /** @brief Bytes appended so far. */
    std::uint64_t length() const { return m_length; }

private:
    std::uint64_t m_seed;
    std::array<std::uint64_t, 4> m_acc;
    std::array<std::uint8_t, 32> m_buffer{};
    std::size_t m_buffered = 0;
    std::uint64_t m_length = 0;
};

} // namespace stylos::core
