#include "TestSupport.h"

#include "stylos/core/util/AtomicTextFile.h"

#include <gtest/gtest.h>

namespace stylos::core {
namespace {

std::string contents(const std::filesystem::path& path)
{
    const auto bytes = test::readBytes(path);
    return {bytes.begin(), bytes.end()};
}

TEST(AtomicTextFileTest, WritesThenReplacesLeavingNoTemporary)
{
    test::TempDir dir;
    const auto path = dir / "a.json";
    ASSERT_TRUE(writeTextFileAtomically(path, "{\"x\": 1}\n").ok());
    EXPECT_EQ(contents(path), "{\"x\": 1}\n");
    ASSERT_TRUE(writeTextFileAtomically(path, "2").ok());
    EXPECT_EQ(contents(path), "2");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(AtomicTextFileTest, FailureNamesThePathAndLeavesNothing)
{
    test::TempDir dir;
    const auto path = dir / "missing-folder" / "a.json";
    const auto status = writeTextFileAtomically(path, "x");
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
    EXPECT_EQ(status.error().message.rfind(path.string() + ": cannot create", 0), 0u) << status.error().message;
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
    // A folder in the way of the rename: the temporary is removed, the folder stays.
    std::filesystem::create_directory(dir / "taken");
    std::filesystem::create_directory(dir / "taken" / "inner");
    const auto blocked = writeTextFileAtomically(dir / "taken", "x");
    ASSERT_FALSE(blocked.ok());
    EXPECT_NE(blocked.error().message.find("cannot rename into place"), std::string::npos) << blocked.error().message;
    EXPECT_FALSE(std::filesystem::exists(dir / "taken.part"));
    EXPECT_TRUE(std::filesystem::is_directory(dir / "taken"));
}

} // namespace
} // namespace stylos::core
