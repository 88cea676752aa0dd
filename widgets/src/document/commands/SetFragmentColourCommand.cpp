#include "document/commands/SetFragmentColourCommand.h"

namespace stylos::widgets {

SetFragmentColourCommand::SetFragmentColourCommand(SceneDocument& document, core::scene::FragmentId id,
                                                   core::scene::Rgb colour, QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_id(id), m_new(colour)
{
    const core::scene::Fragment* f = document.fragment(id);
    if (f) m_old = f->colour;
    const QString name = f ? QString::fromStdString(f->name) : QString();
    setText([this, name] { return tr("Change the colour of %1").arg(m_document.nameOf(m_id, name)); });
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
