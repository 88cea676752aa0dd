#include "document/commands/EditLabelsCommand.h"

#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/document/SceneDocument.h"

namespace stylos::widgets {

EditLabelsCommand::EditLabelsCommand(SceneDocument& document, LabelEdit edit, const CommandText& text, quint64 stroke,
                                     QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_edit(std::move(edit)), m_stroke(stroke)
{
    setText(text);
}

void EditLabelsCommand::redo()
{
    m_document.labelStore().apply(m_edit, true);
}

void EditLabelsCommand::undo()
{
    m_document.labelStore().apply(m_edit, false);
}

bool EditLabelsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const EditLabelsCommand*>(other);
    if (!next || next->m_stroke == 0 || next->m_stroke != m_stroke || next->m_edit.fragment != m_edit.fragment || next->m_edit.layer != m_edit.layer)
        return false;
    m_edit.merge(next->m_edit);
    setObsolete(m_edit.empty());
    return true;
}

} // namespace stylos::widgets
