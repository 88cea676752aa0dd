#include "document/commands/SetFragmentPoseCommand.h"

namespace stylos::widgets {

SetFragmentPoseCommand::SetFragmentPoseCommand(SceneDocument& document, core::scene::FragmentId id,
                                               const core::scene::Pose& pose, bool continuing, QUndoCommand* parent)
    : DocumentCommand(parent), m_document(document), m_id(id), m_new(pose), m_continuing(continuing)
{
    const core::scene::Fragment* f = document.fragment(id);
    if (f) m_old = f->pose;
    const QString name = f ? QString::fromStdString(f->name) : QString();
    setText([this, name] { return tr("Move %1").arg(m_document.nameOf(m_id, name)); });
}

void SetFragmentPoseCommand::redo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.pose = m_new; });
}

void SetFragmentPoseCommand::undo()
{
    m_document.changeFragment(m_id, [this](core::scene::Fragment& f) { f.pose = m_old; });
}

bool SetFragmentPoseCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const SetFragmentPoseCommand*>(other);
    if (!next || !next->m_continuing || next->m_id != m_id) return false;
    m_new = next->m_new;
    setObsolete(m_new == m_old);
    return true;
}

} // namespace stylos::widgets
