#include "BenchmarkFiles.h"

#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/io/PointFileFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numeric>
#include <random>
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

namespace {

/** One point as a fixed-size record: 3 doubles, then 3 floats, 3 bytes and the scalars (doubles) present. */
struct RecordLayout {
    explicit RecordLayout(const core::io::PointSchema& schema)
        : normals(schema.hasNormals), colours(schema.hasColors), scalars(schema.scalarNames.size())
    {
        bytes = 24 + (normals ? 12 : 0) + (colours ? 3 : 0) + 8 * scalars;
    }
    void pack(const core::io::PointBatch& b, std::size_t i, unsigned char* out) const
    {
        std::memcpy(out, &b.positions[3 * i], 24);
        out += 24;
        if (normals) {
            std::memcpy(out, &b.normals[3 * i], 12);
            out += 12;
        }
        if (colours) {
            std::memcpy(out, &b.colors[3 * i], 3);
            out += 3;
        }
        for (std::size_t s = 0; s < scalars; ++s, out += 8) std::memcpy(out, &b.scalars[s][i], 8);
    }
    void unpack(const unsigned char* in, core::io::PointBatch& b) const
    {
        double p[3];
        std::memcpy(p, in, 24);
        b.positions.insert(b.positions.end(), p, p + 3);
        in += 24;
        if (normals) {
            float n[3];
            std::memcpy(n, in, 12);
            b.normals.insert(b.normals.end(), n, n + 3);
            in += 12;
        }
        if (colours) {
            b.colors.insert(b.colors.end(), in, in + 3);
            in += 3;
        }
        for (std::size_t s = 0; s < scalars; ++s, in += 8) {
            double v;
            std::memcpy(&v, in, 8);
            b.scalars[s].push_back(v);
        }
    }
    bool normals, colours;
    std::size_t scalars, bytes = 0;
};

struct FileCloser {
    void operator()(std::FILE* f) const { if (f) std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

} // namespace

std::uint64_t writeShuffledCopy(const std::filesystem::path& input, const std::filesystem::path& output,
                                std::uint64_t seed, std::uint64_t pointsPerBucket)
{
    auto reader = core::io::openPointReader(input);
    if (!reader) throw std::runtime_error(reader.error().message);
    const core::io::PointSchema schema = (*reader)->header().schema;
    const RecordLayout layout(schema);
    const std::uint64_t expected = (*reader)->header().declaredPoints.value_or(pointsPerBucket);
    const std::size_t buckets = static_cast<std::size_t>(std::max<std::uint64_t>(1, (expected + pointsPerBucket - 1) / pointsPerBucket));

    // Pass 1: every point to a random bucket file (buffered writes).
    std::mt19937_64 random(seed);
    std::vector<std::filesystem::path> paths;
    std::vector<File> files;
    std::vector<std::vector<unsigned char>> buffers(buckets);
    for (std::size_t k = 0; k < buckets; ++k) {
        paths.push_back(output.string() + ".bucket" + std::to_string(k));
        files.emplace_back(std::fopen(paths.back().c_str(), "wb"));
        if (!files.back()) throw std::runtime_error("cannot write " + paths.back().string());
    }
    auto flush = [&](std::size_t k) {
        if (std::fwrite(buffers[k].data(), 1, buffers[k].size(), files[k].get()) != buffers[k].size())
            throw std::runtime_error("cannot write " + paths[k].string());
        buffers[k].clear();
    };
    core::io::PointBatch batch;
    std::uint64_t total = 0;
    for (;;) {
        auto got = (*reader)->read(batch, 1 << 16);
        if (!got) throw std::runtime_error(got.error().message);
        if (*got == 0) break;
        for (std::size_t i = 0; i < *got; ++i) {
            const std::size_t k = static_cast<std::size_t>(random() % buckets);
            auto& buffer = buffers[k];
            buffer.resize(buffer.size() + layout.bytes);
            layout.pack(batch, i, buffer.data() + buffer.size() - layout.bytes);
            if (buffer.size() >= (1u << 16)) flush(k);
        }
        total += *got;
    }
    for (std::size_t k = 0; k < buckets; ++k) {
        flush(k);
        files[k].reset();
    }

    // Pass 2: each bucket in memory, shuffled, appended to the output.
    core::io::PlyWriterOptions options;
    for (const auto& name : schema.scalarNames)
        options.scalarTypes.push_back(name == "scan_id" ? core::io::PlyScalarType::UInt8 : core::io::PlyScalarType::Float32);
    auto writer = core::io::PlyWriter::create(output, schema, options);
    if (!writer) throw std::runtime_error(writer.error().message);
    std::vector<unsigned char> records;
    std::vector<std::uint32_t> order;
    for (std::size_t k = 0; k < buckets; ++k) {
        const auto bytes = std::filesystem::file_size(paths[k]);
        records.resize(bytes);
        File in(std::fopen(paths[k].c_str(), "rb"));
        if (!in || std::fread(records.data(), 1, bytes, in.get()) != bytes)
            throw std::runtime_error("cannot read " + paths[k].string());
        in.reset();
        std::filesystem::remove(paths[k]);
        order.resize(bytes / layout.bytes);
        std::iota(order.begin(), order.end(), 0u);
        std::shuffle(order.begin(), order.end(), random);
        for (std::size_t done = 0; done < order.size();) {
            const std::size_t n = std::min<std::size_t>(order.size() - done, 1 << 16);
            batch.reset(schema, n);
            for (std::size_t i = 0; i < n; ++i) layout.unpack(records.data() + std::size_t(order[done + i]) * layout.bytes, batch);
            if (auto s = writer->write(batch); !s) throw std::runtime_error(s.error().message);
            done += n;
        }
    }
    if (auto s = writer->finish(); !s) throw std::runtime_error(s.error().message);
    return total;
}

} // namespace stylos::bench
