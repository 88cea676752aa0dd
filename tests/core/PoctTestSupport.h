#pragma once
// Helpers shared by the .poct tests: a file's bytes as unsigned bytes, and a tree written and reopened.
#include "TestSupport.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/PoctWriter.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

namespace stylos::test {

/** The whole file as bytes. */
inline std::vector<std::uint8_t> fileBytes(const std::filesystem::path& p)
{
    const auto c = readBytes(p);
    return {c.begin(), c.end()};
}

/** The little-endian value of type T at byte @p offset of a file image. */
template <typename T>
T valueAt(const std::vector<std::uint8_t>& bytes, std::size_t offset)
{
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

/** writePoct + open; fails the test (and returns nullptr) on error. */
inline std::unique_ptr<core::octree::PackedOctree> pack(const core::octree::OctreeLevels& levels, const TempDir& dir,
                                                        const char* name = "t.poct")
{
    const auto path = dir / name;
    const auto written = core::octree::writePoct(levels, path);
    EXPECT_TRUE(written.ok()) << (written.ok() ? "" : written.error().message);
    if (!written.ok()) return nullptr;
    auto opened = core::octree::PackedOctree::open(path);
    EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error().message);
    if (!opened.ok()) return nullptr;
    return std::make_unique<core::octree::PackedOctree>(std::move(opened).value());
}

} // namespace stylos::test
