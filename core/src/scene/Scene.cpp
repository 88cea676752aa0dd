#include "stylos/core/scene/Scene.h"

#include <algorithm>

namespace stylos::core::scene {

bool Scene::setNextId(FragmentId id)
{
    if (id == NoFragment) return false;
    for (const Fragment& f : m_fragments)
        if (f.id >= id) return false;
    m_nextId = id;
    return true;
}

FragmentId Scene::insert(std::size_t index, Fragment fragment)
{
    if (fragment.id == NoFragment) fragment.id = allocateId();
    else if (find(fragment.id)) return NoFragment;
    m_nextId = std::max(m_nextId, fragment.id + 1);
    const FragmentId id = fragment.id;
    index = std::min(index, m_fragments.size());
    m_fragments.insert(m_fragments.begin() + static_cast<std::ptrdiff_t>(index), std::move(fragment));
    return id;
}

std::optional<Fragment> Scene::take(FragmentId id)
{
    const auto at = indexOf(id);
    if (!at) return std::nullopt;
    auto it = m_fragments.begin() + static_cast<std::ptrdiff_t>(*at);
    Fragment fragment = std::move(*it);
    m_fragments.erase(it);
    return fragment;
}

const Fragment* Scene::find(FragmentId id) const
{
    const auto at = indexOf(id);
    return at ? &m_fragments[*at] : nullptr;
}

Fragment* Scene::find(FragmentId id)
{
    const auto at = indexOf(id);
    return at ? &m_fragments[*at] : nullptr;
}

std::optional<std::size_t> Scene::indexOf(FragmentId id) const
{
    if (id == NoFragment) return std::nullopt;
    for (std::size_t i = 0; i < m_fragments.size(); ++i)
        if (m_fragments[i].id == id) return i;
    return std::nullopt;
}

} // namespace stylos::core::scene
