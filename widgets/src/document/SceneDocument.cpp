#include "stylos/widgets/document/SceneDocument.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/scene/SceneEigen.h"
#include "document/commands/AddFragmentCommand.h"
#include "document/commands/EditLabelsCommand.h"
#include "document/commands/SetLegendCommand.h"
#include "document/commands/SetPlateCommand.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "tasks/ErrorText.h"
#include "document/commands/RemoveFragmentCommand.h"
#include "document/commands/RenameFragmentCommand.h"
#include "document/commands/SetFragmentColourCommand.h"
#include "document/commands/SetFragmentGuidesCommand.h"
#include "document/commands/SetFragmentPoseCommand.h"
#include "document/commands/SetSceneStructureCommand.h"
#include "document/commands/SetFragmentVisibleCommand.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>
#include <utility>
#include <set>
#include <QUndoStack>

#include <optional>

namespace stylos::widgets {

namespace {

using core::scene::Fragment;
using core::scene::FragmentId;

/** What an octree-opening job hands back. */
struct OpenedOctree {
    SceneDocument::OctreePtr octree;
    std::optional<core::Error> error;
};

QString qtPath(const std::filesystem::path& path)
{
    return QString::fromStdString(path.string());
}

} // namespace

SceneDocument::SceneDocument(TaskManager& tasks, QObject* parent)
    : QObject(parent), m_tasks(tasks), m_undo(new QUndoStack(this)), m_labels(new LabelStore(this))
{
    connect(m_undo, &QUndoStack::cleanChanged, this, [this](bool clean) { Q_EMIT modifiedChanged(!clean); });
}

SceneDocument::~SceneDocument()
{
    cancelLoads();
    // Commands refer to the document: delete them while it is whole.
    delete m_undo; // an undone import's step going releases its octree (releaseOctree())
    m_undo = nullptr;
}

void SceneDocument::noteImportedOctree(const QString& path)
{
    m_importedOctrees << QFileInfo(path).absoluteFilePath();
}

void SceneDocument::noteProjectOctrees(const QString& path)
{
    QStringList octrees;
    for (const Fragment& f : m_scene.fragments()) octrees << QFileInfo(qtPath(f.octreePath)).absoluteFilePath();
    m_projectFiles[QFileInfo(path).absoluteFilePath()] = octrees;
}

void SceneDocument::reserveOctreePath(const QString& path)
{
    m_reservedOctrees << QFileInfo(path).absoluteFilePath();
}

void SceneDocument::releaseOctreePath(const QString& path)
{
    m_reservedOctrees.removeOne(QFileInfo(path).absoluteFilePath());
}

bool SceneDocument::isOctreePathReserved(const QString& path) const
{
    return m_reservedOctrees.contains(QFileInfo(path).absoluteFilePath());
}

void SceneDocument::releaseOctree(const std::filesystem::path& path)
{
    const QString file = QFileInfo(qtPath(path)).absoluteFilePath();
    if (!m_importedOctrees.contains(file)) return; // not made by this session: never removed
    for (const Fragment& f : m_scene.fragments())
        if (QFileInfo(qtPath(f.octreePath)).absoluteFilePath() == file) return;
    for (const auto& project : m_projectFiles)
        if (project.second.contains(file)) return; // a project file on disk needs it
    m_importedOctrees.removeAll(file);
    QFile::remove(file);
}

SceneDocument::OctreePtr SceneDocument::octree(FragmentId id) const
{
    const auto it = m_octrees.find(id);
    return it == m_octrees.end() ? nullptr : it->second;
}

bool SceneDocument::replaceOctree(FragmentId id, OctreePtr octree)
{
    if (!octree || !m_scene.find(id)) return false;
    m_octrees[id] = std::move(octree);
    loadLabels(id);
    Q_EMIT octreeChanged(id);
    return true;
}

SceneDocument::DeveloppeePtr SceneDocument::developpee(FragmentId id) const
{
    const auto it = m_developpees.find(id);
    return it == m_developpees.end() ? nullptr : it->second;
}

bool SceneDocument::setDeveloppee(FragmentId id, DeveloppeePtr result)
{
    if (!m_scene.find(id)) return false;
    if (result) m_developpees[id] = std::move(result);
    else if (m_developpees.erase(id) == 0) return true;
    Q_EMIT developpeeChanged(id);
    return true;
}

QString SceneDocument::projectFolder() const
{
    return m_path.isEmpty() ? QString() : QFileInfo(m_path).absolutePath();
}

QString SceneDocument::displayName() const
{
    return m_path.isEmpty() ? tr("Untitled") : QFileInfo(m_path).fileName();
}

bool SceneDocument::isModified() const
{
    return !m_undo->isClean();
}

void SceneDocument::beginMacro(const CommandText& text)
{
    m_undo->beginMacro(text.text());
    // The macro is the stack's last command from now on (QUndoStack::beginMacro appends it).
    if (m_undo->count() > 0) m_macroTexts[m_undo->command(m_undo->count() - 1)] = text;
}

void SceneDocument::endMacro()
{
    m_undo->endMacro();
    // A clean state left inside the macro (resetClean: the docking drum removed with its fragment) is said now:
    // QUndoStack says nothing of it while a macro is open, nor at its end (its clean index is −1 throughout).
    if (m_cleanReset && isModified()) Q_EMIT modifiedChanged(true);
    m_cleanReset = false;
}

void SceneDocument::retranslate()
{
    std::map<const QUndoCommand*, CommandText> kept;
    for (int i = 0; i < m_undo->count(); ++i) {
        // The stack owns its commands and hands them out const; their text is ours to set.
        auto* command = const_cast<QUndoCommand*>(m_undo->command(i));
        if (auto* own = dynamic_cast<DocumentCommand*>(command)) {
            own->retranslate();
        } else if (const auto it = m_macroTexts.find(command); it != m_macroTexts.end()) {
            command->setText(it->second.text());
            kept.insert(*it);
        }
    }
    m_macroTexts = std::move(kept); // forget the macros no longer on the stack
    // QUndoStack signals the texts only when its index moves: the Edit menu asks again.
    Q_EMIT m_undo->undoTextChanged(m_undo->undoText());
    Q_EMIT m_undo->redoTextChanged(m_undo->redoText());
}

int SceneDocument::relabel(const std::function<void(core::scene::Scene&)>& rename)
{
    core::scene::Scene named = m_scene;
    rename(named);
    int changed = 0;
    for (const Fragment& f : named.fragments()) {
        Fragment* mine = m_scene.find(f.id);
        if (!mine) continue;
        bool differs = mine->name != f.name;
        for (std::size_t g = 0; g < f.guides.size() && g < mine->guides.size(); ++g)
            differs = differs || mine->guides[g].name != f.guides[g].name;
        if (!differs) continue;
        ++changed;
        changeFragment(f.id, [&f](Fragment& target) {
            target.name = f.name;
            for (std::size_t g = 0; g < f.guides.size() && g < target.guides.size(); ++g)
                target.guides[g].name = f.guides[g].name;
        });
    }
    for (const core::scene::Assembly& a : named.assemblies()) {
        core::scene::Assembly* mine = m_scene.findAssembly(a.id);
        if (!mine || mine->name == a.name) continue;
        mine->name = a.name;
        ++changed;
        Q_EMIT assemblyChanged(a.id);
    }
    return changed;
}

QString SceneDocument::nameOf(FragmentId id, const QString& fallback) const
{
    const core::scene::Fragment* f = m_scene.find(id);
    return f ? QString::fromStdString(f->name) : fallback;
}

QString SceneDocument::assemblyNameOf(core::scene::AssemblyId id, const QString& fallback) const
{
    const core::scene::Assembly* a = m_scene.findAssembly(id);
    return a ? QString::fromStdString(a->name) : fallback;
}

FragmentId SceneDocument::addFragment(Fragment fragment, OctreePtr octree, const CommandText& commandText)
{
    if (fragment.id != core::scene::NoFragment && m_scene.find(fragment.id)) return core::scene::NoFragment;
    auto* command = new AddFragmentCommand(*this, std::move(fragment), std::move(octree), commandText);
    const FragmentId id = command->fragmentId();
    m_undo->push(command);
    return id;
}

bool SceneDocument::removeFragment(FragmentId id)
{
    if (!m_scene.find(id)) return false;
    m_undo->push(new RemoveFragmentCommand(*this, id));
    return true;
}

bool SceneDocument::renameFragment(FragmentId id, const QString& name)
{
    const Fragment* f = m_scene.find(id);
    if (!f || f->name == name.toStdString()) return false;
    m_undo->push(new RenameFragmentCommand(*this, id, name));
    return true;
}

bool SceneDocument::setFragmentPose(FragmentId id, const core::scene::Pose& pose, bool continuing)
{
    const Fragment* f = m_scene.find(id);
    if (!f || f->pose == pose) return false;
    m_undo->push(new SetFragmentPoseCommand(*this, id, pose, continuing));
    return true;
}

bool SceneDocument::setFragmentColour(FragmentId id, core::scene::Rgb colour)
{
    const Fragment* f = m_scene.find(id);
    if (!f || f->colour == colour) return false;
    m_undo->push(new SetFragmentColourCommand(*this, id, colour));
    return true;
}

bool SceneDocument::setFragmentVisible(FragmentId id, bool visible)
{
    const Fragment* f = m_scene.find(id);
    if (!f || f->visible == visible) return false;
    m_undo->push(new SetFragmentVisibleCommand(*this, id, visible));
    return true;
}

bool SceneDocument::setFragmentGuides(FragmentId id, std::vector<core::scene::Guide> guides, const CommandText& commandText)
{
    const Fragment* f = m_scene.find(id);
    if (!f || f->guides == guides) return false;
    m_undo->push(new SetFragmentGuidesCommand(*this, id, std::move(guides), commandText));
    return true;
}

bool SceneDocument::setDockingDrum(FragmentId id)
{
    if (id == m_scene.dockingDrum()) return true;
    if (!m_scene.setDockingDrum(id)) return false;
    m_undo->resetClean(); // saved with the project: the file no longer holds what the scene is
    Q_EMIT dockingDrumChanged(id);
    return true;
}

core::scene::FragmentId SceneDocument::drumFor(FragmentId id) const
{
    return core::scene::drumFor(m_scene, id);
}

bool SceneDocument::isShown(FragmentId id) const
{
    const Fragment* f = m_scene.find(id);
    if (!f || !f->visible) return false;
    const core::scene::Assembly* a = m_scene.findAssembly(f->assembly);
    return !a || a->visible;
}

bool SceneDocument::setFragmentWorldPose(FragmentId id, const core::scene::Pose& world, bool continuing)
{
    if (!m_scene.find(id)) return false;
    return setFragmentPose(id, m_scene.localPose(id, world), continuing);
}

template <typename Edit>
bool SceneDocument::editStructure(const std::vector<FragmentId>& touched, const CommandText& text, Edit edit)
{
    core::scene::Scene after = m_scene;
    if (!edit(after)) return false;
    SceneStructure before = SceneStructure::of(m_scene, touched), next = SceneStructure::of(after, touched);
    if (before.assemblies == next.assemblies && before.fragments == next.fragments) return false;
    m_undo->push(new SetSceneStructureCommand(*this, std::move(before), std::move(next), text));
    return true;
}

core::scene::AssemblyId SceneDocument::newAssembly(const QString& name, const std::vector<FragmentId>& members)
{
    if (name.trimmed().isEmpty()) return core::scene::NoAssembly;
    const AssemblyId id = m_scene.nextAssemblyId();
    const bool pushed = editStructure(members, [n = name.trimmed()] { return tr("New assembly %1").arg(n); }, [&](core::scene::Scene& s) {
        core::scene::Assembly a;
        a.name = name.trimmed().toStdString();
        if (!members.empty() && s.find(members.front())) a.pose = s.worldPose(members.front());
        if (s.addAssembly(a) != id) return false;
        for (FragmentId f : members)
            if (!s.moveToAssembly(f, id)) return false;
        return true;
    });
    return pushed ? id : core::scene::NoAssembly;
}

bool SceneDocument::removeAssembly(AssemblyId id)
{
    const core::scene::Assembly* a = m_scene.findAssembly(id);
    if (!a) return false;
    return editStructure(m_scene.membersOf(id),
                         [n = QString::fromStdString(a->name)] { return tr("Remove assembly %1").arg(n); },
                         [id](core::scene::Scene& s) { return s.takeAssembly(id).has_value(); });
}

bool SceneDocument::renameAssembly(AssemblyId id, const QString& name)
{
    const core::scene::Assembly* a = m_scene.findAssembly(id);
    if (!a || name.trimmed().isEmpty()) return false;
    return editStructure({}, [n = QString::fromStdString(a->name)] { return tr("Rename %1").arg(n); }, [&](core::scene::Scene& s) {
        s.findAssembly(id)->name = name.trimmed().toStdString();
        return true;
    });
}

bool SceneDocument::moveToAssembly(const std::vector<FragmentId>& fragments, AssemblyId assembly)
{
    if (assembly != core::scene::NoAssembly && !m_scene.findAssembly(assembly)) return false;
    const QString name = assembly == core::scene::NoAssembly ? QString() : assemblyNameOf(assembly);
    const CommandText text = [this, assembly, name] {
        return assembly == core::scene::NoAssembly ? tr("Take out of assembly")
                                                   : tr("Move into %1").arg(assemblyNameOf(assembly, name));
    };
    return editStructure(fragments, text, [&](core::scene::Scene& s) {
        for (FragmentId f : fragments)
            if (!s.moveToAssembly(f, assembly)) return false;
        return true;
    });
}

bool SceneDocument::setAssemblyPose(AssemblyId id, const core::scene::Pose& pose)
{
    const core::scene::Assembly* a = m_scene.findAssembly(id);
    if (!a || !pose.isRigid()) return false;
    return editStructure({}, [this, id, n = QString::fromStdString(a->name)] { return tr("Move %1").arg(assemblyNameOf(id, n)); }, [&](core::scene::Scene& s) {
        s.findAssembly(id)->pose = pose;
        return true;
    });
}

bool SceneDocument::setAssemblyDrum(AssemblyId id, FragmentId drum)
{
    const core::scene::Assembly* a = m_scene.findAssembly(id);
    if (!a || (drum != core::scene::NoFragment && !m_scene.find(drum))) return false;
    return editStructure({}, [this, id, n = QString::fromStdString(a->name)] { return tr("Set the drum of %1").arg(assemblyNameOf(id, n)); }, [&](core::scene::Scene& s) {
        s.findAssembly(id)->drum = drum;
        return true;
    });
}

bool SceneDocument::setAssemblyVisible(AssemblyId id, bool visible)
{
    const core::scene::Assembly* a = m_scene.findAssembly(id);
    if (!a) return false;
    const CommandText text = [this, id, visible, n = QString::fromStdString(a->name)] {
        return visible ? tr("Show %1").arg(assemblyNameOf(id, n)) : tr("Hide %1").arg(assemblyNameOf(id, n));
    };
    return editStructure({}, text,
                         [&](core::scene::Scene& s) {
                             s.findAssembly(id)->visible = visible;
                             return true;
                         });
}

void SceneDocument::applyStructure(const SceneStructure& structure)
{
    // Membership or the set of assemblies changes the tree; names, poses, drums and visibility do not.
    std::vector<core::scene::AssemblyId> ids, nextIds;
    for (const auto& a : m_scene.assemblies()) ids.push_back(a.id);
    for (const auto& a : structure.assemblies) nextIds.push_back(a.id);
    bool treeChanges = ids != nextIds;
    for (const auto& [id, where] : structure.fragments)
        if (const Fragment* f = m_scene.find(id); f && f->assembly != where.first) treeChanges = true;
    if (treeChanges) Q_EMIT structureAboutToChange();
    // The assemblies whose name, pose, drum or visibility change (or that come or go): their members' place,
    // visibility or drum change with them.
    std::set<core::scene::AssemblyId> changed;
    for (const auto& a : structure.assemblies)
        if (const core::scene::Assembly* now = m_scene.findAssembly(a.id); !now || !(*now == a)) changed.insert(a.id);
    for (const auto& a : m_scene.assemblies())
        if (std::none_of(structure.assemblies.begin(), structure.assemblies.end(),
                         [&a](const core::scene::Assembly& b) { return b.id == a.id; }))
            changed.insert(a.id);
    std::vector<FragmentId> affected;
    for (const Fragment& f : m_scene.fragments())
        if (structure.fragments.count(f.id) || changed.count(f.assembly)) affected.push_back(f.id);
    m_scene.setAssemblies(structure.assemblies, structure.nextAssemblyId);
    for (const auto& [id, where] : structure.fragments)
        if (Fragment* f = m_scene.find(id)) {
            f->assembly = where.first;
            f->pose = where.second;
        }
    if (treeChanges) Q_EMIT structureChanged();
    for (const auto& a : structure.assemblies)
        if (changed.count(a.id)) Q_EMIT assemblyChanged(a.id);
    for (FragmentId id : affected) Q_EMIT fragmentChanged(id);
}

bool SceneDocument::setLabels(FragmentId id, AnnotationLayer layer, std::span<const std::uint32_t> leaves,
                              std::uint8_t classId, const CommandText& text, quint64 stroke)
{
    if (classId != 0 && !legend().find(layer, classId)) return false;
    LabelEdit edit = m_labels->makeEdit(id, layer, leaves, classId);
    if (edit.empty()) return false;
    m_undo->push(new EditLabelsCommand(*this, std::move(edit), text, stroke));
    return true;
}

bool SceneDocument::setLegend(core::annotation::Legend legend, const CommandText& text)
{
    if (legend == m_scene.legend()) return false;
    m_undo->push(new SetLegendCommand(*this, std::move(legend),
                                      text.isEmpty() ? CommandText([] { return tr("Change the legend"); }) : text));
    return true;
}

bool SceneDocument::removeLegendClass(AnnotationLayer layer, std::uint8_t classId, std::uint8_t replacement)
{
    const core::annotation::LegendClass* removed = legend().find(layer, classId);
    if (!removed || replacement == classId || (replacement != 0 && !legend().find(layer, replacement))) return false;
    core::annotation::Legend next = legend();
    auto& classes = next.classes(layer);
    classes.erase(std::remove_if(classes.begin(), classes.end(),
                                 [classId](const core::annotation::LegendClass& c) { return c.id == classId; }),
                  classes.end());
    const QString name = QString::fromStdString(removed->name);
    const CommandText text([name] { return tr("Remove the class %1").arg(name); });
    beginMacro(text);
    for (const Fragment& f : m_scene.fragments()) {
        LabelEdit edit = m_labels->relabelEdit(f.id, layer, classId, replacement);
        if (!edit.empty()) m_undo->push(new EditLabelsCommand(*this, std::move(edit), text));
    }
    m_undo->push(new SetLegendCommand(*this, std::move(next), text));
    endMacro();
    return true;
}

bool SceneDocument::setPlate(core::plate::PlateSpec plate)
{
    if (m_scene.plate() == plate) return false;
    m_undo->push(new SetPlateCommand(*this, std::move(plate), CommandText([] { return tr("Keep the plate's settings"); })));
    return true;
}

void SceneDocument::changePlate(const std::optional<core::plate::PlateSpec>& plate)
{
    m_scene.setPlate(plate);
}

void SceneDocument::changeLegend(const core::annotation::Legend& legend)
{
    m_scene.setLegend(legend);
    Q_EMIT legendChanged();
}

void SceneDocument::loadLabels(FragmentId id)
{
    const OctreePtr tree = octree(id);
    if (!tree) return;
    const core::Status loaded = m_labels->load(id, *tree);
    if (!loaded) m_loadErrors << ErrorText::loadFailure(qtPath(tree->path()), loaded.error());
}

bool SceneDocument::saveLabels(QString* error)
{
    using core::annotation::AllAnnotationLayers;
    for (FragmentId id : m_labels->dirty()) {
        const Fragment* f = m_scene.find(id);
        const OctreePtr tree = octree(id);
        if (!f || !tree) continue; // removed since: its labels wait in the store for an undo
        std::vector<core::octree::AttributeLayer> layers;
        for (AnnotationLayer layer : AllAnnotationLayers)
            layers.push_back(core::annotation::labelAttribute(layer, *m_labels->labels(id, layer)));
        const auto written = core::annotation::writeAttributesPoct(*tree, std::move(layers), f->octreePath);
        if (!written) {
            if (error)
                *error = tr("Could not save the annotations of %1 into %2: %3.")
                             .arg(QString::fromStdString(f->name), qtPath(f->octreePath.filename()),
                                  ErrorText::reason(written.error().code)) +
                         QLatin1Char('\n') + QString::fromStdString(written.error().message);
            return false;
        }
        m_labels->markSaved(id);
    }
    return true;
}

void SceneDocument::newProject()
{
    resetScene(core::scene::Scene{});
    setProjectPath({});
}

bool SceneDocument::save(QString* error, OctreeCopies copies)
{
    if (m_path.isEmpty()) {
        if (error) *error = tr("The project has no file yet: choose one with Save as.");
        return false;
    }
    return saveAs(m_path, error, copies);
}

QString SceneDocument::defaultOctreeCacheFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/octrees");
}

core::scene::GatherPlan SceneDocument::octreeGatherPlan(const QString& path) const
{
    std::set<std::filesystem::path> reserved;
    for (const QString& building : m_reservedOctrees) reserved.insert(building.toStdString());
    return core::scene::planGather(m_scene, QFileInfo(path).absoluteFilePath().toStdString(),
                                   m_octreeCache.toStdString(), reserved);
}

bool SceneDocument::gatherOctrees(const QString& path, OctreeCopies copies, QString* error)
{
    const core::scene::GatherPlan plan = octreeGatherPlan(path);
    const auto gathered = core::scene::gather(m_scene, plan, copies == OctreeCopies::All);
    // The fragments repointed so far stay repointed (their copies are whole), even after a failure.
    for (const core::scene::OctreeTransfer& t : plan.transfers) {
        bool copied = false;
        for (FragmentId id : t.fragments)
            if (const Fragment* f = m_scene.find(id); f && f->octreePath == t.to) {
                copied = true;
                Q_EMIT fragmentChanged(id);
            }
        if (copied) noteImportedOctree(qtPath(t.to)); // a copy this project made: as an import's octree
    }
    if (gathered) return true;
    if (error)
        *error = tr("Could not copy the octrees into the project's folder: %1.").arg(ErrorText::reason(gathered.error().code)) +
                 QLatin1Char('\n') + QString::fromStdString(gathered.error().message);
    return false;
}

bool SceneDocument::saveAs(const QString& path, QString* error, OctreeCopies copies)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    if (!gatherOctrees(absolute, copies, error)) return false;
    if (!saveLabels(error)) return false;
    const core::Status saved = core::scene::ProjectFile::save(m_scene, absolute.toStdString());
    if (!saved) {
        if (error)
            *error = tr("Could not save %1: %2.").arg(QFileInfo(path).fileName(), ErrorText::reason(saved.error().code)) +
                     QLatin1Char('\n') + QString::fromStdString(saved.error().message);
        return false;
    }
    setProjectPath(absolute);
    noteProjectOctrees(absolute);
    m_undo->setClean();
    return true;
}

bool SceneDocument::open(const QString& path, QString* error)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    auto loaded = core::scene::ProjectFile::load(absolute.toStdString());
    if (!loaded) {
        if (error) *error = ErrorText::loadFailure(path, loaded.error());
        return false;
    }
    resetScene(std::move(loaded->scene));
    setProjectPath(absolute);
    noteProjectOctrees(absolute);
    if (loaded->plateProblem)
        m_loadErrors << tr("The plate layout kept in %1 could not be read: the project opens without it, and its "
                           "text stays in the file until a new plate is set (File › Export plate…).")
                                .arg(QFileInfo(path).fileName()) +
                            QLatin1Char('\n') + QString::fromStdString(loaded->plateProblem->message);
    if (!loaded->unknownKeys.empty()) {
        QStringList keys;
        for (const std::string& key : loaded->unknownKeys) keys << QString::fromStdString(key);
        m_loadErrors << tr("%1 holds keys this version of Stylos does not read; they are left out and will not be "
                           "saved: %2")
                            .arg(QFileInfo(path).fileName(), keys.join(QStringLiteral(", ")));
    }
    std::size_t problem = 0;
    for (const Fragment& f : m_scene.fragments()) {
        if (f.octreeMissing && problem < loaded->problems.size())
            m_loadErrors << ErrorText::loadFailure(qtPath(f.octreePath), loaded->problems[problem++]);
        else startLoad(f.id);
    }
    if (m_loads.empty()) {
        // Nothing to open in the background: still report after open() returns, as when there is.
        QMetaObject::invokeMethod(this, [this] {
            if (m_loads.empty()) Q_EMIT loadingFinished(std::exchange(m_loadErrors, {}));
        }, Qt::QueuedConnection);
    }
    return true;
}

void SceneDocument::insertFragment(int index, Fragment fragment, OctreePtr octree)
{
    if (m_scene.find(fragment.id)) return; // a programmer error: ids are unique
    index = std::clamp(index, 0, static_cast<int>(m_scene.size()));
    if (fragment.assembly != core::scene::NoAssembly && !m_scene.findAssembly(fragment.assembly))
        fragment.assembly = core::scene::NoAssembly;
    Q_EMIT fragmentAboutToBeAdded(index, fragment.assembly);
    const FragmentId id = m_scene.insert(static_cast<std::size_t>(index), std::move(fragment));
    if (octree) {
        m_octrees[id] = std::move(octree);
        loadLabels(id);
    }
    Q_EMIT fragmentAdded(id);
    if (!m_octrees.count(id)) startLoad(id);
}

std::pair<Fragment, SceneDocument::OctreePtr> SceneDocument::takeFragment(FragmentId id)
{
    if (!m_scene.find(id)) return {};
    Q_EMIT fragmentAboutToBeRemoved(id);
    const bool wasDrum = id == m_scene.dockingDrum();
    Fragment fragment = m_scene.take(id).value(); // unsets the docking drum when it is this fragment
    m_developpees.erase(id);
    OctreePtr octree;
    if (const auto it = m_octrees.find(id); it != m_octrees.end()) {
        octree = std::move(it->second);
        m_octrees.erase(it);
    }
    bool loadDropped = false;
    if (const auto it = m_loads.find(id); it != m_loads.end()) {
        if (it->second) it->second->cancel();
        m_loads.erase(it);
        loadDropped = true;
    }
    Q_EMIT fragmentRemoved(id);
    if (wasDrum) {
        m_undo->resetClean(); // undoing the removal brings the fragment back, not the docking drum
        m_cleanReset = true;  // said at the end of a macro that holds the removal (endMacro)
        Q_EMIT dockingDrumChanged(core::scene::NoFragment);
    }
    if (loadDropped && m_loads.empty()) Q_EMIT loadingFinished(std::exchange(m_loadErrors, {}));
    return {std::move(fragment), std::move(octree)};
}

void SceneDocument::resetScene(core::scene::Scene scene)
{
    cancelLoads();
    Q_EMIT sceneAboutToBeReset();
    m_undo->clear(); // the undone imports' steps go: their octrees are released (releaseOctree())
    m_scene = std::move(scene);
    m_octrees.clear();
    m_developpees.clear();
    m_labels->clear();
    Q_EMIT sceneReset();
    Q_EMIT legendChanged();
    Q_EMIT dockingDrumChanged(m_scene.dockingDrum()); // the project's, or none
}

void SceneDocument::setProjectPath(const QString& path)
{
    if (path == m_path) return;
    m_path = path;
    Q_EMIT projectPathChanged(m_path);
}

void SceneDocument::startLoad(FragmentId id)
{
    const Fragment* f = m_scene.find(id);
    if (!f || f->octreeMissing || m_loads.count(id) || m_octrees.count(id)) return;
    const std::filesystem::path path = f->octreePath;
    auto* watcher = m_tasks.start<OpenedOctree>(
        tr("Opening %1").arg(QString::fromStdString(f->name)),
        [path](QPromise<OpenedOctree>& promise, core::ProgressSink& progress) {
            auto opened = core::octree::PackedOctree::open(path);
            if (progress.isCancelRequested()) return;
            OpenedOctree out;
            if (opened) out.octree = std::make_shared<const core::octree::PackedOctree>(std::move(opened).value());
            else out.error = opened.error();
            progress.update(1.0);
            promise.addResult(std::move(out));
        });
    m_loads[id] = watcher;
    connect(watcher, &QFutureWatcherBase::finished, this, [this, id, watcher] { loadEnded(id, watcher); });
}

void SceneDocument::loadEnded(FragmentId id, QFutureWatcherBase* watcher)
{
    const auto it = m_loads.find(id);
    if (it == m_loads.end() || it->second != watcher) return; // dropped by a reset or a removal
    m_loads.erase(it);
    auto* typed = static_cast<QFutureWatcher<OpenedOctree>*>(watcher);
    const Fragment* f = m_scene.find(id);
    if (f && !typed->isCanceled() && typed->future().resultCount() > 0) {
        OpenedOctree opened = typed->result();
        if (opened.octree) {
            m_octrees[id] = std::move(opened.octree);
            loadLabels(id);
        } else if (opened.error) {
            m_loadErrors << ErrorText::loadFailure(qtPath(f->octreePath), *opened.error);
            changeFragment(id, [](Fragment& fragment) { fragment.octreeMissing = true; });
        }
        Q_EMIT octreeChanged(id);
    }
    if (m_loads.empty()) Q_EMIT loadingFinished(std::exchange(m_loadErrors, {}));
}

void SceneDocument::cancelLoads()
{
    for (auto& entry : m_loads)
        if (entry.second) entry.second->cancel();
    m_loads.clear();
    m_loadErrors.clear();
}

} // namespace stylos::widgets
