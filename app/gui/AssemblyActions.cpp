#include "AssemblyActions.h"

#include "SceneDock.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <QAction>
#include <QMenu>
#include <QTreeView>

namespace stylos::app {

namespace {

bool hasAxis(const core::scene::Fragment& f)
{
    return core::scene::firstGuide(f, core::scene::GuideKind::Axis).has_value();
}

} // namespace

AssemblyActions::AssemblyActions(widgets::SceneDocument& document, SceneDock& scene, QWidget& window)
    : QObject(&window), m_document(document), m_scene(scene), m_new(new QAction(this)), m_takeOut(new QAction(this)),
      m_remove(new QAction(this)), m_useAsDrum(new QAction(this)), m_developpee(new QAction(this))
{
    m_developpee->setObjectName(QStringLiteral("actionAssemblyDeveloppee"));
    connect(m_developpee, &QAction::triggered, this, [this] {
        if (const auto id = currentAssembly(); id != core::scene::NoAssembly) Q_EMIT developpeeRequested(id);
    });
    m_new->setObjectName(QStringLiteral("actionNewAssembly"));
    m_takeOut->setObjectName(QStringLiteral("actionTakeOutOfAssembly"));
    m_remove->setObjectName(QStringLiteral("actionRemoveAssembly"));
    m_useAsDrum->setObjectName(QStringLiteral("actionUseAsAssemblyDrum"));
    m_new->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_G));
    m_takeOut->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G));
    connect(m_new, &QAction::triggered, this, &AssemblyActions::newAssembly);
    connect(m_takeOut, &QAction::triggered, this, &AssemblyActions::takeOut);
    connect(m_remove, &QAction::triggered, this, &AssemblyActions::removeAssembly);
    connect(m_useAsDrum, &QAction::triggered, this, &AssemblyActions::useAsDrum);
    connect(&scene, &SceneDock::selectionChanged, this, &AssemblyActions::updateEnabled);
    connect(&document, &widgets::SceneDocument::structureChanged, this, &AssemblyActions::updateEnabled);
    connect(&document, &widgets::SceneDocument::assemblyChanged, this, &AssemblyActions::updateEnabled);
    updateEnabled();
    retranslateUi();
}

void AssemblyActions::populate(QMenu& menu)
{
    menu.addSeparator();
    for (QAction* action : {m_new, m_takeOut, m_remove, m_useAsDrum, m_developpee}) {
        menu.addAction(action);
        m_scene.view()->addAction(action);
    }
    m_scene.view()->setContextMenuPolicy(Qt::ActionsContextMenu);
}

void AssemblyActions::updateEnabled()
{
    const auto ids = m_scene.selectedFragments();
    bool inAssembly = false;
    for (auto id : ids)
        if (const auto* f = m_document.fragment(id); f && f->assembly != core::scene::NoAssembly) inAssembly = true;
    const auto* current = m_document.fragment(m_scene.currentFragment());
    const auto* assembly = current ? m_document.assembly(current->assembly) : nullptr;
    m_new->setEnabled(!ids.isEmpty());
    m_takeOut->setEnabled(inAssembly);
    m_remove->setEnabled(m_scene.currentAssembly() != core::scene::NoAssembly);
    m_useAsDrum->setEnabled(current && assembly && hasAxis(*current) && assembly->drum != current->id);
    const auto* chosen = m_document.assembly(currentAssembly());
    const auto* drum = chosen ? m_document.fragment(chosen->drum) : nullptr;
    m_developpee->setEnabled(drum && hasAxis(*drum));
}

core::scene::AssemblyId AssemblyActions::currentAssembly() const
{
    if (const auto id = m_scene.currentAssembly(); id != core::scene::NoAssembly) return id;
    const auto* f = m_document.fragment(m_scene.currentFragment());
    return f ? f->assembly : core::scene::NoAssembly;
}

void AssemblyActions::newAssembly()
{
    const auto ids = m_scene.selectedFragments();
    if (ids.isEmpty()) return;
    const QString name = tr("Assembly %1").arg(m_document.scene().nextAssemblyId());
    const std::vector<core::scene::FragmentId> members(ids.begin(), ids.end());
    const auto id = m_document.newAssembly(name, members);
    if (id == core::scene::NoAssembly) return;
    // A drum among them (a fragment with an axis guide) is what the others dock against.
    int drums = 0;
    core::scene::FragmentId drum = core::scene::NoFragment;
    for (auto f : members)
        if (const auto* fragment = m_document.fragment(f); fragment && hasAxis(*fragment)) ++drums, drum = f;
    if (drums == 1) m_document.setAssemblyDrum(id, drum);
    Q_EMIT reported(tr("%1: %n fragment(s)", nullptr, int(members.size())).arg(name), false);
}

void AssemblyActions::takeOut()
{
    const auto ids = m_scene.selectedFragments();
    m_document.moveToAssembly(std::vector<core::scene::FragmentId>(ids.begin(), ids.end()), core::scene::NoAssembly);
}

void AssemblyActions::removeAssembly()
{
    m_document.removeAssembly(m_scene.currentAssembly());
}

void AssemblyActions::useAsDrum()
{
    const auto* f = m_document.fragment(m_scene.currentFragment());
    if (!f) return;
    m_document.setAssemblyDrum(f->assembly, f->id);
}

void AssemblyActions::retranslateUi()
{
    m_new->setText(tr("New &assembly from selection"));
    m_new->setStatusTip(tr("Group the selected fragments into an assembly that moves as one; a drum among them "
                           "(a fragment with an axis guide) becomes what they dock against"));
    m_takeOut->setText(tr("&Take out of assembly"));
    m_takeOut->setStatusTip(tr("Move the selected fragments back to the top of the scene, where they are"));
    m_remove->setText(tr("&Remove assembly"));
    m_remove->setStatusTip(tr("Dissolve the selected assembly; its fragments stay where they are"));
    m_useAsDrum->setText(tr("&Use as the assembly's drum"));
    m_useAsDrum->setStatusTip(tr("Dock the assembly's fragments against the guides of the selected fragment"));
    m_developpee->setText(tr("Dé&veloppée of the assembly"));
    m_developpee->setStatusTip(tr("Unroll the assembly's drum with every fragment of the assembly at its place, on the "
                                  "drum's axis: the reconstruction in 2D, the free places; click a fragment to select it"));
}

} // namespace stylos::app
