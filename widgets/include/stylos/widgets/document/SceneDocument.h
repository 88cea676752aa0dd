#pragma once
/** @file
 * @brief The open project: owns the core scene, its undo stack, the opened octree of each fragment, the
 *        project file's path and the modified flag. Every edit is an undo command (AddFragmentCommand,
 *        RemoveFragmentCommand, SetFragmentPoseCommand, RenameFragmentCommand, SetFragmentColourCommand,
 *        SetFragmentVisibleCommand, SetFragmentGuidesCommand); the edit functions below push them. Docks and views observe the
 *        signals, which always come in about-to/done pairs around a structural change (for item models).
 *        Octrees are opened in background tasks (TaskManager); a fragment in the scene that has no
 *        octree and is not marked missing gets one opened, so undoing a removal restores it either way.
 *        GUI thread only. Failures come back as translated messages naming the file and the reason.
 */
#include "stylos/core/scene/ProjectOctrees.h"
#include "stylos/core/scene/Scene.h"
#include "stylos/widgets/document/CommandText.h"

#include <cstdint>
#include <span>

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <functional>
#include <map>
#include <memory>
#include <vector>

class QFutureWatcherBase;
class QUndoCommand;
class QUndoStack;

namespace stylos::core::octree {
class PackedOctree;
}

namespace stylos::widgets {

class TaskManager;
class LabelStore;
struct DeveloppeeResult;
struct SceneStructure;

class SceneDocument : public QObject {
    Q_OBJECT

public:
    using FragmentId = core::scene::FragmentId;
    using OctreePtr = std::shared_ptr<const core::octree::PackedOctree>;

    /** Runs its background jobs on @p tasks (not owned; it must outlive the document). */
    explicit SceneDocument(TaskManager& tasks, QObject* parent = nullptr);
    ~SceneDocument() override;

    const core::scene::Scene& scene() const { return m_scene; }
    /** @brief The fragment with @p id, or nullptr (invalidated by the next structural change). */
    const core::scene::Fragment* fragment(FragmentId id) const { return m_scene.find(id); }
    /** @brief The opened octree of @p id; nullptr while it opens, when it is missing or failed. */
    OctreePtr octree(FragmentId id) const;
    /** @brief True while octrees are being opened (after open(), or for restored fragments). */
    bool isLoading() const { return !m_loads.empty(); }
    /**
     * @brief Swaps the opened octree of @p id for @p octree: the same fragment's file opened again after a
     *        derived attribute layer was written into it (SkydomeJob's "ambient"). Not an undo step and not a
     *        modification of the project: the scene is unchanged. Emits octreeChanged(id). Returns false
     *        (changing nothing) when the fragment is gone or @p octree is null. The previous octree stays
     *        valid for whoever still holds it (a view's buffers, a running job).
     */
    bool replaceOctree(FragmentId id, OctreePtr octree);

    using DeveloppeePtr = std::shared_ptr<const DeveloppeeResult>;
    /** @brief The développée last computed for @p id in this session; null when none. Not saved. */
    DeveloppeePtr developpee(FragmentId id) const;
    /**
     * @brief Keeps @p result (a successful one) as the développée of fragment @p id, replacing the
     *        previous one; null forgets it. Not an undo step; dropped with the fragment. Emits
     *        developpeeChanged(). False (nothing changed) when there is no such fragment.
     */
    bool setDeveloppee(FragmentId id, DeveloppeePtr result);

    QUndoStack* undoStack() const { return m_undo; }
    /** @brief Opens a macro (several edits, one undo step) whose text follows the language; endMacro() closes it. */
    void beginMacro(const CommandText& text);
    void endMacro();
    /** @brief Makes every undo step's text again in the current language (after a change of language). */
    void retranslate();
    /**
     * @brief Gives new names to fragments, their guides and assemblies: @p rename edits a copy of the scene,
     *        and only the names it changed are taken. Not an undo step: it is for the names the program gave
     *        (the demo's "Drum", "Axis"…), which follow the language; the project stays as modified as it
     *        was. Emits fragmentChanged() / assemblyChanged() for what changed; returns how many changed.
     */
    int relabel(const std::function<void(core::scene::Scene&)>& rename);
    /** @brief The fragment's name now; @p fallback when it is not in the scene (any more). */
    QString nameOf(FragmentId id, const QString& fallback = {}) const;
    /** @brief The assembly's name now; @p fallback when it is not in the scene (any more). */
    QString assemblyNameOf(core::scene::AssemblyId id, const QString& fallback = {}) const;
    TaskManager& tasks() const { return m_tasks; }

    /** @brief The project file, absolute; empty for a project never saved. */
    QString projectPath() const { return m_path; }
    /** @brief The project file's folder; empty for a project never saved. */
    QString projectFolder() const;
    /** @brief The project's file name, or "Untitled" (translated) when never saved. */
    QString displayName() const;
    /** @brief True when the scene differs from the last save or open (the undo stack is not clean). */
    bool isModified() const;

    // Edits: each pushes one undo command and returns false (pushing nothing) when it would change nothing.
    /**
     * @brief Adds @p fragment (its id, when NoFragment, is allocated here) with its already opened
     *        @p octree, or none (then it is opened in the background). @p commandText names the undo
     *        step ("Import drum.ply"); default "Add NAME". Returns the fragment's id.
     */
    FragmentId addFragment(core::scene::Fragment fragment, OctreePtr octree, const CommandText& commandText = {});
    bool removeFragment(FragmentId id);
    bool renameFragment(FragmentId id, const QString& name);
    /** @brief @p continuing: part of a drag, merged with the previous pose step of the same fragment. */
    bool setFragmentPose(FragmentId id, const core::scene::Pose& pose, bool continuing = false);
    bool setFragmentColour(FragmentId id, core::scene::Rgb colour);
    bool setFragmentVisible(FragmentId id, bool visible);
    /** @brief Replaces the fragment's guides (its own frame); @p commandText names the step (default
     *         "Change the guides of NAME"). */
    bool setFragmentGuides(FragmentId id, std::vector<core::scene::Guide> guides, const CommandText& commandText = {});

    // Where fragments are: a fragment's pose is relative to its assembly (core::scene::Scene).
    /** @brief Fragment frame → scene frame (its assembly's pose composed with its own). */
    core::scene::Pose worldPose(FragmentId id) const { return m_scene.worldPose(id); }
    /** @brief Whether the fragment is shown: visible, and its assembly too. */
    bool isShown(FragmentId id) const;
    /** @brief Moves the fragment to @p world in the scene frame (setFragmentPose() of the pose relative to its assembly). */
    bool setFragmentWorldPose(FragmentId id, const core::scene::Pose& world, bool continuing = false);

    // Assemblies: each edit one undo step (SetSceneStructureCommand); the tree changes come as
    // structureAboutToChange() / structureChanged(), a member's place in the scene as fragmentChanged().
    using AssemblyId = core::scene::AssemblyId;
    const core::scene::Assembly* assembly(AssemblyId id) const { return m_scene.findAssembly(id); }
    /** @brief A new assembly named @p name holding @p members (moved in, keeping their place), its frame at
     *         the first member's (or the scene's); its id, or NoAssembly when @p name is empty. */
    AssemblyId newAssembly(const QString& name, const std::vector<FragmentId>& members = {});
    /** @brief Removes the assembly; its members go to the top level, where they are. */
    bool removeAssembly(AssemblyId id);
    bool renameAssembly(AssemblyId id, const QString& name);
    /** @brief Moves @p fragments into @p assembly (NoAssembly: the top level), keeping their place in the scene. */
    bool moveToAssembly(const std::vector<FragmentId>& fragments, AssemblyId assembly);
    /** @brief Moves the assembly (and so its members) to @p pose (assembly frame → scene frame). */
    bool setAssemblyPose(AssemblyId id, const core::scene::Pose& pose);
    /** @brief The drum its members dock against (NoFragment: none). */
    bool setAssemblyDrum(AssemblyId id, FragmentId drum);
    bool setAssemblyVisible(AssemblyId id, bool visible);

    // The docking drum (core::scene::Scene::dockingDrum): the fragment whose guides the gizmo's Drum frame follows
    // and about whose axis a fragment without its own unrolls. Saved in the project, not undoable (a setting, as a
    // view's): choosing another marks the project modified. Cleared when that fragment is removed.
    /** @brief The docking drum; NoFragment when none. */
    FragmentId dockingDrum() const { return m_scene.dockingDrum(); }
    /** @brief The drum fragment @p id docks against: its assembly's drum when it has one, else the docking drum. */
    FragmentId drumFor(FragmentId id) const;
    /** @brief Sets the docking drum (NoFragment: none); false for an unknown fragment. Emits dockingDrumChanged() and,
     *  when it changed, modifiedChanged(true) (QUndoStack::resetClean: no undo step returns to the saved state). */
    bool setDockingDrum(FragmentId id);

    // Annotation: the legend (part of the scene, saved in the project file) and the labels of each fragment's
    // leaves (labels(), written into the fragments' `.poct` layers by save()).
    using AnnotationLayer = core::annotation::AnnotationLayer;
    const core::annotation::Legend& legend() const { return m_scene.legend(); }
    /** @brief The labels of every fragment whose octree opened (read-only: edits go through setLabels()). */
    const LabelStore& labels() const { return *m_labels; }
    /** @brief A new stroke's token, for setLabels(): the steps of one stroke merge into one undo step. */
    quint64 beginStroke() { return ++m_lastStroke; }
    /**
     * @brief Gives @p classId (0: unlabelled) to @p leaves (indices in leaf order; duplicates and leaves out of
     *        range ignored) of @p id's @p layer: one undo step named @p text holding only the leaves that change.
     *        A non-zero @p stroke (beginStroke()) merges the step into the previous one of the same stroke.
     *        False (nothing pushed) when nothing changes, the fragment has no labels yet, or @p classId is
     *        neither 0 nor a class of the layer's legend.
     */
    bool setLabels(FragmentId id, AnnotationLayer layer, std::span<const std::uint32_t> leaves, std::uint8_t classId,
                   const CommandText& text, quint64 stroke = 0);
    /** @brief Replaces the legend (names, colours, hatches, classes added): one undo step, default text
     *         "Change the legend". False when equal. Removing a class that is used: removeLegendClass(). */
    bool setLegend(core::annotation::Legend legend, const CommandText& text = {});
    /** @brief Keeps @p plate in the project (one undo step); false when it is the one kept already. */
    bool setPlate(core::plate::PlateSpec plate);
    /**
     * @brief Removes class @p classId from @p layer; every leaf holding it (in every fragment with labels) gets
     *        @p replacement (0: unlabelled, or another class of the layer). One undo step. False when there is
     *        no such class or @p replacement is neither 0 nor another class of the layer.
     */
    bool removeLegendClass(AnnotationLayer layer, std::uint8_t classId, std::uint8_t replacement);

    // Files.
    /** @brief An empty, unsaved project (the undo history is cleared). */
    void newProject();
    /** @brief Whether saving copies the octrees outside the project's folder into it (those in the cache always). */
    enum class OctreeCopies { All, CacheOnly };
    /** @brief Saves to projectPath() (see saveAs()); false (with @p error) when it fails or the project was never saved. */
    bool save(QString* error = nullptr, OctreeCopies copies = OctreeCopies::All);
    /**
     * @brief Saves to @p path (paths inside are made relative to its folder) and makes it the project path.
     *        First brings the fragments' octrees into the project's folder (core::scene::gather: those in
     *        octreeCacheFolder() always, the others unless @p copies is CacheOnly), so the folder can be
     *        moved or copied whole; then writes the labels of every fragment changed since its octree opened
     *        into that octree's file (both layers, one atomic rewrite each). When a step fails, nothing more
     *        is written and the project stays modified.
     */
    bool saveAs(const QString& path, QString* error = nullptr, OctreeCopies copies = OctreeCopies::All);
    /** @brief What saving to @p path would copy into its folder (see saveAs()). */
    core::scene::GatherPlan octreeGatherPlan(const QString& path) const;
    /** @brief Where imports build their octrees while the project was never saved (ScanImporter). */
    QString octreeCacheFolder() const { return m_octreeCache; }
    void setOctreeCacheFolder(const QString& folder) { m_octreeCache = folder; }
    /** @brief The user cache's "octrees" folder: the default octreeCacheFolder(). */
    static QString defaultOctreeCacheFolder();
    /**
     * @brief Notes that an import built the octree @p path in this session (ScanImporter; saving notes the copies it
     *        makes in the project's folder too): such a file is removed when the import that made it can no longer
     *        be redone — its undo step discarded, or the history cleared by closing the project — while it is undone,
     *        unless a fragment of the scene or a project file saved or opened in this session names it
     *        (releaseOctree()). A fragment removed with Delete keeps its file; so does an import never undone.
     */
    void noteImportedOctree(const QString& path);
    /** @brief An import is building @p path (ScanImporter): a save copies no octree onto that name meanwhile (it
     *         renamed the finished import over the copy: the project named the wrong scan). Until released. */
    void reserveOctreePath(const QString& path);
    void releaseOctreePath(const QString& path);
    /** @brief Whether an import is building @p path (reserveOctreePath()). */
    bool isOctreePathReserved(const QString& path) const;
    /**
     * @brief An undone import's undo step is going (AddFragmentCommand): removes @p path when noteImportedOctree()
     *        noted it and neither the scene nor a project file saved or opened in this session names it.
     */
    void releaseOctree(const std::filesystem::path& path);
    /**
     * @brief Replaces the project by the one in @p path and opens each fragment's octree in the
     *        background; loadingFinished() follows with the problems met. On failure (unreadable or
     *        malformed project) returns false with @p error and keeps the current project.
     */
    bool open(const QString& path, QString* error = nullptr);

Q_SIGNALS:
    /** @brief Fragment about to be inserted at scene position @p index, into assembly @p assembly (0: the top). */
    void fragmentAboutToBeAdded(int index, quint64 assembly);
    void fragmentAdded(quint64 id);
    void fragmentAboutToBeRemoved(quint64 id);
    void fragmentRemoved(quint64 id);
    /** @brief Name, pose, colour, visibility, guides or the missing flag changed. */
    void fragmentChanged(quint64 id);
    void sceneAboutToBeReset();
    void sceneReset();
    /** @brief The octree of @p id became available (or failed: octree() stays null, the fragment is missing). */
    void octreeChanged(quint64 id);
    /** @brief The fragment's développée was kept, replaced or forgotten (setDeveloppee()). */
    void developpeeChanged(quint64 id);
    /**
     * @brief The octrees being opened are all done. @p errors: a translated message per failure (a
     *        missing or unreadable octree), naming the file; empty when all opened.
     */
    void loadingFinished(const QStringList& errors);
    void projectPathChanged(const QString& path);
    void modifiedChanged(bool modified);
    /** @brief The docking drum changed (@p id: the new one, or 0). */
    void dockingDrumChanged(quint64 id);
    /** @brief Assemblies or fragments' membership are about to change / changed (a tree's structure). */
    void structureAboutToChange();
    void structureChanged();
    /** @brief An assembly's name, pose, drum or visibility changed (its members' fragmentChanged() follow). */
    void assemblyChanged(quint64 id);
    /** @brief The legend changed (an edit, its undo, a new or opened project). */
    void legendChanged();

private:
    friend class AddFragmentCommand;
    friend class RemoveFragmentCommand;
    friend class SetFragmentPoseCommand;
    friend class RenameFragmentCommand;
    friend class SetFragmentColourCommand;
    friend class SetFragmentVisibleCommand;
    friend class SetFragmentGuidesCommand;
    friend class SetSceneStructureCommand;
    friend class EditLabelsCommand;
    friend class SetLegendCommand;
    friend class SetPlateCommand;

    /** Sets the assemblies and the touched fragments' assembly and pose to @p structure's, with the signals. */
    void applyStructure(const SceneStructure& structure);
    /** Pushes the command from the current structure to the one @p edit makes of a copy of the scene. */
    template <typename Edit>
    bool editStructure(const std::vector<FragmentId>& touched, const CommandText& text, Edit edit);

    // The commands' primitives: change the scene and signal, without touching the undo stack.
    FragmentId allocateId() { return m_scene.allocateId(); }
    void insertFragment(int index, core::scene::Fragment fragment, OctreePtr octree);
    /** Removes the fragment; returns it and its octree (empty fragment when there is none). */
    std::pair<core::scene::Fragment, OctreePtr> takeFragment(FragmentId id);
    /** Applies @p change to the fragment and emits fragmentChanged(); false when there is none. */
    template <typename Change>
    bool changeFragment(FragmentId id, Change change);

    LabelStore& labelStore() { return *m_labels; }
    void changeLegend(const core::annotation::Legend& legend);
    void changePlate(const std::optional<core::plate::PlateSpec>& plate);
    /** Writes the changed labels into their octrees' files; false with @p error at the first failure. */
    bool saveLabels(QString* error);
    /** Brings the octrees into the folder of @p path (saveAs()); false with @p error when a copy fails. */
    bool gatherOctrees(const QString& path, OctreeCopies copies, QString* error);
    /** Takes @p id's labels from its opened octree; a failure goes to the load errors. */
    void loadLabels(FragmentId id);

    void resetScene(core::scene::Scene scene);
    /** Records the octrees the project file @p path references now (after a save or an open). */
    void noteProjectOctrees(const QString& path);
    void setProjectPath(const QString& path);
    void startLoad(FragmentId id);
    void loadEnded(FragmentId id, QFutureWatcherBase* watcher);
    void cancelLoads();

    TaskManager& m_tasks;
    QUndoStack* m_undo;
    /** The texts of the macros open or on the stack (QUndoStack makes their commands), by command; kept to
     *  the commands on the stack. */
    std::map<const QUndoCommand*, CommandText> m_macroTexts;
    bool m_cleanReset = false; ///< resetClean() was called since the last endMacro()
    core::scene::Scene m_scene;
    std::map<FragmentId, OctreePtr> m_octrees;
    QString m_octreeCache = defaultOctreeCacheFolder();
    std::map<FragmentId, DeveloppeePtr> m_developpees;
    std::map<FragmentId, QPointer<QFutureWatcherBase>> m_loads;  ///< octrees being opened
    QStringList m_loadErrors;                                    ///< for the next loadingFinished()
    QString m_path;
    QStringList m_importedOctrees;                 ///< built by imports (or copied by saves) in this session
    QStringList m_reservedOctrees;                 ///< being built by imports (reserveOctreePath())
    std::map<QString, QStringList> m_projectFiles; ///< per project file saved or opened: the octrees it references
    LabelStore* m_labels;
    quint64 m_lastStroke = 0;
};

template <typename Change>
bool SceneDocument::changeFragment(FragmentId id, Change change)
{
    core::scene::Fragment* f = m_scene.find(id);
    if (!f) return false;
    change(*f);
    Q_EMIT fragmentChanged(id);
    return true;
}

} // namespace stylos::widgets
