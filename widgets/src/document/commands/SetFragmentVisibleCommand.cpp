#include "document/commands/SetFragmentVisibleCommand.h"

namespace stylos::widgets {

SetFragmentVisibleCommand::SetFragmentVisibleCommand(SceneDocument& document, core::scene::FragmentId id,
                                                     bool visible, QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_id(id), m_visible(visible)
{
    const core::scene::Fragment* f = document.fragment(id);
    const QString name = f ? QString::fromStdString(f->name) : QString();
    setText([this, name] {
        const QString current = m_document.nameOf(m_id, name);
        return m_visible ? tr("Show %1").arg(current) : tr("Hide %1").arg(current);
    });
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
