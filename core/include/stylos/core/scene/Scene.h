#pragma once
/** @file
 * @brief The scene, a graph of two levels: assemblies, and fragments in display order, each fragment at
 *        the top level or in one assembly (Fragment::assembly), its pose relative to that assembly
 *        (worldPose() composes them). Ids are handed out by the scene from nextId() / nextAssemblyId() and
 *        never reused, even after a removal, so references (undo commands, annotations, an assembly's
 *        drum) stay valid. Plain data, no Qt; the widgets layer's SceneDocument owns one and changes it
 *        through undo commands. Invariant: every fragment's assembly exists (or is NoAssembly).
 *        Thread-safety: none (a value type; confine to one thread or copy).
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/plate/PlateSpec.h"
#include "stylos/core/scene/Assembly.h"
#include "stylos/core/scene/Fragment.h"

#include <cstddef>
#include <optional>
#include <string>
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
     *        NoFragment gets allocateId(); one with an id keeps it and nextId() moves above it. A fragment
     *        naming an assembly that does not exist goes to the top level (its pose kept as it is).
     * @return the fragment's id, or NoFragment (nothing inserted) when its id is already in the scene.
     */
    FragmentId insert(std::size_t index, Fragment fragment);
    /** @brief Removes the fragment and returns it; nullopt when there is none with @p id. */
    std::optional<Fragment> take(FragmentId id);
    /** @brief Removes the fragment; false when there is none with @p id. */
    bool remove(FragmentId id) { return take(id).has_value(); }
    /** @brief Removes every fragment and assembly (the docking drum too); the next ids are kept (ids are never
     *  reused). */
    void clear()
    {
        m_fragments.clear();
        m_assemblies.clear();
        m_dockingDrum = NoFragment;
    }

    /** @brief The fragment with @p id, or nullptr. Pointers are invalidated by insert and take. */
    const Fragment* find(FragmentId id) const;
    Fragment* find(FragmentId id);
    /** @brief Position of the fragment with @p id in display order. */
    std::optional<std::size_t> indexOf(FragmentId id) const;

    // Assemblies.
    const std::vector<Assembly>& assemblies() const { return m_assemblies; }
    AssemblyId nextAssemblyId() const { return m_nextAssemblyId; }
    /** @brief Sets the next assembly id; false (nothing changed) when not above every assembly's id. */
    bool setNextAssemblyId(AssemblyId id);
    /** @brief Inserts @p assembly before position @p index (clamped); an id of NoAssembly gets the next
     *  one. Returns its id, or NoAssembly (nothing inserted) when the id is already used. */
    AssemblyId insertAssembly(std::size_t index, Assembly assembly);
    AssemblyId addAssembly(Assembly assembly) { return insertAssembly(m_assemblies.size(), std::move(assembly)); }
    /** @brief Replaces every assembly (order and values) and the next assembly id (raised above their ids
     *  when needed); a fragment whose assembly is no longer there goes to the top level, in place. */
    void setAssemblies(std::vector<Assembly> assemblies, AssemblyId nextAssemblyId);
    /** @brief Removes the assembly and returns it; its members move to the top level keeping their
     *  place in the scene (their pose composed with the assembly's). nullopt when there is none. */
    std::optional<Assembly> takeAssembly(AssemblyId id);
    const Assembly* findAssembly(AssemblyId id) const;
    Assembly* findAssembly(AssemblyId id);
    std::optional<std::size_t> assemblyIndexOf(AssemblyId id) const;
    /** @brief The members of assembly @p id in display order (the top level's for NoAssembly). */
    std::vector<FragmentId> membersOf(AssemblyId id) const;
    /** @brief Moves fragment @p id into assembly @p assembly (NoAssembly: the top level), its place in the
     *  scene kept (its pose re-expressed in the new frame). False when either does not exist. */
    bool moveToAssembly(FragmentId id, AssemblyId assembly);
    /** @brief Fragment frame → scene frame: its assembly's pose composed with its own. Identity when none. */
    Pose worldPose(FragmentId id) const;
    /** @brief The pose, relative to fragment @p id's assembly, that puts it at @p world in the scene. */
    Pose localPose(FragmentId id, const Pose& world) const;

    /**
     * @brief The drum that fragments outside an assembly with a drum dock against (Fragment › Dock against this
     *        drum): its guides place them, and a fragment without an axis guide of its own unrolls about its
     *        axis (unrollAxisOwner). NoFragment when none; taking that fragment out unsets it. Saved in the
     *        project, so that a reopened project unrolls and plates its fragments as they were painted.
     */
    FragmentId dockingDrum() const { return m_dockingDrum; }
    /** @brief Sets the docking drum (NoFragment: none); false, nothing changed, for an id not in the scene. */
    bool setDockingDrum(FragmentId id);

    /** @brief The project's annotation legend (its classes, colours and hatches); the default vocabulary
     *  until changed. clear() keeps it. */
    const annotation::Legend& legend() const { return m_legend; }
    void setLegend(annotation::Legend legend) { m_legend = std::move(legend); }

    /** @brief The plate last exported (File › Export plate…), kept so the figure can be made again; none
     *  until one is. clear() keeps it. */
    const std::optional<plate::PlateSpec>& plate() const { return m_plate; }
    void setPlate(std::optional<plate::PlateSpec> plate) { m_plate = std::move(plate); }

    /** @brief A "plate" section of the project file that this version could not read (a misspelt key, a
     *  later version's layout), as JSON text: written back (same keys and values) whenever the scene has no
     *  plate, so opening and saving a project never loses it — a plate set and undone included. Empty when
     *  there is none. */
    const std::string& unreadPlate() const { return m_unreadPlate; }
    void setUnreadPlate(std::string json) { m_unreadPlate = std::move(json); }

    bool operator==(const Scene&) const = default;

private:
    std::vector<Fragment> m_fragments;
    std::vector<Assembly> m_assemblies;
    FragmentId m_nextId = 1;
    AssemblyId m_nextAssemblyId = 1;
    FragmentId m_dockingDrum = NoFragment;
    annotation::Legend m_legend = annotation::Legend::defaults();
    std::optional<plate::PlateSpec> m_plate;
    std::string m_unreadPlate;
};

} // namespace stylos::core::scene
