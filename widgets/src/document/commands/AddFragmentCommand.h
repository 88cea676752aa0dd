#pragma once
/** @file
 * @brief Undo command: adds a fragment (with its opened octree, if any) to a SceneDocument. The fragment's
 *        id is allocated when the command is made and kept through undo and redo; redo puts it back at
 *        the same position. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QCoreApplication>
#include "document/commands/DocumentCommand.h"

namespace stylos::widgets {

class AddFragmentCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::AddFragmentCommand)

public:
    /** @p text names the step; empty: "Add NAME". */
    AddFragmentCommand(SceneDocument& document, core::scene::Fragment fragment, SceneDocument::OctreePtr octree,
                       const CommandText& text = {}, QUndoCommand* parent = nullptr);

    core::scene::FragmentId fragmentId() const { return m_fragment.id; }

    /** An import's step going while undone (the redo branch dropped, the history cleared) releases its octree
     *  (SceneDocument::releaseOctree: removed if this session's import built it and nothing names it). */
    ~AddFragmentCommand() override;

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    core::scene::Fragment m_fragment;  ///< as it was when last removed by undo()
    SceneDocument::OctreePtr m_octree;
    int m_index = -1;                  ///< position, fixed at the first redo()
    bool m_applied = false;            ///< redone and not undone since
};

} // namespace stylos::widgets
