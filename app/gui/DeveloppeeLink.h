#pragma once
/** @file
 * @brief Makes the Développée dock and the 3D view one instrument: Compute in the dock runs a
 *        DeveloppeeJob for the dock's fragment on the document's TaskManager and shows its result; a click in the
 *        développée marks the 3D point in the view (through the fragment's pose), and a pick in the 3D
 *        view on that fragment marks it in the développée (through the inverse pose). The dock follows the
 *        current fragment (setFragment), offering its axis guide and showing the développée last
 *        computed for it (kept by the document, listed in the Scene dock). Several fragments may be
 *        computing at once; each result goes to its fragment. The jobs run through FragmentJobs: another
 *        project, or the fragment's removal, cancels them, and a result whose fragment or octree file is no
 *        longer the one it was computed for is dropped. The unrolling radius: with the guides' axis (the fragment's
 *        own, or its drum's), the leading radius of those guides (DrumGuidesCache, fitted first when needed), so a
 *        docked fragment and its drum unroll at the same scale; without the cache or usable guides (no flutes), the
 *        radius fitted about the axis. GUI thread only.
 */
#include "stylos/core/scene/Assembly.h"
#include "stylos/core/scene/Fragment.h"
#include "stylos/widgets/tasks/FragmentJobs.h"

#include <QObject>
#include <QPointer>

#include <Eigen/Core>

#include <optional>


namespace stylos::widgets {
class DeveloppeePanel;
struct DeveloppeeSettings;
class DrumGuidesCache;
struct DeveloppeeResult;
class SceneDocument;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class DeveloppeeLink : public QObject {
    Q_OBJECT

public:
    /** None owned; @p viewport may be null (no OpenGL: no 3D markers). The jobs run on the document's
     *  TaskManager. */
    DeveloppeeLink(widgets::SceneDocument& document, widgets::DeveloppeePanel& dock, widgets::ViewportWidget* viewport,
                   QObject* parent = nullptr);

    /** @brief The drum guides the unrolling radius comes from (not owned; null: none, the radius is fitted). */
    void setGuidesCache(widgets::DrumGuidesCache* cache);

    /** @brief The fragment Compute works on (the Scene dock's current one); NoFragment for none. */
    void setFragment(core::scene::FragmentId id);
    /** @brief The Scene dock's current row is assembly @p id: its développée (kept as its drum's by computeAssembly())
     *         is shown again, with no fragment for Compute (as right after it was computed); none: as setFragment(NoFragment). */
    void showAssembly(core::scene::AssemblyId id);

    /** @brief Marks @p scenePoint in the développée when it shows fragment @p id (else clears its marker). */
    void markInDeveloppee(const Eigen::Vector3d& scenePoint, core::scene::FragmentId id);

    /** @brief Computes the développée of the dock's fragment with the dock's settings (as Compute does). */
    void compute();
    /**
     * @brief Computes the développée of assembly @p id — its drum's, with every other member unrolled on the
     *        drum's axis guide at its place (AssemblyDeveloppeeJob) — shown in the dock and kept as the drum's.
     *        False, with finished(failed) saying why, when the assembly has no drum with an axis guide or an
     *        octree is not open.
     */
    bool computeAssembly(core::scene::AssemblyId id);
    /** @brief True while a développée of @p id computes. */
    bool isComputing(core::scene::FragmentId id) const { return m_jobs.isRunning(id); }

Q_SIGNALS:
    /** @brief A computation ended: @p message says what was made (or why not, @p failed). Translated. */
    void finished(const QString& message, bool failed);
    /** @brief A fragment was picked in an assembly's développée: select it. */
    void fragmentPicked(quint64 id);

private:
    void markInView(quint64 fragmentId, const Eigen::Vector3d& octreePoint);
    void refreshFragment();
    /** The fragment whose guides give @p fragment's axis: itself with an Axis guide, else its drum; NoFragment. */
    core::scene::FragmentId guidesOwner(const core::scene::Fragment& fragment) const;
    /** The leading radius and taper of @p owner's guides: set in @p settings (radius, radiusSlope), true; false (a fit
     *  started, compute again on its end: m_waiting) while it is fitted. Without guides to fit, true and neither. */
    bool leadingRadius(core::scene::FragmentId owner, widgets::DeveloppeeSettings& settings);
    void guidesArrived(core::scene::FragmentId owner, bool failed);

    widgets::SceneDocument& m_document;
    widgets::FragmentJobs m_jobs;
    widgets::DeveloppeePanel& m_dock;
    QPointer<widgets::ViewportWidget> m_viewport;
    core::scene::FragmentId m_fragment = core::scene::NoFragment;
    QPointer<widgets::DrumGuidesCache> m_cache;
    /** A computation waiting for its guides' fit: the guides' owner and what to compute (a fragment, or an
     *  assembly when @c assembly). */
    struct Waiting {
        core::scene::FragmentId owner = core::scene::NoFragment;
        core::scene::FragmentId fragment = core::scene::NoFragment;
        core::scene::AssemblyId assembly = core::scene::NoAssembly;
    };
    std::optional<Waiting> m_waiting;
    core::scene::FragmentId m_fitFailed = core::scene::NoFragment; ///< the guides whose fit failed last (no radius)
};

} // namespace stylos::app
