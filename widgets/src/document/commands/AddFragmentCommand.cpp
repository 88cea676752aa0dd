#include "document/commands/AddFragmentCommand.h"

namespace stylos::widgets {

AddFragmentCommand::AddFragmentCommand(SceneDocument& document, core::scene::Fragment fragment,
                                       SceneDocument::OctreePtr octree, const CommandText& text, QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_fragment(std::move(fragment)), m_octree(std::move(octree))
{
    if (m_fragment.id == core::scene::NoFragment) m_fragment.id = m_document.allocateId();
    if (text.isEmpty())
        setText([this, name = QString::fromStdString(m_fragment.name)] {
            return tr("Add %1").arg(m_document.nameOf(m_fragment.id, name));
        });
    else
        setText(text);
}

AddFragmentCommand::~AddFragmentCommand()
{
    // Undone (this step's own state: a fragment removed later by another step is not an undone import).
    if (m_index >= 0 && !m_applied) m_document.releaseOctree(m_fragment.octreePath);
}

void AddFragmentCommand::redo()
{
    if (m_index < 0) m_index = static_cast<int>(m_document.scene().size());
    m_document.insertFragment(m_index, m_fragment, m_octree);
    m_octree.reset(); // the document holds it now
    m_applied = true;
}

void AddFragmentCommand::undo()
{
    auto [fragment, octree] = m_document.takeFragment(m_fragment.id);
    m_fragment = std::move(fragment);
    m_octree = std::move(octree);
    m_applied = false;
}

} // namespace stylos::widgets
