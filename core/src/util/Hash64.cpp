#include "stylos/core/util/Hash64.h"

#include <xxhash.h>

#include <cassert>
#include <new>

namespace stylos::core {

namespace {

XXH64_state_t* newState()
{
    XXH64_state_t* state = XXH64_createState();
    if (!state) throw std::bad_alloc();
    return state;
}

} // namespace

std::uint64_t xxh64(const void* data, std::size_t size, std::uint64_t seed)
{
    assert((data || size == 0) && "xxh64(): null data with a non-zero size");
    return XXH64(data, size, seed);
}

void Hash64::FreeState::operator()(XXH64_state_s* state) const
{
    XXH64_freeState(state);
}

Hash64::Hash64(std::uint64_t seed) : m_state(newState())
{
    XXH64_reset(m_state.get(), seed);
}

Hash64::~Hash64() = default;

Hash64::Hash64(const Hash64& other) : m_state(newState()), m_length(other.m_length)
{
    XXH64_copyState(m_state.get(), other.m_state.get());
}

Hash64& Hash64::operator=(const Hash64& other)
{
    if (this != &other) {
        if (!m_state) m_state.reset(newState());
        XXH64_copyState(m_state.get(), other.m_state.get());
        m_length = other.m_length;
    }
    return *this;
}

void Hash64::update(const void* data, std::size_t size)
{
    assert(m_state && "Hash64::update(): the hash was moved from");
    if (size == 0) return;
    XXH64_update(m_state.get(), data, size);
    m_length += size;
}

std::uint64_t Hash64::digest() const
{
    assert(m_state && "Hash64::digest(): the hash was moved from");
    return XXH64_digest(m_state.get());
}

} // namespace stylos::core
