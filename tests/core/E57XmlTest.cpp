// The E57 XML section read on its own (core/io/E57Structure.h, parseE57Xml): a prototype's fields with
// their stated ranges, scales and offsets, the fallbacks where an attribute is absent, and an attribute
// that is not a number refused naming the field, the attribute and its text.
#include "stylos/core/io/E57Structure.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cstdint>
#include <limits>
#include <string>

using namespace stylos::core;
using namespace stylos::core::io;

namespace {

/** One scan whose prototype holds @p fields (XML elements). */
std::string scanXml(const std::string& fields)
{
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<e57Root type=\"Structure\">\n<data3D type=\"Vector\">\n"
           "<vectorChild type=\"Structure\"><guid type=\"String\">scan-1</guid>"
           "<points type=\"CompressedVector\" fileOffset=\"2048\" recordCount=\"7\"><prototype type=\"Structure\">" +
           fields + "</prototype><codecs type=\"Vector\"/></points></vectorChild>\n</data3D>\n</e57Root>\n";
}

Result<std::vector<E57Scan>> parse(const std::string& xml)
{
    return parseE57Xml(xml.data(), xml.size(), "scan.e57", "XML section at byte 1024");
}

} // namespace

TEST(E57Xml, FieldsTakeTheirRangesScalesAndOffsets)
{
    const auto scans = parse(scanXml(
        "<cartesianX type=\"ScaledInteger\" minimum=\"-1000\" maximum=\"3000\" scale=\"0.001\" offset=\"12.5\"/>"
        "<cartesianY type=\"Float\" precision=\"single\" minimum=\"-2.5\" maximum=\"4\"/>"
        "<intensity type=\"Integer\" minimum=\"0\" maximum=\"2047\"/>"));
    ASSERT_TRUE(scans.ok()) << scans.error().message;
    ASSERT_EQ(scans->size(), 1u);
    const E57Scan& scan = scans->front();
    EXPECT_EQ(scan.sectionOffset, 2048u);
    EXPECT_EQ(scan.recordCount, 7u);
    ASSERT_EQ(scan.fields.size(), 3u);
    const E57Field& x = scan.fields[0];
    EXPECT_EQ(x.name, "cartesianX");
    EXPECT_EQ(x.type, E57Field::Type::ScaledInteger);
    EXPECT_EQ(x.minimum, -1000);
    EXPECT_EQ(x.maximum, 3000);
    EXPECT_EQ(x.scale, 0.001);
    EXPECT_EQ(x.offset, 12.5);
    EXPECT_EQ(x.bits(), 12u); // 4000 values
    const E57Field& y = scan.fields[1];
    EXPECT_EQ(y.type, E57Field::Type::Float);
    EXPECT_TRUE(y.singlePrecision);
    EXPECT_EQ(y.floatMinimum, -2.5);
    EXPECT_EQ(y.floatMaximum, 4.0);
    EXPECT_EQ(scan.fields[2].maximum, 2047);
    EXPECT_EQ(scan.fields[2].bits(), 11u);
}

TEST(E57Xml, AbsentAttributesTakeTheirDefaults)
{
    const auto scans = parse(scanXml("<cartesianX type=\"ScaledInteger\"/><cartesianY type=\"Float\"/>"));
    ASSERT_TRUE(scans.ok()) << scans.error().message;
    const E57Field& x = scans->front().fields[0];
    EXPECT_EQ(x.minimum, std::numeric_limits<std::int64_t>::min());
    EXPECT_EQ(x.maximum, std::numeric_limits<std::int64_t>::max());
    EXPECT_EQ(x.scale, 1.0);
    EXPECT_EQ(x.offset, 0.0);
    const E57Field& y = scans->front().fields[1];
    EXPECT_EQ(y.floatMinimum, -DBL_MAX);
    EXPECT_EQ(y.floatMaximum, DBL_MAX);
}

TEST(E57Xml, AnAttributeThatIsNotANumberIsNamed)
{
    struct Case {
        const char* field;
        const char* expected;
    };
    const Case cases[] = {
        {"<intensity type=\"Integer\" minimum=\"0\" maximum=\"x2047\"/>",
         "prototype field <intensity>: attribute maximum=\"x2047\" is not an integer"},
        {"<intensity type=\"Integer\" minimum=\"1.5\" maximum=\"9\"/>",
         "prototype field <intensity>: attribute minimum=\"1.5\" is not an integer"},
        {"<cartesianX type=\"ScaledInteger\" minimum=\"0\" maximum=\"9\" scale=\"one\"/>",
         "prototype field <cartesianX>: attribute scale=\"one\" is not a number"},
        {"<cartesianX type=\"ScaledInteger\" minimum=\"0\" maximum=\"9\" offset=\"\"/>",
         "prototype field <cartesianX>: attribute offset=\"\" is not a number"},
        {"<cartesianY type=\"Float\" minimum=\"-inf?\"/>",
         "prototype field <cartesianY>: attribute minimum=\"-inf?\" is not a number"},
    };
    for (const Case& c : cases) {
        const auto scans = parse(scanXml(c.field));
        ASSERT_FALSE(scans.ok()) << c.field;
        EXPECT_EQ(scans.error().code, ErrorCode::Malformed) << c.field;
        EXPECT_NE(scans.error().message.find("scan.e57"), std::string::npos) << scans.error().message;
        EXPECT_NE(scans.error().message.find(c.expected), std::string::npos) << scans.error().message;
    }
}
