#include "TileSpool.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <system_error>

namespace stylos::core::normals::detail {
namespace {

struct FileCloser {
    void operator()(std::FILE* file) const
    {
        if (file) std::fclose(file);
    }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

std::string randomSuffix()
{
    std::random_device device;
    const auto ticks = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
    const std::uint64_t value = (std::uint64_t(device()) << 32) ^ device() ^ ticks;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

bool makeFreshDirectory(const std::filesystem::path& parent, const std::string& name, std::filesystem::path& made)
{
    for (int attempt = 0; attempt < 8; ++attempt) {
        std::error_code error;
        const auto candidate = parent / ("." + name + ".normals-" + randomSuffix());
        if (std::filesystem::create_directory(candidate, error) && !error) {
            made = candidate;
            return true;
        }
        if (!std::filesystem::is_directory(parent, error)) return false;
    }
    return false;
}

} // namespace

Result<std::unique_ptr<TileSpool>> TileSpool::create(const std::filesystem::path& parent, const std::string& name,
                                                     std::size_t tiles, std::size_t ownRecordBytes,
                                                     std::size_t haloValues, std::size_t bufferBytes)
{
    std::unique_ptr<TileSpool> spool(new TileSpool());
    std::error_code error;
    const auto fallback = std::filesystem::temp_directory_path(error);
    if (!makeFreshDirectory(parent.empty() ? "." : parent, name, spool->m_directory) &&
        (error || !makeFreshDirectory(fallback, name, spool->m_directory)))
        return Error::at(ErrorCode::WriteFailed, parent.string(), "",
                         "cannot create a temporary folder for the tiles (nor in " + fallback.string() + ")");
    spool->m_ownRecordBytes = ownRecordBytes;
    spool->m_haloRecordBytes = haloValues * sizeof(double);
    spool->m_bufferBytes = std::max({bufferBytes, ownRecordBytes, spool->m_haloRecordBytes});
    spool->m_buffers.resize(2 * tiles);
    spool->m_counts.assign(2 * tiles, 0);
    return spool;
}

TileSpool::~TileSpool()
{
    std::error_code ignored;
    if (!m_directory.empty()) std::filesystem::remove_all(m_directory, ignored);
}

std::filesystem::path TileSpool::file(std::uint32_t tile, Part part) const
{
    return m_directory / ("tile" + std::to_string(tile) + (part == Part::Own ? ".own" : ".halo"));
}

Status TileSpool::appendOwn(std::uint32_t tile, const unsigned char* record)
{
    auto& buffer = m_buffers[2 * std::size_t(tile)];
    if (buffer.capacity() == 0) buffer.reserve(m_bufferBytes);
    buffer.insert(buffer.end(), record, record + m_ownRecordBytes);
    ++m_counts[2 * std::size_t(tile)];
    return buffer.size() + m_ownRecordBytes > m_bufferBytes ? flushOne(tile, Part::Own) : Status{};
}

Status TileSpool::appendHalo(std::uint32_t tile, const double* values)
{
    auto& buffer = m_buffers[2 * std::size_t(tile) + 1];
    if (buffer.capacity() == 0) buffer.reserve(m_bufferBytes);
    const auto* bytes = reinterpret_cast<const unsigned char*>(values);
    buffer.insert(buffer.end(), bytes, bytes + m_haloRecordBytes);
    ++m_counts[2 * std::size_t(tile) + 1];
    return buffer.size() + m_haloRecordBytes > m_bufferBytes ? flushOne(tile, Part::Halo) : Status{};
}

Status TileSpool::flushOne(std::uint32_t tile, Part part)
{
    auto& buffer = m_buffers[2 * std::size_t(tile) + (part == Part::Own ? 0 : 1)];
    if (buffer.empty()) return {};
    const auto path = file(tile, part);
    FilePtr out(std::fopen(path.c_str(), "ab"));
    if (!out || std::fwrite(buffer.data(), 1, buffer.size(), out.get()) != buffer.size() ||
        std::fclose(out.release()) != 0)
        return Error::at(ErrorCode::WriteFailed, path.string(), "", std::string("write error: ") + std::strerror(errno));
    buffer.clear();
    return {};
}

Status TileSpool::flush()
{
    for (std::uint32_t tile = 0; tile < m_counts.size() / 2; ++tile)
        for (Part part : {Part::Own, Part::Halo}) {
            if (Status status = flushOne(tile, part); !status) return status;
            std::vector<unsigned char>().swap(m_buffers[2 * std::size_t(tile) + (part == Part::Own ? 0 : 1)]);
        }
    return {};
}

std::uint64_t TileSpool::count(std::uint32_t tile, Part part) const
{
    return m_counts[2 * std::size_t(tile) + (part == Part::Own ? 0 : 1)];
}

Status TileSpool::read(std::uint32_t tile, Part part,
                       const std::function<void(const unsigned char*, std::size_t)>& consume) const
{
    const std::uint64_t total = count(tile, part);
    if (total == 0) return {};
    const std::size_t recordBytes = part == Part::Own ? m_ownRecordBytes : m_haloRecordBytes;
    const auto path = file(tile, part);
    FilePtr in(std::fopen(path.c_str(), "rb"));
    if (!in) return Error::at(ErrorCode::Unreadable, path.string(), "", std::strerror(errno));
    const std::size_t chunk = std::max<std::size_t>(1, (1u << 20) / recordBytes);
    std::vector<unsigned char> bytes(chunk * recordBytes);
    for (std::uint64_t done = 0; done < total;) {
        const auto want = static_cast<std::size_t>(std::min<std::uint64_t>(chunk, total - done));
        if (std::fread(bytes.data(), recordBytes, want, in.get()) != want)
            return Error::at(ErrorCode::Truncated, path.string(), "record " + std::to_string(done),
                             "temporary tile file is shorter than written");
        consume(bytes.data(), want);
        done += want;
    }
    return {};
}

void TileSpool::discard(std::uint32_t tile)
{
    std::error_code ignored;
    std::filesystem::remove(file(tile, Part::Own), ignored);
    std::filesystem::remove(file(tile, Part::Halo), ignored);
}

} // namespace stylos::core::normals::detail
