// Orthographic print render of packed octrees on the CPU: oriented discs in a software z-buffer.
#include "stylos/core/plate/OrthoRender.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>

namespace stylos::core::plate {

namespace {

namespace oct = octree;

/** A source's leaves in the view frame: x right, y up, z toward the viewer. */
struct ViewTransform {
    Eigen::Matrix3d rotation;     // octree frame → view frame
    Eigen::Vector3d translation;
    Eigen::Vector3d apply(const std::array<double, 3>& p) const
    {
        return rotation * Eigen::Vector3d(p[0], p[1], p[2]) + translation;
    }
};

ViewTransform viewTransform(const OrthoSource& source, const OrthoOptions& options)
{
    const Eigen::Matrix3d camera = (options.orientation ? options.orientation->normalized()
                                                        : view::Camera::standardOrientation(options.view))
                                       .toRotationMatrix(); // camera → scene
    Eigen::Matrix3d r;
    Eigen::Vector3d t;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) r(i, j) = source.pose(i, j);
        t[i] = source.pose(i, 3);
    }
    return {camera.transpose() * r, camera.transpose() * t};
}

std::span<const float> ambientOf(const oct::PackedOctree& octree)
{
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    const auto layer = octree.attribute("ambient");
    if (!layer || layer->type != oct::AttributeType::Float32 || layer->components != 1 || layer->bytes.size() != 4 * leaves)
        return {};
    return {reinterpret_cast<const float*>(layer->bytes.data()), std::size_t(leaves)};
}

Status checkSources(std::span<const OrthoSource> sources, const OrthoOptions& options)
{
    if (sources.empty()) return Error{ErrorCode::InvalidArgument, "a 3D panel needs at least one octree"};
    if (!(options.pixelSizeM > 0) || !std::isfinite(options.pixelSizeM))
        return Error{ErrorCode::InvalidArgument, "the pixel size of a 3D panel must be a positive length"};
    for (const OrthoSource& s : sources) {
        assert(s.octree);
        const std::uint64_t leaves = s.octree->cellCount(s.octree->depth());
        if (!s.labels.empty() && s.labels.size() != leaves)
            return Error{ErrorCode::InvalidArgument, s.octree->path().string() + ": " + std::to_string(s.labels.size()) +
                                                         " labels for " + std::to_string(leaves) + " leaves"};
        if (options.shading == PanelShading::Skydome && ambientOf(*s.octree).empty())
            return Error{ErrorCode::InvalidArgument,
                         s.octree->path().string() +
                             ": has no skydome (\"ambient\" layer); compute it first (stylos-cli ao, or Compute skydome "
                             "in the workbench) or use headlight shading"};
    }
    return {};
}


struct Bounds {
    double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double hi[2] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    std::uint64_t leaves = 0;
};

/** The view-plane bounds of every leaf's disc (one pass over the leaves). */
Bounds boundsOf(std::span<const OrthoSource> sources, const OrthoOptions& options)
{
    Bounds b;
    for (const OrthoSource& s : sources) {
        const ViewTransform t = viewTransform(s, options);
        s.octree->forEachCell(s.octree->depth(), [&](const oct::CellView& c) {
            const Eigen::Vector3d v = t.apply(c.centre);
            const double r = double(s.octree->leafSpacing(c.index)) * options.splatScale;
            b.lo[0] = std::min(b.lo[0], v.x() - r), b.hi[0] = std::max(b.hi[0], v.x() + r);
            b.lo[1] = std::min(b.lo[1], v.y() - r), b.hi[1] = std::max(b.hi[1], v.y() + r);
            ++b.leaves;
            return true;
        });
    }
    return b;
}

/** The frame of @p b at the options' pixel size, or OutOfBudget. */
Result<OrthoRender> frameOf(const Bounds& b, const OrthoOptions& options)
{
    OrthoRender out;
    out.leaves = b.leaves;
    if (b.leaves == 0) return Error{ErrorCode::InvalidArgument, "the 3D panel's octrees hold no leaves"};
    const double p = options.pixelSizeM;
    const double w = std::ceil((b.hi[0] - b.lo[0]) / p), h = std::ceil((b.hi[1] - b.lo[1]) / p);
    if (w * h > double(options.maxPixels) || w > 1e6 || h > 1e6) {
        char text[200];
        std::snprintf(text, sizeof text, "a %.0f × %.0f pixel render (%.0f Mpx, %.1f GB) is larger than the %.0f Mpx limit",
                      w, h, w * h / 1e6, w * h * 7 / 1e9, double(options.maxPixels) / 1e6);
        return Error{ErrorCode::OutOfBudget, text};
    }
    out.image.width = std::max(1, int(w));
    out.image.height = std::max(1, int(h));
    out.image.pixelSizeM = p;
    out.extentM[0] = out.image.width * p;
    out.extentM[1] = out.image.height * p;
    return out;
}

} // namespace

view::StandardView standardViewOf(PanelView view)
{
    switch (view) {
    case PanelView::Front: return view::StandardView::Front;
    case PanelView::Back: return view::StandardView::Back;
    case PanelView::Left: return view::StandardView::Left;
    case PanelView::Right: return view::StandardView::Right;
    case PanelView::Top: return view::StandardView::Top;
    case PanelView::Bottom: return view::StandardView::Bottom;
    case PanelView::Developpee:
    case PanelView::Camera: break;
    }
    assert(false && "standardViewOf: a développée or a camera view has no standard side");
    return view::StandardView::Front;
}

Eigen::Quaterniond panelOrientation(const PanelSpec& panel)
{
    if (panel.view == PanelView::Camera && panel.camera) {
        const auto& q = *panel.camera;
        return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
    }
    return view::Camera::standardOrientation(standardViewOf(panel.view));
}

Result<OrthoRender> measureOrtho(std::span<const OrthoSource> sources, const OrthoOptions& options)
{
    if (auto s = checkSources(sources, options); !s) return s.error();
    return frameOf(boundsOf(sources, options), options);
}

Result<OrthoRender> renderOrtho(std::span<const OrthoSource> sources, const OrthoOptions& options, ProgressSink* progress)
{
    if (auto s = checkSources(sources, options); !s) return s.error();
    const Bounds bounds = boundsOf(sources, options);
    auto framed = frameOf(bounds, options);
    if (!framed) return framed.error();
    OrthoRender out = std::move(framed).value();
    const double* lo = bounds.lo;
    const double* hi = bounds.hi;
    const int W = out.image.width, H = out.image.height;
    const double p = options.pixelSizeM;
    // Centre the content: the frame is ceil()ed, so split the slack on both sides.
    const double left = lo[0] - 0.5 * (W * p - (hi[0] - lo[0]));
    const double top = hi[1] + 0.5 * (H * p - (hi[1] - lo[1]));
    const std::size_t pixels = std::size_t(W) * std::size_t(H);
    std::vector<float> depth(pixels, -std::numeric_limits<float>::infinity());
    std::vector<std::uint16_t> grey(pixels, 65535);
    std::vector<std::uint8_t> classes(options.keepClasses ? pixels : 0, 0);

    std::uint64_t done = 0;
    bool cancelled = false;
    for (const OrthoSource& s : sources) {
        const ViewTransform t = viewTransform(s, options);
        const std::span<const float> ambient = options.shading == PanelShading::Skydome ? ambientOf(*s.octree) : std::span<const float>{};
        const bool labelled = options.keepClasses && !s.labels.empty();
        s.octree->forEachCell(s.octree->depth(), [&](const oct::CellView& c) {
            if ((++done & 0xFFFFF) == 0 && progress) {
                progress->update(std::min(1.0, double(done) / double(out.leaves)));
                if (progress->isCancelRequested()) return !(cancelled = true);
            }
            const Eigen::Vector3d v = t.apply(c.centre);
            const Eigen::Vector3d n = t.rotation * Eigen::Vector3d(c.normal[0], c.normal[1], c.normal[2]);
            const double r = double(s.octree->leafSpacing(c.index)) * options.splatScale;
            const double facing = std::abs(n.z());
            double shade = options.shading == PanelShading::Skydome ? double(ambient[c.index]) * (0.8 + 0.2 * facing)
                                                                    : 0.12 + 0.88 * facing;
            const std::uint16_t g = std::uint16_t(std::lround(std::clamp(shade, 0.0, 1.0) * 65535.0));
            const std::uint8_t id = labelled ? s.labels[c.index] : 0;
            const double cx = (v.x() - left) / p, cy = (top - v.y()) / p; // continuous pixel coordinates
            const double rp = r / p;
            const bool plane = facing > 0.3;
            const double gx = plane ? -n.x() / n.z() : 0.0, gy = plane ? -n.y() / n.z() : 0.0; // depth slope per metre
            const int x0 = std::max(0, int(std::floor(cx - rp))), x1 = std::min(W - 1, int(std::floor(cx + rp)));
            const int y0 = std::max(0, int(std::floor(cy - rp))), y1 = std::min(H - 1, int(std::floor(cy + rp)));
            if (x0 > x1 || y0 > y1) {
                return true;
            }
            const double r2 = r * r;
            bool any = false;
            for (int y = y0; y <= y1; ++y) {
                const double dy = (cy - (double(y) + 0.5)) * p; // metres, up
                for (int x = x0; x <= x1; ++x) {
                    const double dx = ((double(x) + 0.5) - cx) * p;
                    const double dz = gx * dx + gy * dy;
                    if (dx * dx + dy * dy + dz * dz > r2) continue;
                    const std::size_t k = std::size_t(y) * std::size_t(W) + std::size_t(x);
                    const float z = float(v.z() + dz);
                    any = true;
                    if (z <= depth[k]) continue;
                    depth[k] = z;
                    grey[k] = g;
                    if (!classes.empty()) classes[k] = id;
                }
            }
            if (!any) { // a disc smaller than a pixel: its centre's pixel
                const int x = std::clamp(int(std::floor(cx)), 0, W - 1), y = std::clamp(int(std::floor(cy)), 0, H - 1);
                const std::size_t k = std::size_t(y) * std::size_t(W) + std::size_t(x);
                if (float(v.z()) > depth[k]) {
                    depth[k] = float(v.z());
                    grey[k] = g;
                    if (!classes.empty()) classes[k] = id;
                }
            }
            return true;
        });
        if (cancelled) return Error{ErrorCode::Cancelled, "rendering the 3D panel was cancelled"};
    }
    if (progress) progress->update(1.0);
    out.image.channels = 1;
    out.image.samples = std::move(grey);
    out.image.classes = std::move(classes);
    return out;
}

} // namespace stylos::core::plate
