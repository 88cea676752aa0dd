#pragma once
/** @file
 * @brief Automation: orbits the camera of a ViewportWidget for N frames and reports the frame times, for
 *        `stylos --orbit-benchmark N FILE` and for measurements. Each frame turns the camera about the
 *        scene's vertical axis through the target by degreesPerFrame (a continuous move: the view draws its
 *        moving frames); timing, waiting and the JSON result are FrameBenchmark's, plus "degreesPerFrame".
 *        GUI thread only.
 */
#include "stylos/widgets/view3d/FrameBenchmark.h"

namespace stylos::widgets {

class OrbitBenchmark : public FrameBenchmark {
    Q_OBJECT

public:
    struct Options {
        int frames = 360;
        double degreesPerFrame = 1.0;
        bool waitUntilRefined = true;
        int waitTimeoutMs = 120000;   ///< give up waiting for the first frame / refinement after this
    };

    OrbitBenchmark(ViewportWidget& viewport, const Options& options, QObject* parent = nullptr);

protected:
    void advance(ViewportWidget& viewport, int frame) override;
    void describe(QJsonObject& result) const override;

private:
    Options m_options;
};

} // namespace stylos::widgets
