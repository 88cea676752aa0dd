#include "document/commands/RemoveFragmentCommand.h"

namespace stylos::widgets {

RemoveFragmentCommand::RemoveFragmentCommand(SceneDocument& document, core::scene::FragmentId id,
                                             QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_id(id),
      m_index(static_cast<int>(document.scene().indexOf(id).value_or(document.scene().size())))
{
    const core::scene::Fragment* f = document.fragment(id);
    setText(tr("Remove %1").arg(f ? QString::fromStdString(f->name) : QString()));
}

void RemoveFragmentCommand::redo()
{
    auto [fragment, octree] = m_document.takeFragment(m_id);
    m_fragment = std::move(fragment);
    m_octree = std::move(octree);
}

void RemoveFragmentCommand::undo()
{
    m_document.insertFragment(m_index, m_fragment, m_octree);
    m_octree.reset();
}

} // namespace stylos::widgets
