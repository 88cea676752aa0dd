#pragma once
/** @file
 * @brief XXH64, the 64-bit xxHash of Yann Collet: a fast non-cryptographic checksum, used for the
 *        sections of `.poct` files. Computed by Debian's libxxhash (linked privately to stylos_core);
 *        the digests are those of the published specification, golden values and the published test
 *        vectors in tests/core/Hash64Test.cpp. Several GB/s on one core.
 *        Pure functions and a small value type; thread-safe (one Hash64 object per thread).
 */
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

struct XXH64_state_s; // libxxhash's streaming state, opaque here

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
 *        continue after it). Copies hash on independently. Throws std::bad_alloc when the state
 *        cannot be allocated.
 */
class Hash64 {
public:
    explicit Hash64(std::uint64_t seed = 0);
    ~Hash64();
    Hash64(const Hash64& other);
    Hash64& operator=(const Hash64& other);
    Hash64(Hash64&& other) noexcept = default;
    Hash64& operator=(Hash64&& other) noexcept = default;

    /** @brief Appends @p size bytes at @p data (null allowed when @p size is 0). */
    void update(const void* data, std::size_t size);
    void update(std::span<const std::uint8_t> bytes) { update(bytes.data(), bytes.size()); }

    /** @brief XXH64 of everything appended so far. */
    std::uint64_t digest() const;

    /** @brief Bytes appended so far. */
    std::uint64_t length() const { return m_length; }

private:
    struct FreeState {
        void operator()(XXH64_state_s* state) const;
    };
    std::unique_ptr<XXH64_state_s, FreeState> m_state;
    std::uint64_t m_length = 0;
};

} // namespace stylos::core
