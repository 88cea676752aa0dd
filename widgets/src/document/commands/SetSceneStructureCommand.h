#pragma once
/** @file
 * @brief Undo command for every assembly edit: new assembly, remove, rename, move fragments in or out,
 *        the assembly's pose, drum or visibility. It keeps the scene's structure before and after — the
 *        assemblies and, for the fragments it touches, their assembly and pose — and swaps them (the
 *        fragments keep their place in the scene when they change assembly: their pose is re-expressed).
 *        GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include "document/commands/DocumentCommand.h"

#include <map>
#include <utility>
#include <vector>

namespace stylos::widgets {

/** @brief The part of a scene an assembly edit changes. */
struct SceneStructure {
    std::vector<core::scene::Assembly> assemblies;
    core::scene::AssemblyId nextAssemblyId = 1;
    /** Per touched fragment: its assembly and its pose (relative to it). */
    std::map<core::scene::FragmentId, std::pair<std::uint64_t, core::scene::Pose>> fragments;

    /** The structure of @p scene for the fragments @p touched. */
    static SceneStructure of(const core::scene::Scene& scene, const std::vector<core::scene::FragmentId>& touched);
};

class SetSceneStructureCommand : public DocumentCommand {
public:
    SetSceneStructureCommand(SceneDocument& document, SceneStructure before, SceneStructure after, const CommandText& text,
                             QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    SceneStructure m_before;
    SceneStructure m_after;
};

} // namespace stylos::widgets
