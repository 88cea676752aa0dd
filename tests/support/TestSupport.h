#pragma once
// Helpers shared by the tests: where the fixtures are, and a temporary folder removed on exit.
#include "stylos/core/io/PointReader.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace stylos::test {

/** ../shared/data beside the clone (may be absent: use SKIP_WITHOUT_SHARED_DATA()). */
std::filesystem::path sharedData();
bool hasSharedData();

/** A fresh temporary folder, removed with everything in it when the object dies. */
class TempDir {
public:
    TempDir();
    /** A fresh folder under @p base (e.g. a memory-backed one for tests that rewrite files a lot). */
    explicit TempDir(const std::filesystem::path& base);
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return m_path; }
    std::filesystem::path operator/(const std::string& name) const { return m_path / name; }

private:
    std::filesystem::path m_path;
};

/** /dev/shm when it exists (memory-backed: fast for many rewrites), else the system temp folder. */
std::filesystem::path fastTempBase();

/**
 * Every point of @p reader, gathered from batches of @p maxPoints; checks on the way that no batch is
 * larger than asked and that pointsRead() matches.
 */
core::Result<core::io::PointBatch> readAllPoints(core::io::PointReader& reader, std::size_t maxPoints);

std::vector<char> readBytes(const std::filesystem::path& path);
void writeBytes(const std::filesystem::path& path, const std::vector<char>& bytes);
void writeText(const std::filesystem::path& path, const std::string& text);

} // namespace stylos::test

#define SKIP_WITHOUT_SHARED_DATA()                                                              \
    do {                                                                                        \
        if (!::stylos::test::hasSharedData())                                                   \
            GTEST_SKIP() << "../shared/data is absent: real-scan test skipped";                 \
    } while (0)
