// Cells and areas per annotation class, measured per fragment in the background and summed.
#include "stylos/widgets/annotation/ClassMeasures.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/FragmentJobs.h"

#include <QFuture>

#include <algorithm>

namespace stylos::widgets {

namespace {

using core::annotation::ClassMeasure;

struct MeasureResult {
    std::shared_ptr<const std::vector<double>> areas;
    std::array<std::vector<ClassMeasure>, 2> measures;
    bool areasComputed = false;
};

} // namespace

ClassMeasures::ClassMeasures(SceneDocument& document, QObject* parent)
    : QObject(parent), m_document(document), m_jobs(new FragmentJobs(document, this))
{
    m_turn.setSingleShot(true);
    m_turn.setInterval(0);
    connect(&m_turn, &QTimer::timeout, this, &ClassMeasures::startPending);
    connect(&document.labels(), &LabelStore::labelsChanged, this,
            [this](quint64 fragment, int, const std::vector<std::uint32_t>&) { labelsChanged(fragment); });
    connect(&document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        m_pending.erase(id);
        if (m_entries.erase(id)) Q_EMIT changed();
    });
    connect(&document, &SceneDocument::fragmentAdded, this, [this](quint64 id) {
        if (m_document.labels().has(id)) labelsChanged(id); // back by an undo: measure it again
    });
    connect(&document, &SceneDocument::sceneReset, this, [this] {
        m_pending.clear();
        m_entries.clear();
        Q_EMIT changed();
    });
    connect(m_jobs, &FragmentJobs::ended, this, [this](quint64, bool) {
        if (!m_pending.empty()) m_turn.start(); // changes that came while it ran
    });
}

ClassMeasures::~ClassMeasures() = default;

ClassMeasure ClassMeasures::total(AnnotationLayer layer, std::uint8_t classId) const
{
    ClassMeasure sum;
    const std::size_t slot = layer == AnnotationLayer::Material ? 0 : 1;
    for (const auto& [id, entry] : m_entries) {
        if (entry.measures[slot].size() <= classId) continue;
        sum.cells += entry.measures[slot][classId].cells;
        sum.areaM2 += entry.measures[slot][classId].areaM2;
    }
    return sum;
}

bool ClassMeasures::isBusy() const { return !m_pending.empty() || m_jobs->count() > 0; }

void ClassMeasures::labelsChanged(quint64 fragment)
{
    m_pending.insert(fragment);
    m_turn.start();
}

void ClassMeasures::startPending()
{
    for (auto it = m_pending.begin(); it != m_pending.end();) {
        const FragmentId id = *it;
        if (m_jobs->isRunning(id)) { // again once it ends
            ++it;
            continue;
        }
        it = m_pending.erase(it);
        start(id);
    }
}

void ClassMeasures::start(FragmentId id)
{
    const SceneDocument::OctreePtr octree = m_document.octree(id);
    const auto material = m_document.labels().labels(id, AnnotationLayer::Material);
    const auto toolmark = m_document.labels().labels(id, AnnotationLayer::Toolmark);
    if (!octree || !material || !toolmark || material->size() != core::annotation::leafCount(*octree)) return;
    const auto found = m_entries.find(id);
    std::shared_ptr<const std::vector<double>> areas = found != m_entries.end() ? found->second.areas : nullptr;
    if (areas && areas->size() != material->size()) areas = nullptr; // another octree since
    const auto job = [octree, material, toolmark, areas](QPromise<MeasureResult>& promise, core::ProgressSink& progress) {
        MeasureResult result;
        result.areas = areas;
        const auto unlabelled = [](const std::vector<std::uint8_t>& l) {
            return std::all_of(l.begin(), l.end(), [](std::uint8_t id) { return id == 0; });
        };
        if (!result.areas && unlabelled(*material) && unlabelled(*toolmark)) {
            promise.addResult(std::move(result)); // nothing painted yet: no class to measure, no areas needed
            return;
        }
        if (!result.areas) {
            auto computed = core::annotation::leafAreas(*octree, {}, &progress);
            if (!computed) return; // cancelled (leafAreas fails no other way): no result
            result.areas = std::make_shared<const std::vector<double>>(std::move(computed).value());
            result.areasComputed = true;
        }
        result.measures[0] = core::annotation::measureClasses(*material, *result.areas);
        result.measures[1] = core::annotation::measureClasses(*toolmark, *result.areas);
        promise.addResult(std::move(result));
    };
    const QString name = QString::fromStdString(m_document.fragment(id) ? m_document.fragment(id)->name : std::string());
    m_jobs->start<MeasureResult>(id, tr("Areas of the classes of %1").arg(name), job,
                                 [this](FragmentId key, const QFuture<MeasureResult>& future) {
        if (future.resultCount() == 0) return;
        MeasureResult result = future.result();
        if (result.areasComputed) ++m_areaRuns;
        Entry& entry = m_entries[key];
        entry.areas = std::move(result.areas);
        entry.measures = std::move(result.measures);
        Q_EMIT changed();
    });
}

} // namespace stylos::widgets
