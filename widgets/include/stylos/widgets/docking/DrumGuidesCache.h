#pragma once
/** @file
 * @brief The docking drum's guides with their flute profile (core::dock::DrumGuides), fitted once per drum and
 *        kept for the session: what docking and the contact readout need and the scene's guides (lines only) do
 *        not hold. The fit (a GuideFitJob) takes the axis and the flute count from the drum's first Axis guide and
 *        its Groove guides (its own frame, which is its octree's), so it only finds the radius, the depth, the phase
 *        and the profile. Keyed by the octree file, that axis and that count: other guides on the drum (Fit drum
 *        guides, undo) or another file mean another fit; a second dock against the same drum fits nothing.
 *        One fit per drum at a time, on the document's TaskManager through FragmentJobs (listed in the Tasks dock,
 *        cancelled with its drum or the project). GUI thread only.
 */
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/FragmentJobs.h"

#include <QObject>
#include <QString>

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace stylos::widgets {

struct GuideFitResult;

class DrumGuidesCache : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;
    using GuidesPtr = std::shared_ptr<const core::dock::DrumGuides>;
    enum class State { Ready, Fitting, Unavailable };

    /** @p document is not owned and must outlive the cache. */
    explicit DrumGuidesCache(SceneDocument& document, QObject* parent = nullptr);

    /** @brief What the drum's scene guides give the fit: its axis and flute count; nullopt without an Axis guide
     *         or with fewer than 3 Groove guides. */
    static std::optional<core::dock::GuideOptions> guideOptionsOf(const core::scene::Fragment& drum);

    /** @brief The fitted guides of @p drum for its current file and guides; null when not fitted yet. */
    GuidesPtr guides(FragmentId drum) const;
    /** @brief Ready when guides(@p drum) has them; Fitting when a fit runs (started now if needed): ready() or
     *         failed() follows; Unavailable when the drum is gone, has no octree open or no usable guides. */
    State request(FragmentId drum);
    /** @brief Fits done so far (each a task), for tests and the log. */
    int fits() const { return m_fits; }

Q_SIGNALS:
    /** @brief The guides of @p drum are in (guides() has them). */
    void ready(quint64 drum);
    /** @brief The fit of @p drum failed: @p message is translated and names the drum and the reason. */
    void failed(quint64 drum, const QString& message);

private:
    std::optional<std::string> keyOf(FragmentId drum) const;
    void delivered(FragmentId drum, const std::string& key, const GuideFitResult& result);

    SceneDocument& m_document;
    FragmentJobs m_jobs;
    std::map<std::string, GuidesPtr> m_guides;
    int m_fits = 0;
};

} // namespace stylos::widgets
