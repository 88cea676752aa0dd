#include "document/commands/SetFragmentGuidesCommand.h"

namespace stylos::widgets {

SetFragmentGuidesCommand::SetFragmentGuidesCommand(SceneDocument& document, core::scene::FragmentId id,
                                                   std::vector<core::scene::Guide> guides, const CommandText& text,
                                                   QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_id(id), m_new(std::move(guides))
{
    const core::scene::Fragment* f = document.fragment(id);
    if (f) m_old = f->guides;
    const QString name = f ? QString::fromStdString(f->name) : QString();
    if (text.isEmpty())
        setText([this, name] { return tr("Change the guides of %1").arg(m_document.nameOf(m_id, name)); });
    else
        setText(text);
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
