#include "document/commands/SetFragmentVisibleCommand.h"

namespace stylos::widgets {

SetFragmentVisibleCommand::SetFragmentVisibleCommand(SceneDocument& document, core::scene::FragmentId id,
                                                     bool visible, QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_id(id), m_visible(visible)
{
    const core::scene::Fragment* f = document.fragment(id);
    const QString name = f ? QString::fromStdString(f->name) : QString();
    setText(visible ? tr("Show %1").arg(name) : tr("Hide %1").arg(name));
}

void SetFragmentVisibleCommand::redo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.visible = m_visible; });
}

void SetFragmentVisibleCommand::undo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.visible = !m_visible; });
}

} // namespace stylos::widgets
