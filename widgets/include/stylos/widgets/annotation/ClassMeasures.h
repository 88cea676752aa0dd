#pragma once
/** @file
 * @brief Per annotation class, the cell (leaf) count and the surface area on the object, over every fragment of
 *        the project: core::annotation::leafAreas (each leaf's share of the surface, from the octree — computed
 *        once per fragment and octree file, cached) and measureClasses (labels × areas), run as a background
 *        task per fragment (FragmentJobs on the document's TaskManager, listed in the Tasks dock). A fragment is
 *        measured again only when its labels change (LabelStore::labelsChanged; changes within one event-loop
 *        turn and while its task runs are gathered into one new run); the other fragments' figures are kept.
 *        A fragment with no label at all is not measured (no leaf areas computed until something is painted).
 *        A fragment that is removed drops out of the sums; a new project forgets everything.
 * GUI thread only; the tasks read shared, read-only snapshots of the labels and the octree.
 */
#include "stylos/core/annotation/LabelArea.h"
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/scene/Fragment.h"

#include <QObject>
#include <QTimer>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace stylos::widgets {

class FragmentJobs;
class SceneDocument;

class ClassMeasures : public QObject {
    Q_OBJECT

public:
    using AnnotationLayer = core::annotation::AnnotationLayer;
    using FragmentId = core::scene::FragmentId;

    /** @p document is not owned and must outlive this. */
    explicit ClassMeasures(SceneDocument& document, QObject* parent = nullptr);
    ~ClassMeasures() override;

    /** @brief The sum over the fragments measured so far, of class @p classId of @p layer. */
    core::annotation::ClassMeasure total(AnnotationLayer layer, std::uint8_t classId) const;
    /** @brief True while a fragment waits to be measured or is being measured. */
    bool isBusy() const;
    /** @brief How many times a fragment's leaf areas were computed (a cache check for tests). */
    int areaRuns() const { return m_areaRuns; }

Q_SIGNALS:
    /** @brief total() changed (a fragment was measured or dropped). */
    void changed();

private:
    struct Entry {
        std::shared_ptr<const std::vector<double>> areas; ///< per leaf; null until computed
        std::array<std::vector<core::annotation::ClassMeasure>, 2> measures;
    };
    void labelsChanged(quint64 fragment);
    void startPending();
    void start(FragmentId id);

    SceneDocument& m_document;
    FragmentJobs* m_jobs;
    std::map<FragmentId, Entry> m_entries;
    std::set<FragmentId> m_pending;
    QTimer m_turn; ///< gathers the changes of one event-loop turn
    int m_areaRuns = 0;
};

} // namespace stylos::widgets
