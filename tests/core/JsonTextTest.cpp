// util/JsonText.h: every JSON reader refuses bad text, a number too large for a double included, with one
// Malformed message naming the file, the line and column, and the problem. The overflow was found by
// PlateLayoutFuzzer (tests/fuzz): nlohmann throws out_of_range for it, which no reader caught (the process
// ended in std::terminate); tests/data/fuzz/plate/number-overflow.json is that input.
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/dock/GuidesFile.h"
#include "stylos/core/plate/PlateSpec.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/util/JsonText.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

using namespace stylos::core;

namespace {

const char* const Overflowing = "{\n  \"format\": \"stylos-x\",\n  \"version\": 1e400\n}\n";
const std::string OverflowProblem = ": line 3, column 18: not valid JSON: number overflow parsing '1e400'";

} // namespace

TEST(JsonText, ParsesValidText)
{
    auto parsed = parseJsonText("{\"a\": [1, 2.5, \"x\"], \"b\": null}", "t.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    EXPECT_EQ(parsed.value()["a"][1].get<double>(), 2.5);
    EXPECT_TRUE(parsed.value()["b"].is_null());
}

TEST(JsonText, ASyntaxErrorNamesTheLineAndColumn)
{
    auto parsed = parseJsonText("{\n  \"a\": tru\n}", "t.json");
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.error().code, ErrorCode::Malformed);
    EXPECT_EQ(parsed.error().message,
              "t.json: line 2, column 11: not valid JSON: syntax error while parsing value - invalid literal; "
              "last read: '\"a\": tru<U+000A>'");
}

TEST(JsonText, ANumberTooLargeForADoubleIsMalformedNotAnException)
{
    auto parsed = parseJsonText(Overflowing, "t.json");
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.error().code, ErrorCode::Malformed);
    EXPECT_EQ(parsed.error().message, "t.json" + OverflowProblem);
}

TEST(JsonText, EmptyTextIsMalformed)
{
    auto parsed = parseJsonText("", "t.json");
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.error().message,
              "t.json: line 1, column 1: not valid JSON: syntax error while parsing value - unexpected end of input; "
              "expected '[', '{', or a literal");
}

TEST(JsonText, ReadingAFileNamesIt)
{
    stylos::test::TempDir dir;
    EXPECT_EQ(readJsonFile(dir / "none.json").error().message, (dir / "none.json").string() + ": no such file");
    EXPECT_EQ(readJsonFile(dir.path()).error().code, ErrorCode::Unreadable);
}

TEST(JsonText, FuzzRegressionPlateLayoutWithANumberOverflow)
{
    const std::string path = std::string(STYLOS_TEST_DATA) + "/fuzz/plate/number-overflow.json";
    auto spec = plate::PlateSpec::read(path);
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::Malformed);
    EXPECT_EQ(spec.error().message, path + ": line 7, column 19: not valid JSON: number overflow parsing '101e308'");
}

TEST(JsonText, EveryJsonReaderRefusesANumberOverflow)
{
    stylos::test::TempDir dir;
    const auto path = dir / "overflow.json";
    stylos::test::writeText(path, Overflowing);
    const std::string expected = path.string() + OverflowProblem;
    EXPECT_EQ(annotation::Legend::read(path).error().message, expected);
    EXPECT_EQ(unroll::UnrollMap::readSidecar(path).error().message, expected);
    EXPECT_EQ(dock::readGuidesFile(path).error().message, expected);
    EXPECT_EQ(plate::PlateSpec::read(path.string()).error().message, expected);
    EXPECT_EQ(scene::ProjectFile::load(path).error().message, expected);
    EXPECT_EQ(scene::ProjectFile::fromJson(Overflowing, path).error().message, expected);
}
