#pragma once
/** @file
 * @brief Undo command: renames a fragment. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QCoreApplication>
#include "document/commands/DocumentCommand.h"

#include <string>

namespace stylos::widgets {

class RenameFragmentCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::RenameFragmentCommand)

public:
    /** Precondition: @p id is in the document's scene. */
    RenameFragmentCommand(SceneDocument& document, core::scene::FragmentId id, const QString& name,
                          QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    core::scene::FragmentId m_id;
    std::string m_old;
    std::string m_new;
};

} // namespace stylos::widgets
