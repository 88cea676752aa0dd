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

} // namespace stylos::bench
