#pragma once
/** @file
 * @brief Undo command: sets a fragment's pose. Steps of one drag merge: a command made with
 *        `continuing` true merges into the previous pose command of the same fragment, so a whole gizmo
 *        drag is one undo step from the pose before the drag to the last one (and disappears when it ends
 *        where it started). GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QCoreApplication>
#include "document/commands/DocumentCommand.h"

namespace stylos::widgets {

class SetFragmentPoseCommand : public DocumentCommand {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::SetFragmentPoseCommand)

public:
    /** @brief The QUndoCommand::id() of pose commands (merging). */
    static constexpr int CommandId = 0x5057;

    /** Precondition: @p id is in the document's scene; its current pose is the one undo restores. */
    SetFragmentPoseCommand(SceneDocument& document, core::scene::FragmentId id, const core::scene::Pose& pose,
                           bool continuing = false, QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return CommandId; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    SceneDocument& m_document;
    core::scene::FragmentId m_id;
    core::scene::Pose m_old;
    core::scene::Pose m_new;
    bool m_continuing;
};

} // namespace stylos::widgets
