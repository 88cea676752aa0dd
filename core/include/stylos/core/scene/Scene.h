#pragma once
/** @file
 * @brief The scene: fragments in display order, each with a stable id. Ids are handed out by the scene
 *        from nextId() and never reused, even after a removal, so references to a fragment (undo
 *        commands, annotations, guides of another fragment) stay valid. Plain data, no Qt; the widgets
 *        layer's SceneDocument owns one and changes it through undo commands.
 *        Thread-safety: none (a value type; confine to one thread or copy).
 */
#include "stylos/core/scene/Fragment.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace stylos::core::scene {

class Scene {
public:
    /** @brief The fragments in display order. */
    const std::vector<Fragment>& fragments() const { return m_fragments; }
    std::size_t size() const { return m_fragments.size(); }
    bool empty() const { return m_fragments.empty(); }

    /** @brief The id the next added fragment without one will get (≥ 1, above every id ever used). */
    FragmentId nextId() const { return m_nextId; }
    /** @brief Takes the next id for a fragment that will be added later (an undo command keeps it). */
    FragmentId allocateId() { return m_nextId++; }
    /**
     * @brief Sets the next id (the project file stores it). Returns false and changes nothing when
     *        @p id is not above every fragment's id.
     */
    bool setNextId(FragmentId id);

    /** @brief Appends @p fragment; see insert(). */
    FragmentId add(Fragment fragment) { return insert(m_fragments.size(), std::move(fragment)); }
    /**
     * @brief Inserts @p fragment before position @p index (clamped to size()). A fragment with id
     *        NoFragment gets allocateId(); one with an id keeps it and nextId() moves above it.
     * @return the fragment's id, or NoFragment (nothing inserted) when its id is already in the scene.
     */
    FragmentId insert(std::size_t index, Fragment fragment);
    /** @brief Removes the fragment and returns it; nullopt when there is none with @p id. */
    std::optional<Fragment> take(FragmentId id);
    /** @brief Removes the fragment; false when there is none with @p id. */
    bool remove(FragmentId id) { return take(id).has_value(); }
    /** @brief Removes every fragment; nextId() is kept (ids are never reused). */
    void clear() { m_fragments.clear(); }

    /** @brief The fragment with @p id, or nullptr. Pointers are invalidated by insert and take. */
    const Fragment* find(FragmentId id) const;
    Fragment* find(FragmentId id);
    /** @brief Position of the fragment with @p id in display order. */
    std::optional<std::size_t> indexOf(FragmentId id) const;

    bool operator==(const Scene&) const = default;

private:
    std::vector<Fragment> m_fragments;
    FragmentId m_nextId = 1;
};

} // namespace stylos::core::scene
