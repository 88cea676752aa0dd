#pragma once
/** @file
 * @brief Undo command: changes annotation labels (a brush dab, a fill, a lasso). It holds only the leaves it
 *        changes (LabelEdit), per fragment and layer. Dabs of one stroke merge: a command made with a non-zero
 *        `stroke` token (SceneDocument::beginStroke()) merges into the previous label command of the same stroke —
 *        of the same fragment and layer into its edit, of another (a stroke across the drum and a fragment on an
 *        assembly's développée) as one more edit — so a whole stroke is one undo step, whatever it labels (and
 *        disappears when it changes nothing). Redo applies the edits in order, undo in reverse. GUI thread only.
 */
#include "document/commands/DocumentCommand.h"
#include "stylos/widgets/annotation/LabelEdit.h"

#include <QCoreApplication>

#include <vector>

namespace stylos::widgets {

class SceneDocument;

class EditLabelsCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::EditLabelsCommand)

public:
    /** @brief The QUndoCommand::id() of label commands (merging). */
    static constexpr int CommandId = 0x4c42;

    /** Precondition: @p edit was made from the document's current labels. */
    EditLabelsCommand(SceneDocument& document, LabelEdit edit, const CommandText& text, quint64 stroke = 0,
                      QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return CommandId; }
    bool mergeWith(const QUndoCommand* other) override;

    /** @brief The leaves this step changes in its first fragment (for tests: a step stores only what it changed). */
    const LabelEdit& edit() const { return m_edits.front(); }
    /** @brief Every fragment's and layer's edit of this step (one per fragment and layer, never empty). */
    const std::vector<LabelEdit>& edits() const { return m_edits; }

private:
    SceneDocument& m_document;
    std::vector<LabelEdit> m_edits; ///< at least one; distinct (fragment, layer)
    quint64 m_stroke; ///< 0: a step of its own
};

} // namespace stylos::widgets
