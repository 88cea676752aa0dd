#include "document/commands/RemoveFragmentCommand.h"

namespace stylos::widgets {

RemoveFragmentCommand::RemoveFragmentCommand(SceneDocument& document, core::scene::FragmentId id,
                                             QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_id(id),
      m_index(static_cast<int>(document.scene().indexOf(id).value_or(document.scene().size())))
{
    const core::scene::Fragment* f = document.fragment(id);
    const QString name = f ? QString::fromStdString(f->name) : QString();
    setText([this, name] { return tr("Remove %1").arg(m_document.nameOf(m_id, name)); });
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
