#include "document/commands/EditLabelsCommand.h"

#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <algorithm>

namespace stylos::widgets {

EditLabelsCommand::EditLabelsCommand(SceneDocument& document, LabelEdit edit, const CommandText& text, quint64 stroke,
                                     QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_stroke(stroke)
{
    m_edits.push_back(std::move(edit));
    setText(text);
}

void EditLabelsCommand::redo()
{
    for (const LabelEdit& edit : m_edits) m_document.labelStore().apply(edit, true);
}

void EditLabelsCommand::undo()
{
    for (auto it = m_edits.rbegin(); it != m_edits.rend(); ++it) m_document.labelStore().apply(*it, false);
}

bool EditLabelsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const EditLabelsCommand*>(other);
    if (!next || next->m_stroke == 0 || next->m_stroke != m_stroke) return false;
    for (const LabelEdit& later : next->m_edits) {
        const auto same = std::find_if(m_edits.begin(), m_edits.end(), [&later](const LabelEdit& e) {
            return e.fragment == later.fragment && e.layer == later.layer;
        });
        if (same != m_edits.end()) same->merge(later);
        else m_edits.push_back(later);
    }
    // An edit that came back to where it started holds nothing; keep one (edit() reads the first) while all are.
    std::erase_if(m_edits, [](const LabelEdit& e) { return e.empty(); });
    if (m_edits.empty()) {
        m_edits.emplace_back();
        m_edits.back().fragment = next->m_edits.front().fragment;
        m_edits.back().layer = next->m_edits.front().layer;
    }
    setObsolete(std::all_of(m_edits.begin(), m_edits.end(), [](const LabelEdit& e) { return e.empty(); }));
    return true;
}

} // namespace stylos::widgets
