#pragma once
// Internal to the octree builders: what both builders share — opening the source for each pass (and
// checking it), the root box (given or from a bounds pass), the point count every pass must find,
// progress over all passes, cancel, and the error messages.
#include "stylos/core/octree/ConstructionOctree.h"
#include "stylos/core/octree/OctreeBuild.h"

#include <optional>
#include <string>

namespace stylos::core::octree {

class BuildContext {
public:
    /** @p inputPasses: passes over the input besides the bounds pass (which is added when no box is given). */
    BuildContext(const PointSourceFactory& open, const BuildOptions& options, ProgressSink* progress,
                 int inputPasses);

    /** @brief Opens the source for the next pass; the first time also checks it has normals. */
    Result<std::unique_ptr<io::PointReader>> open();
    /** @brief options.box (the source is then only opened, to learn its schema), or the enclosing cube
     *         of a bounds pass over the source. Call it first. */
    Result<RootBox> rootBox();
    /** @brief The empty octree in @p box (OutOfBudget if even its root passes the memory limit). */
    Result<std::unique_ptr<ConstructionOctree>> newTree(const RootBox& box) const;
    /** @brief Ends a pass that read @p points points and dropped @p skipped: the first count becomes the
     *         expected one; a source with no points, or a count that changes, is an error. */
    Status endPass(std::uint64_t points, std::uint64_t skipped);

    /** @brief Progress: @p fraction of the current pass done. */
    void progress(double fraction) const;
    /** @brief Progress at the start of the work after the last pass (the pull). */
    void progressAfterPasses() const;
    bool cancelRequested() const { return m_progress && m_progress->isCancelRequested(); }

    Error cancelled() const;
    /** @brief OutOfBudget: the octree needs @p neededBytes (@p when, e.g. "at level 12"). */
    Error outOfBudget(std::uint64_t neededBytes, const std::string& when) const;
    /** @brief Malformed: a later pass did not meet the cells of the earlier passes. */
    Error inputChanged(const std::string& what) const;

    const std::string& name() const { return m_name; }
    bool hasColour() const { return m_hasColour; }
    std::optional<std::uint64_t> expectedPoints() const { return m_points; }
    std::uint64_t skippedPoints() const { return m_skipped; }
    int passes() const { return m_passes; }

private:
    const PointSourceFactory& m_open;
    const BuildOptions& m_options;
    ProgressSink* m_progress;
    int m_totalUnits;
    int m_passes = 0;
    std::string m_name = "<source>";
    bool m_hasColour = false;
    bool m_inspected = false;
    std::optional<std::uint64_t> m_points;
    std::uint64_t m_skipped = 0;
};

/** @brief InvalidArgument for a depth out of range, zero threads or a bad root box. */
Status checkBuildOptions(const BuildOptions& options);

/** @brief "812 MiB", "3.5 MiB", "12 KiB" — sizes in messages, rounded up (a need), or down (@p up false: a
 *         limit), so that a need above a limit never reads as the same figure. */
std::string formatBytes(std::uint64_t bytes, bool up = true);

} // namespace stylos::core::octree
