// Projects that travel: planGather/gather bring a scene's octrees into the project's folder (cache octrees
// always, others unless left where they are; shared ones once; names made unique), and cleanCache removes
// only what nothing uses.
#include "TestSupport.h"

#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/scene/ProjectOctrees.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace stylos::core::scene {
namespace {

std::string contents(const fs::path& path)
{
    const auto bytes = test::readBytes(path);
    return {bytes.begin(), bytes.end()};
}

FragmentId addFragment(Scene& scene, const std::string& name, const fs::path& octree)
{
    Fragment f;
    f.name = name;
    f.octreePath = octree;
    return scene.add(std::move(f));
}

struct Folders {
    test::TempDir root;
    fs::path cache = root / "cache";
    fs::path elsewhere = root / "elsewhere";
    fs::path project = root / "site" / "column.stylos";
    Folders()
    {
        fs::create_directories(cache);
        fs::create_directories(elsewhere);
        fs::create_directories(project.parent_path());
    }
};

TEST(ProjectOctreesTest, SavingBringsEveryOctreeIntoTheFolderAndTheCopiedProjectOpens)
{
    Folders d;
    test::writeText(d.cache / "drum.poct", "cache drum");                    // an unsaved import
    test::writeText(d.elsewhere / "fragment.poct", "built with the CLI");     // stylos-cli build elsewhere
    test::writeText(d.project.parent_path() / "inside.poct", "already here"); // in the folder already
    test::writeText(d.project.parent_path() / "fragment.poct", "another file of that name");
    Scene scene;
    const FragmentId drum = addFragment(scene, "Drum 1", d.cache / "drum.poct");
    const FragmentId a = addFragment(scene, "Fragment A", d.elsewhere / "fragment.poct");
    const FragmentId b = addFragment(scene, "Fragment A again", d.elsewhere / "fragment.poct");
    const FragmentId inside = addFragment(scene, "Inside", d.project.parent_path() / "inside.poct");

    const GatherPlan plan = planGather(scene, d.project, d.cache);
    ASSERT_EQ(plan.transfers.size(), 2u);
    EXPECT_EQ(plan.cacheBytes, 10u);
    EXPECT_EQ(plan.copyBytes, 18u);
    EXPECT_TRUE(plan.transfers[0].fromCache);
    EXPECT_FALSE(plan.transfers[1].fromCache);
    EXPECT_EQ(plan.transfers[1].fragments, (std::vector<FragmentId>{a, b}));
    EXPECT_EQ(plan.transfers[1].to.filename(), "fragment-2.poct"); // fragment.poct is another file

    auto report = gather(scene, plan);
    ASSERT_TRUE(report.ok()) << report.error().message;
    EXPECT_EQ(report->fromCache, 1);
    EXPECT_EQ(report->copied, 1);
    EXPECT_EQ(report->bytes, 28u);
    const fs::path folder = fs::weakly_canonical(d.project.parent_path());
    EXPECT_EQ(scene.find(drum)->octreePath, folder / "drum.poct");
    EXPECT_EQ(scene.find(a)->octreePath, folder / "fragment-2.poct");
    EXPECT_EQ(scene.find(b)->octreePath, folder / "fragment-2.poct");
    EXPECT_EQ(scene.find(inside)->octreePath, d.project.parent_path() / "inside.poct");
    EXPECT_EQ(contents(d.cache / "drum.poct"), "cache drum"); // left for the cache cleaner (the undo history)
    EXPECT_EQ(contents(d.elsewhere / "fragment.poct"), "built with the CLI"); // copied: the original stays
    EXPECT_EQ(contents(folder / "fragment-2.poct"), "built with the CLI");
    EXPECT_EQ(contents(folder / "fragment.poct"), "another file of that name");
    EXPECT_FALSE(fs::exists(folder / "fragment-2.poct.part"));

    // The saved folder copied elsewhere and the originals gone: the project still opens whole.
    ASSERT_TRUE(ProjectFile::save(scene, d.project));
    const fs::path travelled = d.root / "usb" / "site";
    fs::create_directories(travelled.parent_path());
    fs::copy(d.project.parent_path(), travelled, fs::copy_options::recursive);
    fs::remove_all(d.project.parent_path());
    fs::remove_all(d.elsewhere);
    auto loaded = ProjectFile::load(travelled / "column.stylos");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->problems.empty());
    EXPECT_EQ(loaded->scene.find(a)->octreePath, travelled / "fragment-2.poct");
    EXPECT_EQ(contents(loaded->scene.find(drum)->octreePath), "cache drum");

    // Gathering again has nothing to do.
    EXPECT_TRUE(planGather(loaded->scene, travelled / "column.stylos", d.cache).transfers.empty());
}

TEST(ProjectOctreesTest, OctreesElsewhereCanBeLeftWhereTheyAreButNotTheCaches)
{
    Folders d;
    test::writeText(d.cache / "scan.poct", "cache");
    test::writeText(d.elsewhere / "big.poct", "big octree");
    Scene scene;
    const FragmentId scan = addFragment(scene, "Scan", d.cache / "scan.poct");
    const FragmentId big = addFragment(scene, "Big", d.elsewhere / "big.poct");
    auto report = gather(scene, planGather(scene, d.project, d.cache), /*copies=*/false);
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->fromCache, 1);
    EXPECT_EQ(report->copied, 0);
    EXPECT_EQ(scene.find(scan)->octreePath.filename(), "scan.poct");
    EXPECT_NE(scene.find(scan)->octreePath.parent_path(), fs::weakly_canonical(d.cache));
    EXPECT_EQ(scene.find(big)->octreePath, d.elsewhere / "big.poct");
}

TEST(ProjectOctreesTest, ACopyNeverTakesTheNameOfAnImportStillBuilding)
{
    // An import is building site/scan.poct (not on disk yet) while the project is saved: the octree scan.poct from
    // elsewhere is copied as scan-2.poct, not onto the name the import will rename its result to.
    Folders d;
    test::writeText(d.elsewhere / "scan.poct", "the drum");
    Scene scene;
    const FragmentId drum = addFragment(scene, "Drum", d.elsewhere / "scan.poct");
    const fs::path building = d.project.parent_path() / "scan.poct";
    const GatherPlan plan = planGather(scene, d.project, d.cache, {building});
    ASSERT_EQ(plan.transfers.size(), 1u);
    EXPECT_EQ(plan.transfers[0].to.filename(), "scan-2.poct");
    EXPECT_EQ(planGather(scene, d.project, d.cache).transfers[0].to.filename(), "scan.poct"); // without it
    ASSERT_TRUE(gather(scene, plan, true).ok());
    EXPECT_EQ(contents(scene.find(drum)->octreePath), "the drum");
    EXPECT_FALSE(fs::exists(building));
}

TEST(ProjectOctreesTest, AFailedCopyNamesBothFilesLeavesNoPartAndTheSceneTrue)
{
    Folders d;
    test::writeText(d.cache / "moved.poct", "cache");
    test::writeText(d.elsewhere / "f.poct", "x");
    Scene scene;
    const FragmentId moved = addFragment(scene, "Moved", d.cache / "moved.poct");
    const FragmentId f = addFragment(scene, "F", d.elsewhere / "f.poct");
    GatherPlan plan = planGather(scene, d.project, d.cache);
    ASSERT_EQ(plan.transfers.size(), 2u);
    plan.transfers[1].to = d.root / "no such folder" / "f.poct"; // as if the folder vanished meanwhile
    auto report = gather(scene, plan);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(report.error().message.find("f.poct: could not copy the octree " + fs::weakly_canonical(d.elsewhere / "f.poct").string()),
              std::string::npos)
        << report.error().message;
    EXPECT_EQ(scene.find(moved)->octreePath, plan.transfers[0].to); // the transfer done before stays done
    EXPECT_TRUE(fs::exists(plan.transfers[0].to));
    EXPECT_EQ(scene.find(f)->octreePath, d.elsewhere / "f.poct");
    EXPECT_FALSE(fs::exists(d.root / "no such folder"));
}

// A folder without room for the copies is refused before the first one (a disk that filled halfway left some octrees
// copied, the project unsaved, and the message "Input/output error"). The plan's sizes stand for the files'.
TEST(ProjectOctreesTest, NotEnoughSpaceIsSaidBeforeAnyCopy)
{
    Folders d;
    test::writeText(d.cache / "a.poct", "aaaa");
    test::writeText(d.cache / "b.poct", "bbbb");
    Scene scene;
    const FragmentId a = addFragment(scene, "A", d.cache / "a.poct");
    addFragment(scene, "B", d.cache / "b.poct");
    GatherPlan plan = planGather(scene, d.project, d.cache);
    ASSERT_EQ(plan.transfers.size(), 2u);
    plan.transfers[1].bytes = std::uintmax_t(1) << 62; // more than any disk
    auto report = gather(scene, plan);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(report.error().message.find(plan.transfers[0].to.parent_path().string() +
                                          ": not enough space to bring the octrees into the project's folder: "),
              std::string::npos) << report.error().message;
    EXPECT_NE(report.error().message.find(" MB free"), std::string::npos) << report.error().message;
    EXPECT_FALSE(fs::exists(plan.transfers[0].to)); // nothing copied
    EXPECT_EQ(scene.find(a)->octreePath, d.cache / "a.poct");
}

// A cache's octree made unique in the cache ("drum-2.poct": an earlier session's drum.poct is there) comes into the
// project's folder under its scan's name, "drum.poct"; a second scan of that name gets "drum-2.poct" there.
TEST(ProjectOctreesTest, ACacheOctreeTakesItsScansName)
{
    Folders d;
    test::writeText(d.cache / "drum.poct", "last session's");
    test::writeText(d.cache / "drum-2.poct", "this one");
    test::writeText(d.cache / "drum-3.poct", "the other drum");
    Scene scene;
    Fragment a;
    a.name = "Drum 1";
    a.octreePath = d.cache / "drum-2.poct";
    a.sourcePath = d.root / "scans" / "north" / "drum.ply";
    const FragmentId first = scene.add(a);
    Fragment b = a;
    b.octreePath = d.cache / "drum-3.poct";
    b.sourcePath = d.root / "scans" / "south" / "drum.ply";
    const FragmentId second = scene.add(b);
    const GatherPlan plan = planGather(scene, d.project, d.cache);
    ASSERT_EQ(plan.transfers.size(), 2u);
    EXPECT_EQ(plan.transfers[0].to, fs::weakly_canonical(d.project.parent_path()) / "drum.poct");
    EXPECT_EQ(plan.transfers[1].to, fs::weakly_canonical(d.project.parent_path()) / "drum-2.poct");
    ASSERT_TRUE(gather(scene, plan).ok());
    EXPECT_EQ(contents(scene.find(first)->octreePath), "this one");
    EXPECT_EQ(contents(scene.find(second)->octreePath), "the other drum");
}

TEST(ProjectOctreesTest, AVanishedSourceIsNotFound)
{
    Folders d;
    test::writeText(d.cache / "gone.poct", "x");
    Scene scene;
    addFragment(scene, "Gone", d.cache / "gone.poct");
    const GatherPlan plan = planGather(scene, d.project, d.cache);
    fs::remove(d.cache / "gone.poct");
    auto report = gather(scene, plan);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::NotFound);
}

TEST(ProjectOctreesTest, TheCacheKeepsWhatTheSceneOrARecentProjectUsesAndWhatIsRecent)
{
    Folders d;
    for (const char* name : {"open.poct", "recent.poct", "discarded.poct", "fresh.poct", "import.poct.part"})
        test::writeText(d.cache / name, "12345");
    test::writeText(d.cache / "notes.txt", "not an octree");
    Scene recent;
    addFragment(recent, "Legacy", d.cache / "recent.poct");
    ASSERT_TRUE(ProjectFile::save(recent, d.root / "legacy.stylos"));

    const auto now = fs::file_time_type::clock::now();
    for (const char* name : {"open.poct", "recent.poct", "discarded.poct", "import.poct.part", "notes.txt"})
        fs::last_write_time(d.cache / name, now - 3h);
    const CacheCleanReport report =
        cleanCache(d.cache, {d.cache / "open.poct"}, {d.root / "legacy.stylos", d.root / "deleted.stylos"}, 1h, now);
    EXPECT_EQ(report.removed, (std::vector<fs::path>{d.cache / "discarded.poct", d.cache / "import.poct.part"}));
    EXPECT_EQ(report.bytesFreed, 10u);
    EXPECT_EQ(report.bytesKept, 15u); // open, recent and fresh (younger than the grace)
    EXPECT_TRUE(fs::exists(d.cache / "fresh.poct"));
    EXPECT_TRUE(fs::exists(d.cache / "notes.txt"));

    EXPECT_TRUE(cleanCache(d.root / "no such cache", {}, {}, 0s).removed.empty());
}

} // namespace
} // namespace stylos::core::scene
