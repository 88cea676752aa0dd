#include "TestSupport.h"

#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <random>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;

namespace stylos::test {

fs::path sharedData() { return fs::path(STYLOS_SHARED_DATA); }
bool hasSharedData() { return fs::is_directory(sharedData() / "formats"); }

TempDir::TempDir() : TempDir(fs::temp_directory_path()) {}

fs::path fastTempBase()
{
    std::error_code ec;
    if (fs::is_directory("/dev/shm", ec)) return "/dev/shm";
    return fs::temp_directory_path();
}

TempDir::TempDir(const fs::path& base)
{
    static std::atomic<int> counter{0};
    std::random_device rd;
    m_path = base /
             ("stylos-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" +
              std::to_string(rd()));
    fs::create_directories(m_path);
}

TempDir::~TempDir()
{
    std::error_code ec;
    fs::remove_all(m_path, ec);
}

core::Result<core::io::PointBatch> readAllPoints(core::io::PointReader& reader, std::size_t maxPoints)
{
    core::io::PointBatch all;
    all.reset(reader.header().schema, 0);
    core::io::PointBatch batch;
    for (;;) {
        auto got = reader.read(batch, maxPoints);
        if (!got) return got.error();
        if (*got == 0) break;
        EXPECT_LE(*got, maxPoints);
        EXPECT_EQ(batch.size(), *got);
        all.append(batch);
    }
    EXPECT_EQ(reader.pointsRead(), all.size());
    return all;
}

std::vector<char> readBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const fs::path& path, const std::vector<char>& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

void writeText(const fs::path& path, const std::string& text)
{
    writeBytes(path, std::vector<char>(text.begin(), text.end()));
}

} // namespace stylos::test
