#pragma once
/** @file
 * @brief The développée of an assembly: the drum's développée with every docked fragment unrolled on the
 *        same guides (the drum's axis, pixel size and cut) and drawn at its place, so the reconstruction
 *        reads in 2D and the free places show. Each pixel knows which fragment it shows (picking one there
 *        selects it in 3D; its outline is drawn from it).
 *
 * Method. (1) The drum's own développée about the given axis (DeveloppeeOptions::axis, required) fixes the
 * pixel size and the cut angle. (2) Each piece's points, carried into the drum's frame, mark the pixels
 * they land in (within the unroller's band), grown by one pixel: the piece's footprint. (3) The drum's
 * points outside every footprint and the pieces' points within the band of the drum's surface (their
 * inner and fracture faces far from it are left out, so the radius fitted about the axis stays the drum's)
 * make one cloud, unrolled and shaded once with
 * the same axis, pixel size and cut (so the shading is continuous across a piece's edge and a piece shows
 * its own surface, not the drum's, where they coincide — docked pieces lie on the drum's surface). (4) Each
 * pixel's piece: the one whose point lies outermost there; a pixel with a height that no piece point reached
 * but inside a footprint (between sparse points, a filled hole), that footprint's piece; 0 for the drum's
 * own pixels and empty ones.
 *
 * Failure: what computeDeveloppee() returns (naming the drum's source), InvalidArgument without an axis or
 * with a piece id of 0. Units: metres. Thread-safety: reentrant. Memory: one copy of all the points as a
 * combined cloud (12 bytes each) beside the inputs.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace stylos::core::developpee {

/** @brief A docked piece: its cloud (file frame) and where it stands in the drum's file frame. */
struct AssemblyPiece {
    const cloud::PointCloud* cloud = nullptr;
    Eigen::Isometry3d toDrum = Eigen::Isometry3d::Identity(); ///< piece file frame → drum file frame
    std::uint64_t id = 0;                                      ///< the caller's (a fragment id), ≠ 0
};

struct AssemblyDeveloppee {
    Developpee developpee;              ///< of the drum and the pieces together, in the drum's file frame
    std::vector<std::uint64_t> pieceAt; ///< per pixel (row-major, the map's size): its piece's id, 0 for none
    /** The piece at pixel (@p column, @p row); 0 outside the image. */
    std::uint64_t pieceOf(int column, int row) const;
};

/** @brief See the file comment. @p options.axis is the drum's axis (its file frame). */
Result<AssemblyDeveloppee> computeAssemblyDeveloppee(const cloud::PointCloud& drum,
                                                     const std::vector<AssemblyPiece>& pieces,
                                                     const DeveloppeeOptions& options, ProgressSink* progress = nullptr);

} // namespace stylos::core::developpee
