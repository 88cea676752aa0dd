#include "BuildContext.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace stylos::core::octree {

std::string formatBytes(std::uint64_t bytes, bool up)
{
    char text[64];
    const auto round = [up](double x) { return up ? std::ceil(x) : std::floor(x); };
    const double mib = double(bytes) / double(1u << 20);
    if (bytes >= (std::uint64_t(10) << 20))
        std::snprintf(text, sizeof text, "%.0f MiB", round(mib));
    else if (bytes >= (std::uint64_t(1) << 20))
        std::snprintf(text, sizeof text, "%.1f MiB", round(mib * 10) / 10);
    else
        std::snprintf(text, sizeof text, "%.0f KiB", round(double(bytes) / 1024));
    return text;
}

BuildContext::BuildContext(const PointSourceFactory& open, const BuildOptions& options, ProgressSink* progress,
                           int inputPasses)
    : m_open(open), m_options(options), m_progress(progress),
      m_totalUnits(inputPasses + (options.box ? 0 : 1) + 1)
{
}

Result<std::unique_ptr<io::PointReader>> BuildContext::open()
{
    auto reader = m_open();
    if (!reader.ok()) return reader.error();
    if (!*reader) return Error::at(ErrorCode::InvalidArgument, m_name, "", "the point source gave no reader");
    if (!m_inspected) {
        m_inspected = true;
        const io::PointReader& r = **reader;
        if (!r.path().empty()) m_name = r.path().string();
        else if (!r.header().format.empty()) m_name = r.header().format;
        if (!r.header().schema.hasNormals)
            return Error::at(ErrorCode::InvalidArgument, m_name, "",
                             "the points have no normals (estimate them first: stylos-cli normals, or build "
                             "from the file, which estimates them)");
        m_hasColour = r.header().schema.hasColors;
    }
    ++m_passes;
    return reader;
}

Result<RootBox> BuildContext::rootBox()
{
    if (m_options.box) {
        // No bounds pass, but the source's schema (normals, colour) is needed before the first pass.
        auto opened = open();
        if (!opened.ok()) return opened.error();
        m_passes = 0;
        return *m_options.box;
    }
    auto opened = open();
    if (!opened.ok()) return opened.error();
    io::PointReader& reader = **opened;
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::array<double, 6> bounds{inf, inf, inf, -inf, -inf, -inf};
    io::PointBatch batch;
    const std::optional<std::uint64_t> declared = reader.header().declaredPoints;
    for (;;) {
        auto n = reader.read(batch, 65536);
        if (!n.ok()) return n.error();
        if (*n == 0) break;
        const double* p = batch.positions.data();
        for (std::size_t i = 0; i < *n; ++i, p += 3) {
            for (int a = 0; a < 3; ++a) {
                bounds[a] = std::min(bounds[a], p[a]);
                bounds[a + 3] = std::max(bounds[a + 3], p[a]);
            }
        }
        progress(declared && *declared > 0 ? double(reader.pointsRead()) / double(*declared)
                 : reader.fileBytes() > 0  ? double(reader.bytesConsumed()) / double(reader.fileBytes())
                                           : 0.0);
        if (cancelRequested()) return cancelled();
    }
    const Status counted = endPass(reader.pointsRead(), reader.pointsSkipped());
    if (!counted.ok()) return counted.error();
    return RootBox::enclosing(bounds);
}

Result<std::unique_ptr<ConstructionOctree>> BuildContext::newTree(const RootBox& box) const
{
    const std::uint64_t minimum = ConstructionOctree::minimumBytes(m_hasColour);
    if (m_options.memoryLimit > 0 && m_options.memoryLimit < minimum) return outOfBudget(minimum, "at level 0");
    return std::make_unique<ConstructionOctree>(box, m_options.depth, m_options.normalCode, m_hasColour,
                                                m_options.memoryLimit);
}

Status BuildContext::endPass(std::uint64_t points, std::uint64_t skipped)
{
    m_skipped = skipped;
    if (!m_points) {
        if (points == 0)
            return Error::at(ErrorCode::Empty, m_name, "", "no points to build an octree from");
        m_points = points;
    } else if (points != *m_points) {
        return inputChanged("pass " + std::to_string(m_passes) + " read " + std::to_string(points) +
                            " points, the first pass " + std::to_string(*m_points));
    }
    return {};
}

void BuildContext::progress(double fraction) const
{
    if (!m_progress) return;
    const double done = double(m_passes - 1) + std::clamp(fraction, 0.0, 1.0);
    m_progress->update(std::clamp(done / double(m_totalUnits), 0.0, 1.0));
}

void BuildContext::progressAfterPasses() const
{
    if (m_progress) m_progress->update(double(m_passes) / double(m_totalUnits));
}

Error BuildContext::cancelled() const
{
    return Error::at(ErrorCode::Cancelled, m_name, "", "octree build cancelled");
}

Error BuildContext::outOfBudget(std::uint64_t neededBytes, const std::string& when) const
{
    return Error::at(ErrorCode::OutOfBudget, m_name, "",
                     "the octree needs " + formatBytes(neededBytes) + " " + when + " but the memory limit " +
                         "(--memory-limit) is " + formatBytes(m_options.memoryLimit, false));
}

Error BuildContext::inputChanged(const std::string& what) const
{
    return Error::at(ErrorCode::Malformed, m_name, "",
                     "the points changed between passes over the input (" + what + ")");
}

} // namespace stylos::core::octree
