#include "document/commands/SetFragmentColourCommand.h"

namespace stylos::widgets {

SetFragmentColourCommand::SetFragmentColourCommand(SceneDocument& document, core::scene::FragmentId id,
                                                   core::scene::Rgb colour, QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_id(id), m_new(colour)
{
    const core::scene::Fragment* f = document.fragment(id);
    if (f) m_old = f->colour;
    setText(tr("Change the colour of %1").arg(f ? QString::fromStdString(f->name) : QString()));
}

void SetFragmentColourCommand::redo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.colour = m_new; });
}

void SetFragmentColourCommand::undo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.colour = m_old; });
}

} // namespace stylos::widgets
