#pragma once
// Writers of large benchmark inputs in each format (a column-drum-like cloud of N points).
#include <cstdint>
#include <filesystem>

namespace stylos::bench {

/** Binary little-endian PLY: float x y z + uchar scan_id (the layout of the real Stanford scans). */
void writeBinaryPly(const std::filesystem::path& path, std::uint64_t points);
/** LAS 1.2, point format 3 (XYZ, intensity, GPS time, RGB), scale 0.0001. */
void writeLas(const std::filesystem::path& path, std::uint64_t points);
/** Text "x y z" with 6 decimals; with @p normals also "nx ny nz". */
void writeXyz(const std::filesystem::path& path, std::uint64_t points, bool normals);

/**
 * Copies the point file @p input into a binary PLY @p output (double positions, float normals, uchar
 * colours, "scan_id" as uchar and other scalars as float) with the points in a random order, in bounded
 * memory: each point goes to one of K temporary bucket files beside the output at random (K = points /
 * @p pointsPerBucket, rounded up), then each bucket is shuffled in memory and appended. Deterministic
 * for a seed. Returns the number of points. Throws std::runtime_error on any I/O error.
 */
std::uint64_t writeShuffledCopy(const std::filesystem::path& input, const std::filesystem::path& output,
                                std::uint64_t seed, std::uint64_t pointsPerBucket = 1u << 20);

} // namespace stylos::bench
