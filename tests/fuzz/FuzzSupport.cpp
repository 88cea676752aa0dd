#include "FuzzSupport.h"

#include "stylos/core/io/E57PagedFile.h"
#include "stylos/core/io/PointBatch.h"
#include "stylos/core/util/Hash64.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace stylos::fuzz {

namespace fs = std::filesystem;

namespace {

fs::path makeScratchFolder()
{
    fs::path base = "/dev/shm";
    if (::access(base.c_str(), W_OK) != 0) {
        const char* tmp = std::getenv("TMPDIR");
        base = tmp && *tmp ? fs::path(tmp) : fs::path("/tmp");
    }
    fs::path folder = base / ("stylos-fuzz-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) broken("cannot create the scratch folder");
    std::atexit([] {
        std::error_code ignored;
        fs::remove_all(scratchFolder(), ignored);
    });
    return folder;
}

template <typename T>
T get(const std::uint8_t* p)
{
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template <typename T>
void put(std::uint8_t* p, T v)
{
    std::memcpy(p, &v, sizeof v);
}

} // namespace

void broken(const char* what)
{
    std::fprintf(stderr, "stylos-fuzz: contract broken: %s\n", what);
    std::abort();
}

const fs::path& scratchFolder()
{
    static const fs::path folder = makeScratchFolder();
    return folder;
}

fs::path writeScratch(const std::uint8_t* data, std::size_t size, std::string_view extension)
{
    fs::path path = scratchFolder() / ("input." + std::string(extension));
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) broken("cannot write the scratch file");
    if (size > 0 && std::fwrite(data, 1, size, f) != size) broken("cannot write the scratch file");
    std::fclose(f);
    return path;
}

void readAllPoints(const fs::path& path, const core::io::ReadOptions& options)
{
    auto opened = core::io::openPointReader(path, options);
    if (!opened) {
        if (opened.error().message.find(path.string()) == std::string::npos)
            broken("an open error does not name the file");
        return;
    }
    core::io::PointReader& reader = *opened.value();
    const core::io::PointSchema schema = reader.header().schema;
    core::io::PointBatch batch;
    std::uint64_t delivered = 0;
    for (;;) {
        auto got = reader.read(batch, 37);
        if (!got) {
            if (got.error().message.find(path.string()) == std::string::npos)
                broken("a read error does not name the file");
            return;
        }
        const std::size_t n = got.value();
        if (n == 0) break;
        if (n > 37) broken("a batch larger than asked for");
        if (batch.positions.size() != 3 * n) broken("positions do not match the batch size");
        if (batch.normals.size() != (schema.hasNormals ? 3 * n : 0)) broken("normals do not match the schema");
        if (batch.colors.size() != (schema.hasColors ? 3 * n : 0)) broken("colours do not match the schema");
        if (batch.scalars.size() != schema.scalarNames.size()) broken("scalar columns do not match the schema");
        for (const auto& column : batch.scalars)
            if (column.size() != n) broken("a scalar column does not match the batch size");
        for (double v : batch.positions)
            if (!std::isfinite(v)) broken("a non-finite position was delivered");
        delivered += n;
        if (reader.pointsRead() != delivered) broken("pointsRead() differs from the points delivered");
    }
    // Reading past the end keeps answering 0 (or an error), never more points.
    auto again = reader.read(batch, 37);
    if (again && again.value() != 0) broken("points after the end");
}

std::vector<std::uint8_t> withE57Checksums(const std::uint8_t* data, std::size_t size)
{
    std::vector<std::uint8_t> bytes(data, data + size);
    for (std::size_t page = 0; page + 1024 <= size; page += 1024) {
        const std::uint32_t crc = core::io::crc32c(bytes.data() + page, 1020);
        bytes[page + 1020] = static_cast<std::uint8_t>(crc >> 24);
        bytes[page + 1021] = static_cast<std::uint8_t>(crc >> 16);
        bytes[page + 1022] = static_cast<std::uint8_t>(crc >> 8);
        bytes[page + 1023] = static_cast<std::uint8_t>(crc);
    }
    return bytes;
}

std::vector<std::uint8_t> withPoctChecksums(const std::uint8_t* data, std::size_t size)
{
    // docs/file-format.md: a 64-byte fixed header (depth at 56, section count at 60), 8 bytes per level,
    // 48 bytes per section (offset at 24, length at 32, checksum at 40), then the header's XXH64.
    std::vector<std::uint8_t> bytes(data, data + size);
    if (size < 64) return bytes;
    const std::uint64_t depth = bytes[56];
    const std::uint64_t sections = get<std::uint32_t>(bytes.data() + 60);
    if (sections > 64) return bytes;
    const std::uint64_t table = 64 + 8 * (depth + 1);
    const std::uint64_t headerBytes = table + 48 * sections + 8;
    if (headerBytes > size) return bytes;
    for (std::uint64_t s = 0; s < sections; ++s) {
        std::uint8_t* entry = bytes.data() + table + 48 * s;
        const auto offset = get<std::uint64_t>(entry + 24);
        const auto length = get<std::uint64_t>(entry + 32);
        if (offset <= size && length <= size - offset)
            put<std::uint64_t>(entry + 40, core::xxh64(bytes.data() + offset, length));
    }
    put<std::uint64_t>(bytes.data() + headerBytes - 8, core::xxh64(bytes.data(), headerBytes - 8));
    return bytes;
}

} // namespace stylos::fuzz
