#include "stylos/widgets/view3d/OrbitBenchmark.h"

#include "stylos/widgets/view3d/ViewportWidget.h"

#include <cmath>

namespace stylos::widgets {

OrbitBenchmark::OrbitBenchmark(ViewportWidget& viewport, const Options& options, QObject* parent)
    : FrameBenchmark(viewport, {options.frames, options.waitUntilRefined, options.waitTimeoutMs}, parent),
      m_options(options)
{
}

void OrbitBenchmark::advance(ViewportWidget& viewport, int)
{
    core::view::Camera camera = viewport.camera();
    camera.orbit(m_options.degreesPerFrame * M_PI / 180.0, 0.0);
    viewport.setCamera(camera, true);
}

void OrbitBenchmark::describe(QJsonObject& result) const { result["degreesPerFrame"] = m_options.degreesPerFrame; }

} // namespace stylos::widgets
