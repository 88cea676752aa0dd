#include "document/commands/SetFragmentGuidesCommand.h"

namespace stylos::widgets {

SetFragmentGuidesCommand::SetFragmentGuidesCommand(SceneDocument& document, core::scene::FragmentId id,
                                                   std::vector<core::scene::Guide> guides, const QString& text,
                                                   QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_id(id), m_new(std::move(guides))
{
    const core::scene::Fragment* f = document.fragment(id);
    if (f) m_old = f->guides;
    setText(text.isEmpty() ? tr("Change the guides of %1").arg(f ? QString::fromStdString(f->name) : QString()) : text);
}

void SetFragmentGuidesCommand::redo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.guides = m_new; });
}

void SetFragmentGuidesCommand::undo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.guides = m_old; });
}

} // namespace stylos::widgets
