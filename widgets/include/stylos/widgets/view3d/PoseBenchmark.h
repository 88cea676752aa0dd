#pragma once
/** @file
 * @brief Automation: changes one fragment's pose every frame for N frames and reports the frame times, for
 *        `stylos --pose-benchmark N FILE` and for measurements — what dragging a fragment with a gizmo costs.
 *        Each frame turns the fragment about the scene's vertical axis through the centre of its bounds by
 *        degreesPerFrame, from its pose when the view is ready, and hands the new pose to setPose (by default
 *        ViewportWidget::setFragmentPose; the workbench goes through the scene document as an edit would).
 *        Timing, waiting and the JSON result are FrameBenchmark's, plus "degreesPerFrame" and "fragmentId".
 *        GUI thread only. Failure modes: "error" in the result when the view has no such fragment.
 */
#include "stylos/widgets/view3d/FrameBenchmark.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>

namespace stylos::widgets {

class PoseBenchmark : public FrameBenchmark {
    Q_OBJECT

public:
    /** @brief Hands fragment @p id its new pose (octree frame → scene frame). */
    using SetPose = std::function<void(std::uint64_t id, const Eigen::Matrix4d& pose)>;

    struct Options {
        int frames = 360;
        double degreesPerFrame = 1.0;
        std::uint64_t fragmentId = 0;  ///< the fragment moved; 0: the view's first
        SetPose setPose;               ///< empty: ViewportWidget::setFragmentPose
        bool waitUntilRefined = true;
        int waitTimeoutMs = 120000;    ///< give up waiting for the first frame / refinement after this
    };

    PoseBenchmark(ViewportWidget& viewport, Options options, QObject* parent = nullptr);

protected:
    bool prepare(ViewportWidget& viewport) override;
    void advance(ViewportWidget& viewport, int frame) override;
    void describe(QJsonObject& result) const override;

private:
    Options m_options;
    Eigen::Matrix4d m_start = Eigen::Matrix4d::Identity();
    Eigen::Vector3d m_centre = Eigen::Vector3d::Zero();
};

} // namespace stylos::widgets
