#include "BenchmarkFiles.h"

#include "stylos/core/io/PlyWriter.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace stylos::bench {

namespace {

/** Point i of a drum of radius 0.55 m and height 0.5 m sampled on a spiral. */
void drumPoint(std::uint64_t i, std::uint64_t n, double& x, double& y, double& z)
{
    const double t = static_cast<double>(i) / static_cast<double>(n);
    const double turns = std::sqrt(static_cast<double>(n)) / 2;
    const double a = 2 * M_PI * turns * t;
    const double r = 0.55 - 0.008 * std::pow(std::sin(24 * a), 2);
    x = 1000.0 + r * std::cos(a);
    y = 2000.0 + r * std::sin(a);
    z = 50.0 + 0.5 * t;
}

template <typename T>
void put(std::vector<unsigned char>& out, std::size_t at, T v)
{
    std::memcpy(out.data() + at, &v, sizeof(T));
}

} // namespace

void writeBinaryPly(const std::filesystem::path& path, std::uint64_t points)
{
    core::io::PointSchema schema{false, false, {"scan_id"}};
    core::io::PlyWriterOptions options;
    options.positionType = core::io::PlyScalarType::Float32;
    options.scalarTypes = {core::io::PlyScalarType::UInt8};
    auto writer = core::io::PlyWriter::create(path, schema, options);
    if (!writer) throw std::runtime_error(writer.error().message);
    core::io::PointBatch batch;
    for (std::uint64_t done = 0; done < points;) {
        const std::uint64_t k = std::min<std::uint64_t>(points - done, 1 << 16);
        batch.reset(schema, k);
        for (std::uint64_t i = 0; i < k; ++i) {
            double x, y, z;
            drumPoint(done + i, points, x, y, z);
            // Small coordinates (float positions), as in object-scale scans.
            batch.positions.insert(batch.positions.end(), {x - 1000.0, y - 2000.0, z - 50.0});
            batch.scalars[0].push_back(static_cast<double>((done + i) % 3));
        }
        if (auto s = writer->write(batch); !s) throw std::runtime_error(s.error().message);
        done += k;
    }
    if (auto s = writer->finish(); !s) throw std::runtime_error(s.error().message);
}

void writeLas(const std::filesystem::path& path, std::uint64_t points)
{
    constexpr std::size_t headerSize = 227, recordSize = 34;
    std::vector<unsigned char> header(headerSize, 0);
    std::memcpy(header.data(), "LASF", 4);
    header[24] = 1; // version 1.2
    header[25] = 2;
    put<std::uint16_t>(header, 94, headerSize);
    put<std::uint32_t>(header, 96, headerSize);  // offset to point data
    put<std::uint32_t>(header, 100, 0);          // no VLRs
    header[104] = 3;                             // point format 3
    put<std::uint16_t>(header, 105, recordSize);
    put<std::uint32_t>(header, 107, static_cast<std::uint32_t>(points));
    const double scale = 0.0001, offset[3] = {1000.0, 2000.0, 50.0};
    for (int c = 0; c < 3; ++c) put<double>(header, 131 + 8 * c, scale);
    for (int c = 0; c < 3; ++c) put<double>(header, 155 + 8 * c, offset[c]);
    const double bounds[6] = {1000.56, 999.44, 2000.56, 1999.44, 50.5, 50.0}; // maxX minX maxY minY maxZ minZ
    for (int c = 0; c < 6; ++c) put<double>(header, 179 + 8 * c, bounds[c]);

    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path.string());
    std::fwrite(header.data(), 1, header.size(), f);
    std::vector<unsigned char> chunk;
    for (std::uint64_t done = 0; done < points;) {
        const std::uint64_t k = std::min<std::uint64_t>(points - done, 1 << 16);
        chunk.assign(k * recordSize, 0);
        for (std::uint64_t i = 0; i < k; ++i) {
            double x, y, z;
            drumPoint(done + i, points, x, y, z);
            const std::size_t at = i * recordSize;
            put<std::int32_t>(chunk, at + 0, static_cast<std::int32_t>(std::lround((x - offset[0]) / scale)));
            put<std::int32_t>(chunk, at + 4, static_cast<std::int32_t>(std::lround((y - offset[1]) / scale)));
            put<std::int32_t>(chunk, at + 8, static_cast<std::int32_t>(std::lround((z - offset[2]) / scale)));
            put<std::uint16_t>(chunk, at + 12, static_cast<std::uint16_t>(i & 0xffff));
            put<double>(chunk, at + 20, static_cast<double>(done + i));
            put<std::uint16_t>(chunk, at + 28, 0x8000);
            put<std::uint16_t>(chunk, at + 30, 0x4000);
            put<std::uint16_t>(chunk, at + 32, 0x2000);
        }
        std::fwrite(chunk.data(), 1, chunk.size(), f);
        done += k;
    }
    if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path.string());
}

void writeXyz(const std::filesystem::path& path, std::uint64_t points, bool normals)
{
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path.string());
    for (std::uint64_t i = 0; i < points; ++i) {
        double x, y, z;
        drumPoint(i, points, x, y, z);
        if (normals) {
            const double r = std::hypot(x - 1000.0, y - 2000.0);
            std::fprintf(f, "%.6f %.6f %.6f %.6f %.6f 0.000000\n", x, y, z, (x - 1000.0) / r, (y - 2000.0) / r);
        } else {
            std::fprintf(f, "%.6f %.6f %.6f\n", x, y, z);
        }
    }
    if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path.string());
}

} // namespace stylos::bench
