#pragma once
/** @file
 * @brief Undo command: changes annotation labels of one fragment's layer (a brush dab, a fill, a lasso).
 *        It holds only the leaves it changes (LabelEdit). Dabs of one stroke merge: a command made with a
 *        non-zero `stroke` token (SceneDocument::beginStroke()) merges into the previous label command of the
 *        same stroke, fragment and layer, so a whole stroke is one undo step (and disappears when it changes nothing). GUI thread only.
 */
#include "document/commands/DocumentCommand.h"
#include "stylos/widgets/annotation/LabelEdit.h"

#include <QCoreApplication>

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

    /** @brief The leaves this step changes (for tests: an undo step stores only what it changed). */
    const LabelEdit& edit() const { return m_edit; }

private:
    SceneDocument& m_document;
    LabelEdit m_edit;
    quint64 m_stroke; ///< 0: a step of its own
};

} // namespace stylos::widgets
