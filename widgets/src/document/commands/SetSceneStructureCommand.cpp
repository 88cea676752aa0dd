#include "document/commands/SetSceneStructureCommand.h"

namespace stylos::widgets {

SceneStructure SceneStructure::of(const core::scene::Scene& scene, const std::vector<core::scene::FragmentId>& touched)
{
    SceneStructure s;
    s.assemblies = scene.assemblies();
    s.nextAssemblyId = scene.nextAssemblyId();
    for (core::scene::FragmentId id : touched)
        if (const core::scene::Fragment* f = scene.find(id)) s.fragments[id] = {f->assembly, f->pose};
    return s;
}

SetSceneStructureCommand::SetSceneStructureCommand(SceneDocument& document, SceneStructure before, SceneStructure after,
                                                   const CommandText& text, QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void SetSceneStructureCommand::redo()
{
    m_document.applyStructure(m_after);
}

void SetSceneStructureCommand::undo()
{
    m_document.applyStructure(m_before);
}

} // namespace stylos::widgets
