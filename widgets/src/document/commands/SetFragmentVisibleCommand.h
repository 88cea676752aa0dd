#pragma once
/** @file
 * @brief Undo command: shows or hides a fragment. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QCoreApplication>
#include "document/commands/DocumentCommand.h"

namespace stylos::widgets {

class SetFragmentVisibleCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::SetFragmentVisibleCommand)

public:
    /** Precondition: @p id is in the document's scene. */
    SetFragmentVisibleCommand(SceneDocument& document, core::scene::FragmentId id, bool visible,
                              QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    core::scene::FragmentId m_id;
    bool m_visible;
};

} // namespace stylos::widgets
