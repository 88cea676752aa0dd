// The one list of point-file extensions: its exact content and order, the importable ones (readable
// formats and .poct), case-insensitive matching, and that every readable extension really opens a
// reader while laz is refused and other names are unknown.
#include "stylos/core/io/PointFileFormat.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

using namespace stylos::core::io;
using stylos::core::ErrorCode;

TEST(PointFileFormat, TheListOfExtensions)
{
    std::vector<std::string> names;
    for (const auto& e : pointFileExtensions()) names.emplace_back(e.extension);
    EXPECT_EQ(names, (std::vector<std::string>{"ply", "las", "e57", "ptx", "xyz", "xyzn", "asc", "csv", "pts", "txt",
                                               "neu", "obj", "laz"}));
    EXPECT_EQ(importableExtensions(), (std::vector<std::string>{"ply", "las", "e57", "ptx", "xyz", "xyzn", "asc", "csv",
                                                                "pts", "txt", "neu", "obj", "poct"}));
    EXPECT_EQ(PoctExtension, "poct");
}

TEST(PointFileFormat, FormatFromExtensionIgnoresCase)
{
    EXPECT_EQ(formatFromExtension("scan.ply"), PointFormat::Ply);
    EXPECT_EQ(formatFromExtension("/data/SCAN.PLY"), PointFormat::Ply);
    EXPECT_EQ(formatFromExtension("a.Las"), PointFormat::Las);
    EXPECT_EQ(formatFromExtension("a.LAZ"), PointFormat::Laz);
    EXPECT_EQ(formatFromExtension("a.e57"), PointFormat::E57);
    EXPECT_EQ(formatFromExtension("a.PTX"), PointFormat::Ptx);
    EXPECT_EQ(formatFromExtension("a.obj"), PointFormat::Obj);
    for (const char* text : {"a.xyz", "a.xyzn", "a.asc", "a.CSV", "a.pts", "a.txt", "a.neu"})
        EXPECT_EQ(formatFromExtension(text), PointFormat::Text) << text;
    for (const char* other : {"a.poct", "a.stylos", "a.png", "a", "ply", "a.ply.gz", "a.plyx", "a."})
        EXPECT_EQ(formatFromExtension(other), PointFormat::Unknown) << other;
}

TEST(PointFileFormat, ImportableExtensions)
{
    for (const char* yes : {"a.ply", "b.LAS", "c.xyz", "d.neu", "e.obj", "f.poct", "g.POCT", "/x/y.txt", "h.e57", "i.Ptx"})
        EXPECT_TRUE(hasImportableExtension(yes)) << yes;
    for (const char* no : {"a.laz", "c.stylos", "d.png", "e", "f.poct.tmp", ".poct"})
        EXPECT_FALSE(hasImportableExtension(no)) << no;
    EXPECT_TRUE(hasPoctExtension("drum.Poct"));
    EXPECT_FALSE(hasPoctExtension("drum.ply"));
    EXPECT_FALSE(hasPoctExtension("poct"));
    EXPECT_TRUE(isReadable(PointFormat::Ply));
    EXPECT_TRUE(isReadable(PointFormat::Text));
    EXPECT_FALSE(isReadable(PointFormat::Laz));
    EXPECT_TRUE(isReadable(PointFormat::E57));
    EXPECT_TRUE(isReadable(PointFormat::Ptx));
    EXPECT_FALSE(isReadable(PointFormat::Unknown));
}

TEST(PointFileFormat, EveryListedExtensionReachesItsReader)
{
    stylos::test::TempDir dir;
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                            "property float z\nend_header\n1 2 3\n";
    for (const auto& e : pointFileExtensions()) {
        const auto path = dir / ("p." + std::string(e.extension));
        switch (e.format) {
        case PointFormat::Ply: stylos::test::writeText(path, ply); break;
        case PointFormat::Obj: stylos::test::writeText(path, "v 1 2 3\n"); break;
        case PointFormat::Las: continue; // binary: LasReaderTest
        case PointFormat::E57: continue; // binary: E57ReaderTest
        case PointFormat::Ptx:
            stylos::test::writeText(path, "1\n1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n1 2 3 0.5\n");
            break;
        default: stylos::test::writeText(path, "1 2 3\n"); break;
        }
        auto reader = openPointReader(path);
        if (isReadable(e.format)) {
            ASSERT_TRUE(reader.ok()) << e.extension << ": " << reader.error().message;
            const auto points = stylos::test::readAllPoints(**reader, 16);
            ASSERT_TRUE(points.ok()) << e.extension << ": " << points.error().message;
            EXPECT_EQ(points->positions, (std::vector<double>{1, 2, 3})) << e.extension;
        } else {
            ASSERT_FALSE(reader.ok()) << e.extension;
            EXPECT_EQ(reader.error().code, ErrorCode::Unsupported) << e.extension;
        }
    }
    stylos::test::writeText(dir / "p.dat", "1 2 3\n");
    auto unknown = openPointReader(dir / "p.dat");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().code, ErrorCode::UnknownFormat);
    EXPECT_NE(unknown.error().message.find(".ply, .las, .e57, .ptx, .xyz, .xyzn, .asc, .csv, .pts, .txt, .neu or .obj"),
              std::string::npos)
        << unknown.error().message;

    // An octree given where points are read (e.g. `stylos-cli build d.poct`) says it already is one.
    stylos::test::writeText(dir / "d.POCT", "not read\n");
    auto octree = openPointReader(dir / "d.POCT");
    ASSERT_FALSE(octree.ok());
    EXPECT_EQ(octree.error().code, ErrorCode::UnknownFormat);
    EXPECT_NE(octree.error().message.find("is a packed octree (.poct), not a point file: it is already built"),
              std::string::npos)
        << octree.error().message;
    // So does one renamed: recognised by its signature (it read "not a PLY file").
    stylos::test::writeText(dir / "renamed.ply", std::string("\x89POCT\r\n\x1A", 8) + std::string(56, '\0'));
    auto renamed = openPointReader(dir / "renamed.ply");
    ASSERT_FALSE(renamed.ok());
    EXPECT_EQ(renamed.error().message, (dir / "renamed.ply").string() +
                                           ": this is a packed octree (.poct), not a point file: it is already built. "
                                           "Open it in the workbench, describe it with `stylos-cli info`, or give the "
                                           "scan it was built from");
}

TEST(PointFileFormat, OptionsForOtherFormatsAreRefusedNotIgnored)
{
    stylos::test::TempDir dir;
    const auto ply = dir / "p.ply";
    stylos::test::writeText(ply, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                 "property float z\nend_header\n1 2 3\n");
    const auto xyz = dir / "p.xyz";
    stylos::test::writeText(xyz, "1 2 3\n");
    ReadOptions scan;
    scan.scan = 1;
    for (const auto& path : {ply, xyz}) {
        const auto r = openPointReader(path, scan);
        ASSERT_FALSE(r.ok()) << path;
        EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
        EXPECT_EQ(r.error().message,
                  path.string() + ": a scan number applies to E57 and PTX files (several scans); this file has one");
    }
    ReadOptions columns;
    columns.columns = "x y z";
    const auto r = openPointReader(ply, columns);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message,
              ply.string() + ": a column layout applies to text files (XYZ, PTS, TXT); this file names its own fields");
    // Where it applies, it is read.
    auto text = openPointReader(xyz, columns);
    ASSERT_TRUE(text.ok()) << text.error().message;
    const auto points = stylos::test::readAllPoints(**text, 16);
    ASSERT_TRUE(points.ok());
    EXPECT_EQ(points->positions, (std::vector<double>{1, 2, 3}));
}
