#include "document/commands/AddFragmentCommand.h"

namespace stylos::widgets {

AddFragmentCommand::AddFragmentCommand(SceneDocument& document, core::scene::Fragment fragment,
                                       SceneDocument::OctreePtr octree, const QString& text, QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_fragment(std::move(fragment)), m_octree(std::move(octree))
{
    if (m_fragment.id == core::scene::NoFragment) m_fragment.id = m_document.allocateId();
    setText(text.isEmpty() ? tr("Add %1").arg(QString::fromStdString(m_fragment.name)) : text);
}

void AddFragmentCommand::redo()
{
    if (m_index < 0) m_index = static_cast<int>(m_document.scene().size());
    m_document.insertFragment(m_index, m_fragment, m_octree);
    m_octree.reset(); // the document holds it now
}

void AddFragmentCommand::undo()
{
    auto [fragment, octree] = m_document.takeFragment(m_fragment.id);
    m_fragment = std::move(fragment);
    m_octree = std::move(octree);
}

} // namespace stylos::widgets
