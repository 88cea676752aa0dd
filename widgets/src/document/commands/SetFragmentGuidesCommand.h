#pragma once
/** @file
 * @brief Undo command: replaces a fragment's guides (its axis and flute lines, in its own frame, metres) —
 *        fitted on a drum, edited or deleted. The project file saves them. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QCoreApplication>
#include "document/commands/DocumentCommand.h"

#include <vector>

namespace stylos::widgets {

class SetFragmentGuidesCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::SetFragmentGuidesCommand)

public:
    /** Precondition: @p id is in the document's scene. @p text names the step; default "Change the guides of NAME". */
    SetFragmentGuidesCommand(SceneDocument& document, core::scene::FragmentId id, std::vector<core::scene::Guide> guides,
                             const CommandText& text = {}, QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    core::scene::FragmentId m_id;
    std::vector<core::scene::Guide> m_old;
    std::vector<core::scene::Guide> m_new;
};

} // namespace stylos::widgets
