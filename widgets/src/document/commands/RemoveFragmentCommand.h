#pragma once
/** @file
 * @brief Undo command: removes a fragment from a SceneDocument, keeping it (and its opened octree) so
 *        that undo puts it back, same id, same position, same state. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QCoreApplication>
#include "document/commands/DocumentCommand.h"

namespace stylos::widgets {

class RemoveFragmentCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::RemoveFragmentCommand)

public:
    /** Precondition: @p id is in the document's scene. */
    RemoveFragmentCommand(SceneDocument& document, core::scene::FragmentId id, QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    core::scene::FragmentId m_id;
    int m_index;
    core::scene::Fragment m_fragment;  ///< held while removed
    SceneDocument::OctreePtr m_octree;
};

} // namespace stylos::widgets
