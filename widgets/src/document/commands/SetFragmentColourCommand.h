#pragma once
/** @file
 * @brief Undo command: sets a fragment's display colour. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QCoreApplication>
#include "document/commands/DocumentCommand.h"

namespace stylos::widgets {

class SetFragmentColourCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::SetFragmentColourCommand)

public:
    /** Precondition: @p id is in the document's scene. */
    SetFragmentColourCommand(SceneDocument& document, core::scene::FragmentId id, core::scene::Rgb colour,
                             QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    core::scene::FragmentId m_id;
    core::scene::Rgb m_old;
    core::scene::Rgb m_new;
};

} // namespace stylos::widgets
