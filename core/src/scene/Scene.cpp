#include "stylos/core/scene/Scene.h"
#include "stylos/core/scene/SceneEigen.h"

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
    if (fragment.assembly != NoAssembly && !findAssembly(fragment.assembly)) fragment.assembly = NoAssembly;
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
    if (id == m_dockingDrum) m_dockingDrum = NoFragment;
    return fragment;
}

bool Scene::setDockingDrum(FragmentId id)
{
    if (id != NoFragment && !find(id)) return false;
    m_dockingDrum = id;
    return true;
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

bool Scene::setNextAssemblyId(AssemblyId id)
{
    if (id == NoAssembly) return false;
    for (const Assembly& a : m_assemblies)
        if (a.id >= id) return false;
    m_nextAssemblyId = id;
    return true;
}

AssemblyId Scene::insertAssembly(std::size_t index, Assembly assembly)
{
    if (assembly.id == NoAssembly) assembly.id = m_nextAssemblyId++;
    else if (findAssembly(assembly.id)) return NoAssembly;
    m_nextAssemblyId = std::max(m_nextAssemblyId, assembly.id + 1);
    const AssemblyId id = assembly.id;
    index = std::min(index, m_assemblies.size());
    m_assemblies.insert(m_assemblies.begin() + static_cast<std::ptrdiff_t>(index), std::move(assembly));
    return id;
}

void Scene::setAssemblies(std::vector<Assembly> assemblies, AssemblyId nextAssemblyId)
{
    for (Fragment& f : m_fragments) {
        if (f.assembly == NoAssembly) continue;
        const bool kept = std::any_of(assemblies.begin(), assemblies.end(), [&f](const Assembly& a) { return a.id == f.assembly; });
        if (kept) continue;
        f.pose = worldPose(f.id);
        f.assembly = NoAssembly;
    }
    m_assemblies = std::move(assemblies);
    m_nextAssemblyId = std::max<AssemblyId>(nextAssemblyId, 1);
    for (const Assembly& a : m_assemblies) m_nextAssemblyId = std::max(m_nextAssemblyId, a.id + 1);
}

std::optional<Assembly> Scene::takeAssembly(AssemblyId id)
{
    const auto at = assemblyIndexOf(id);
    if (!at) return std::nullopt;
    for (Fragment& f : m_fragments)
        if (f.assembly == id) {
            f.pose = m_assemblies[*at].pose * f.pose;
            f.assembly = NoAssembly;
        }
    Assembly assembly = std::move(m_assemblies[*at]);
    m_assemblies.erase(m_assemblies.begin() + static_cast<std::ptrdiff_t>(*at));
    return assembly;
}

const Assembly* Scene::findAssembly(AssemblyId id) const
{
    const auto at = assemblyIndexOf(id);
    return at ? &m_assemblies[*at] : nullptr;
}

Assembly* Scene::findAssembly(AssemblyId id)
{
    const auto at = assemblyIndexOf(id);
    return at ? &m_assemblies[*at] : nullptr;
}

std::optional<std::size_t> Scene::assemblyIndexOf(AssemblyId id) const
{
    if (id == NoAssembly) return std::nullopt;
    for (std::size_t i = 0; i < m_assemblies.size(); ++i)
        if (m_assemblies[i].id == id) return i;
    return std::nullopt;
}

std::vector<FragmentId> Scene::membersOf(AssemblyId id) const
{
    std::vector<FragmentId> members;
    for (const Fragment& f : m_fragments)
        if (f.assembly == id) members.push_back(f.id);
    return members;
}

bool Scene::moveToAssembly(FragmentId id, AssemblyId assembly)
{
    Fragment* f = find(id);
    if (!f || (assembly != NoAssembly && !findAssembly(assembly))) return false;
    if (f->assembly == assembly) return true;
    const Pose world = worldPose(id);
    f->assembly = assembly;
    f->pose = localPose(id, world);
    return true;
}

Pose Scene::worldPose(FragmentId id) const
{
    const Fragment* f = find(id);
    if (!f) return {};
    const Assembly* a = findAssembly(f->assembly);
    return a ? a->pose * f->pose : f->pose;
}

Pose Scene::localPose(FragmentId id, const Pose& world) const
{
    const Fragment* f = find(id);
    const Assembly* a = f ? findAssembly(f->assembly) : nullptr;
    return a ? a->pose.rigidInverse() * world : world;
}

FragmentId drumFor(const Scene& scene, FragmentId fragment)
{
    const Fragment* f = scene.find(fragment);
    const Assembly* a = f ? scene.findAssembly(f->assembly) : nullptr;
    return a && a->drum != NoFragment ? a->drum : scene.dockingDrum();
}

FragmentId unrollAxisOwner(const Scene& scene, FragmentId fragment, FragmentId drum)
{
    const Fragment* f = scene.find(fragment);
    if (!f) return NoFragment;
    if (firstGuide(*f, GuideKind::Axis)) return fragment;
    const Fragment* d = drum != fragment ? scene.find(drum) : nullptr;
    return d && firstGuide(*d, GuideKind::Axis) ? drum : NoFragment;
}

std::optional<GuideLine> unrollAxis(const Scene& scene, FragmentId fragment, FragmentId drum)
{
    const FragmentId owner = unrollAxisOwner(scene, fragment, drum);
    if (owner == NoFragment) return std::nullopt;
    const auto line = firstGuide(*scene.find(owner), GuideKind::Axis);
    if (owner == fragment) return line;
    const Eigen::Matrix4d m = toEigen(scene.worldPose(fragment).rigidInverse() * scene.worldPose(owner));
    return GuideLine{m.topLeftCorner<3, 3>() * line->origin + m.topRightCorner<3, 1>(),
                     (m.topLeftCorner<3, 3>() * line->direction).normalized()};
}

} // namespace stylos::core::scene
