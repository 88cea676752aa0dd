#include "document/commands/SetLegendCommand.h"

#include "stylos/widgets/document/SceneDocument.h"

namespace stylos::widgets {

SetLegendCommand::SetLegendCommand(SceneDocument& document, core::annotation::Legend legend, const CommandText& text,
                                   QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_old(document.scene().legend()), m_new(std::move(legend))
{
    setText(text);
}

void SetLegendCommand::redo()
{
    m_document.changeLegend(m_new);
}

void SetLegendCommand::undo()
{
    m_document.changeLegend(m_old);
}

} // namespace stylos::widgets
