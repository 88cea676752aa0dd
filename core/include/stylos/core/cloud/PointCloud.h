#pragma once
/** @file
 * @brief A point cloud held in memory for whole-cloud algorithms (surface fit, unrolling): positions
 *        in float relative to a double origin, optional unit normals, and the sampling spacing when the
 *        source knows it. 12 bytes per point (24 with normals): 30 M points take 360 MiB.
 *
 * Positions are stored relative to `origin` so that museum or site coordinates (hundreds of metres)
 * keep sub-micrometre resolution within a monument-sized object (float has 24 bits: a 2 m object
 * resolves 0.12 µm). Units: metres (or the file's own units). Thread-safety: a value type; concurrent
 * reads are safe.
 */
#include <Eigen/Core>

#include <cassert>
#include <cstddef>
#include <string>
#include <vector>

namespace stylos::core::cloud {

/** @brief Points (and optionally normals) as interleaved float arrays relative to a double origin. */
struct PointCloud {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero(); ///< world position of local (0, 0, 0), metres
    std::vector<float> positions; ///< x y z interleaved, relative to origin, size 3n
    std::vector<float> normals;   ///< nx ny nz interleaved unit vectors, size 3n or 0 (none)
    /** Sampling spacing in metres when the source states it (a .poct leaf edge); 0 when unknown. */
    double spacing = 0.0;
    std::string source; ///< the file it came from, for messages ("<memory>" otherwise)

    std::size_t size() const { return positions.size() / 3; }
    bool empty() const { return positions.empty(); }
    bool hasNormals() const { return !normals.empty(); }

    /** Local (origin-relative) position of point @p i, float precision widened to double. */
    Eigen::Vector3d local(std::size_t i) const
    {
        assert(i < size() && "PointCloud::local(): index out of range");
        return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    }
    /** World position of point @p i, metres. */
    Eigen::Vector3d world(std::size_t i) const { return origin + local(i); }
    /** Unit normal of point @p i; requires hasNormals(). */
    Eigen::Vector3d normal(std::size_t i) const
    {
        assert(hasNormals() && i < size() && "PointCloud::normal(): no normals or index out of range");
        return {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
    }
    /** Appends a point given in world coordinates (the origin must already be set). */
    void addWorld(const Eigen::Vector3d& p)
    {
        const Eigen::Vector3d l = p - origin;
        positions.push_back(static_cast<float>(l.x()));
        positions.push_back(static_cast<float>(l.y()));
        positions.push_back(static_cast<float>(l.z()));
    }
};

} // namespace stylos::core::cloud
