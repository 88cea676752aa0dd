#include "document/commands/SetPlateCommand.h"

#include "stylos/widgets/document/SceneDocument.h"

namespace stylos::widgets {

SetPlateCommand::SetPlateCommand(SceneDocument& document, std::optional<core::plate::PlateSpec> plate,
                                 const CommandText& text, QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_old(document.scene().plate()), m_new(std::move(plate))
{
    setText(text);
}

void SetPlateCommand::redo()
{
    m_document.changePlate(m_new);
}

void SetPlateCommand::undo()
{
    m_document.changePlate(m_old);
}

} // namespace stylos::widgets
