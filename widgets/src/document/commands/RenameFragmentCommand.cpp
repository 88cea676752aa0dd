#include "document/commands/RenameFragmentCommand.h"

namespace stylos::widgets {

RenameFragmentCommand::RenameFragmentCommand(SceneDocument& document, core::scene::FragmentId id,
                                             const QString& name, QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_id(id), m_new(name.toStdString())
{
    if (const core::scene::Fragment* f = document.fragment(id)) m_old = f->name;
    setText([this] { return tr("Rename %1 to %2").arg(QString::fromStdString(m_old), QString::fromStdString(m_new)); });
}

void RenameFragmentCommand::redo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.name = m_new; });
}

void RenameFragmentCommand::undo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.name = m_old; });
}

} // namespace stylos::widgets
