#include "stylos/widgets/docking/GuidesDisplay.h"

#include "docking/FragmentBounds.h"
#include "docking/GuidesOverlay.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QTimer>

namespace stylos::widgets {

GuidesDisplay::GuidesDisplay(SceneDocument& document, ViewportWidget& view, QObject* parent)
    : QObject(parent), m_document(document), m_view(&view), m_overlay(std::make_shared<GuidesOverlay>()),
      m_bounds(std::make_unique<FragmentBounds>())
{
    view.addOverlay(m_overlay);
    connect(&document, &SceneDocument::fragmentAdded, this, &GuidesDisplay::schedule);
    connect(&document, &SceneDocument::fragmentRemoved, this, &GuidesDisplay::schedule);
    connect(&document, &SceneDocument::fragmentChanged, this, &GuidesDisplay::schedule);
    connect(&document, &SceneDocument::octreeChanged, this, &GuidesDisplay::schedule);
    connect(&document, &SceneDocument::sceneReset, this, &GuidesDisplay::schedule);
    schedule();
}

GuidesDisplay::~GuidesDisplay()
{
    if (m_view) m_view->removeOverlay(m_overlay.get());
}

void GuidesDisplay::setVisible(bool visible)
{
    if (visible == m_overlay->isVisible()) return;
    m_overlay->setVisible(visible);
    if (m_view) m_view->requestFrame();
}

bool GuidesDisplay::isVisible() const { return m_overlay->isVisible(); }

int GuidesDisplay::segmentCount() const { return int(m_overlay->segments().size()); }

void GuidesDisplay::schedule()
{
    if (m_scheduled) return;
    m_scheduled = true;
    QTimer::singleShot(0, this, &GuidesDisplay::pushNow);
}

void GuidesDisplay::pushNow()
{
    m_scheduled = false;
    std::vector<core::view::GuideSegment> segments;
    for (const core::scene::Fragment& f : m_document.scene().fragments()) {
        if (!m_document.isShown(f.id) || f.guides.empty()) continue;
        const core::scene::Pose world = m_document.worldPose(f.id);
        const auto fragmentSegments = core::view::guideSegments(f, m_bounds->cells(m_document, f.id), &world);
        segments.insert(segments.end(), fragmentSegments.begin(), fragmentSegments.end());
    }
    m_overlay->setSegments(std::move(segments));
    if (m_view) m_view->requestFrame();
}

} // namespace stylos::widgets
