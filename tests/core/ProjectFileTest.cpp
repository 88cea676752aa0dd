// ProjectFile: exact round trips, relative paths that survive moving the project folder, a missing octree
// that still opens, and every load error naming the file and the key.
#include "TestSupport.h"

#include "stylos/core/scene/ProjectFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>

namespace fs = std::filesystem;

namespace stylos::core::scene {
namespace {

std::string contents(const fs::path& path)
{
    const auto bytes = test::readBytes(path);
    return {bytes.begin(), bytes.end()};
}

/** Two fragments with awkward doubles, guides, a hidden one; octrees under @p folder/octrees. */
Scene sampleScene(const fs::path& folder)
{
    fs::create_directories(folder / "octrees");
    test::writeText(folder / "octrees" / "drum 1.poct", "x");
    test::writeText(folder / "octrees" / "fragment.poct", "x");
    Scene scene;
    Fragment drum;
    drum.name = "Drum 1 — Δελφοί";
    drum.octreePath = folder / "octrees" / "drum 1.poct";
    drum.sourcePath = folder.parent_path() / "scans" / "drum1.ply";
    drum.pose = Pose::fromTranslationAngles({{0.1, 1e-300, 4321987.123456789}, {0.3, -1.2, 2.9}});
    drum.colour = {214, 204, 186};
    drum.guides.push_back({"axis", GuideKind::Axis, {0.1, 0.2, -0.3}, {0.0, 0.6, 0.8}});
    drum.guides.push_back({"groove 7", GuideKind::Groove, {0.55, 0, 0}, {0, 0, 1}});
    drum.annotationLayer = "class";
    drum.importFrame = {io::UpAxis::NegX, io::LengthUnit::Millimetre, {512000.25, -4.5e6, 1e-3}};
    scene.add(drum);
    Fragment piece;
    piece.name = "fragment";
    piece.octreePath = folder / "octrees" / "fragment.poct";
    piece.visible = false;
    piece.colour = {1, 2, 3};
    scene.add(piece);
    scene.remove(scene.add(Fragment{}));  // nextId 4 while the largest id is 2
    EXPECT_TRUE(scene.setDockingDrum(1)); // what fragments outside an assembly dock against
    // An assembly holding the piece, docked against the drum; a removed one leaves nextAssemblyId at 3.
    Assembly assembly;
    assembly.name = "Drum 1 reconstruction";
    assembly.pose = Pose::fromTranslationAngles({{-2.5, 0.125, 1e-17}, {0.0, 0.0, 1.0471975511965976}});
    assembly.drum = 1;
    const AssemblyId id = scene.addAssembly(assembly);
    scene.takeAssembly(scene.addAssembly(Assembly{}));
    scene.find(2)->assembly = id;
    scene.find(2)->pose = Pose::fromTranslationAngles({{0.01, 0.02, 0.03}, {0.1, 0.2, 0.3}});
    // A legend changed from the defaults: a renamed class, a new one, a removed one.
    annotation::Legend legend = annotation::Legend::defaults();
    legend.material[0].name = "marbre conservé";
    legend.material.push_back({9, "patine", {10, 20, 30}, annotation::Hatch::Dots});
    legend.toolmark.pop_back();
    scene.setLegend(legend);
    return scene;
}

TEST(ProjectFileTest, SaveThenLoadGivesAnEqualSceneAndTheSameBytes)
{
    test::TempDir dir;
    const Scene scene = sampleScene(dir / "project");
    const fs::path path = dir / "project" / "site.stylos";
    ASSERT_TRUE(ProjectFile::save(scene, path).ok());
    const auto loaded = ProjectFile::load(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->problems.empty());
    EXPECT_EQ(loaded->scene, scene);
    EXPECT_EQ(loaded->scene.nextId(), 4u);
    EXPECT_EQ(loaded->scene.dockingDrum(), 1u); // a reopened project unrolls its fragments about the same axis
    EXPECT_EQ(loaded->scene.fragments()[0].pose.rowMajor(), scene.fragments()[0].pose.rowMajor());

    const std::string first = contents(path);
    ASSERT_TRUE(ProjectFile::save(loaded->scene, path).ok());
    EXPECT_EQ(contents(path), first);
    EXPECT_FALSE(fs::exists(dir / "project" / "site.stylos.part"));
}

TEST(ProjectFileTest, TheFileHoldsFormatVersionAndRelativePaths)
{
    test::TempDir dir;
    const Scene scene = sampleScene(dir / "project");
    const fs::path path = dir / "project" / "site.stylos";
    ASSERT_TRUE(ProjectFile::save(scene, path).ok());
    const auto json = nlohmann::json::parse(contents(path));
    EXPECT_EQ(json["format"], "stylos-project");
    EXPECT_EQ(json["version"], 2);
    EXPECT_EQ(json["nextId"], 4);
    EXPECT_EQ(json["dockingDrum"], 1);
    const auto& drum = json["fragments"][0];
    EXPECT_EQ(drum["octree"], "octrees/drum 1.poct");
    EXPECT_EQ(drum["source"], "../scans/drum1.ply");
    EXPECT_EQ(drum["colour"], "#d6ccba");
    EXPECT_EQ(drum["guides"][1]["kind"], "groove");
    EXPECT_EQ(drum["annotations"], "class");
    const auto& piece = json["fragments"][1];
    // Written even when empty, for the annotation and docking work to come.
    EXPECT_EQ(piece["source"], "");
    EXPECT_EQ(piece["guides"], nlohmann::json::array());
    EXPECT_EQ(piece["annotations"], "");
    EXPECT_EQ(piece["visible"], false);
    EXPECT_EQ(piece["pose"].size(), 16u);
}

TEST(ProjectFileTest, MovingTheProjectFolderKeepsItsFragments)
{
    test::TempDir dir;
    const Scene scene = sampleScene(dir / "before");
    ASSERT_TRUE(ProjectFile::save(scene, dir / "before" / "site.stylos").ok());
    fs::rename(dir / "before", dir / "after");
    const auto loaded = ProjectFile::load(dir / "after" / "site.stylos");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->problems.empty());
    ASSERT_EQ(loaded->scene.size(), 2u);
    EXPECT_EQ(loaded->scene.fragments()[0].octreePath, dir.path() / "after" / "octrees" / "drum 1.poct");
    EXPECT_EQ(loaded->scene.fragments()[0].sourcePath, dir.path() / "scans" / "drum1.ply");
    EXPECT_EQ(loaded->scene.fragments()[1].octreePath, dir.path() / "after" / "octrees" / "fragment.poct");
    EXPECT_FALSE(loaded->scene.fragments()[0].octreeMissing);
}

TEST(ProjectFileTest, PathsOutsideTheFolderAndAbsolutePathsResolve)
{
    EXPECT_EQ(ProjectFile::storedPath("/a/b/c.poct", "/a/b"), "c.poct");
    EXPECT_EQ(ProjectFile::storedPath("/a/x/c.poct", "/a/b"), "../x/c.poct");
    EXPECT_EQ(ProjectFile::storedPath("/a/b/./d/../c.poct", "/a/b/"), "c.poct");
    EXPECT_EQ(ProjectFile::storedPath("", "/a/b"), "");
    EXPECT_EQ(ProjectFile::resolvedPath("c.poct", "/a/b"), fs::path("/a/b/c.poct"));
    EXPECT_EQ(ProjectFile::resolvedPath("../x/c.poct", "/a/b"), fs::path("/a/x/c.poct"));
    EXPECT_EQ(ProjectFile::resolvedPath("/elsewhere/c.poct", "/a/b"), fs::path("/elsewhere/c.poct"));
    EXPECT_EQ(ProjectFile::resolvedPath("", "/a/b"), fs::path());
}

TEST(ProjectFileTest, AMissingOctreeIsReportedAndTheProjectStillOpens)
{
    test::TempDir dir;
    const Scene scene = sampleScene(dir / "project");
    const fs::path path = dir / "project" / "site.stylos";
    ASSERT_TRUE(ProjectFile::save(scene, path).ok());
    fs::remove(dir / "project" / "octrees" / "fragment.poct");
    const auto loaded = ProjectFile::load(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    ASSERT_EQ(loaded->scene.size(), 2u);
    EXPECT_FALSE(loaded->scene.fragments()[0].octreeMissing);
    EXPECT_TRUE(loaded->scene.fragments()[1].octreeMissing);
    ASSERT_EQ(loaded->problems.size(), 1u);
    EXPECT_EQ(loaded->problems[0].code, ErrorCode::NotFound);
    const std::string octree = (dir.path() / "project" / "octrees" / "fragment.poct").string();
    EXPECT_EQ(loaded->problems[0].message, octree + ": the octree of fragment \"fragment\" does not exist");
    // Everything but the runtime flag is what was saved.
    Scene expected = scene;
    expected.find(2)->octreeMissing = true;
    EXPECT_EQ(loaded->scene, expected);
}

TEST(ProjectFileTest, FileLevelErrorsNameTheFile)
{
    test::TempDir dir;
    const fs::path missing = dir / "none.stylos";
    auto result = ProjectFile::load(missing);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::NotFound);
    EXPECT_EQ(result.error().message, missing.string() + ": no such file");

    result = ProjectFile::load(dir.path());
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::Unreadable);

    test::writeText(dir / "empty.stylos", "");
    result = ProjectFile::load(dir / "empty.stylos");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::Empty);
    EXPECT_EQ(result.error().message.rfind((dir / "empty.stylos").string(), 0), 0u);

    // The second comma, line 3, column 16, is the error.
    test::writeText(dir / "bad.stylos", "{\n  \"format\": \"stylos-project\",\n  \"version\": 1,,\n}\n");
    result = ProjectFile::load(dir / "bad.stylos");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::Malformed);
    EXPECT_EQ(result.error().message.rfind((dir / "bad.stylos").string() + ": line 3, column 16: not valid JSON: ", 0), 0u)
        << result.error().message;

    const auto failed = ProjectFile::save(Scene{}, dir / "no-folder" / "x.stylos");
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(failed.error().message.find("x.stylos"), std::string::npos);
}

/** A valid project document with one fragment (octree "a.poct"). */
nlohmann::json validDocument()
{
    return nlohmann::json::parse(R"({"format": "stylos-project", "version": 1, "nextId": 2,
        "fragments": [{"id": 1, "name": "a", "octree": "a.poct", "source": "",
                       "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "colour": "#102030", "visible": true,
                       "guides": [{"name": "axis", "kind": "axis", "origin": [0,0,0], "direction": [0,0,1]}],
                       "annotations": ""}]})");
}

struct BadCase {
    const char* what;
    std::function<void(nlohmann::json&)> edit;
    ErrorCode code;
    std::string position;  ///< what follows "FILE: " in the message
};

TEST(ProjectFileTest, EveryBadKeyIsNamed)
{
    using J = nlohmann::json;
    const std::vector<BadCase> cases = {
        {"not an object", [](J& j) { j = J::array(); }, ErrorCode::UnknownFormat, "not a Stylos project"},
        {"no format", [](J& j) { j.erase("format"); }, ErrorCode::UnknownFormat, "format: "},
        {"other format", [](J& j) { j["format"] = "stylos-octree"; }, ErrorCode::UnknownFormat, "format: "},
        {"no version", [](J& j) { j.erase("version"); }, ErrorCode::Malformed, "version: is missing"},
        {"text version", [](J& j) { j["version"] = "1"; }, ErrorCode::Malformed, "version: is not an integer"},
        {"newer version", [](J& j) { j["version"] = 3; }, ErrorCode::Unsupported, "version: version 3 is not supported"},
        {"older version", [](J& j) { j["version"] = 0; }, ErrorCode::Unsupported, "version: version 0"},
        {"unknown assembly", [](J& j) { j["version"] = 2; j["fragments"][0]["assembly"] = 5; }, ErrorCode::Malformed,
         "fragments[0].assembly: no assembly has id 5"},
        {"assembly drum", [](J& j) { j["version"] = 2; j["assemblies"] = J::parse(R"([{"id": 1, "name": "r", "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "drum": 9}])"); },
         ErrorCode::Malformed, "assemblies[0].drum: no fragment has id 9"},
        {"docking drum", [](J& j) { j["dockingDrum"] = 7; }, ErrorCode::Malformed, "dockingDrum: no fragment has id 7"},
        {"docking drum type", [](J& j) { j["dockingDrum"] = "1"; }, ErrorCode::Malformed, "dockingDrum: is not a fragment id"},
        {"assembly pose", [](J& j) { j["version"] = 2; j["assemblies"] = J::parse(R"([{"id": 1, "name": "r", "pose": [2,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])"); },
         ErrorCode::Malformed, "assemblies[0].pose: is not a rigid transform"},
        {"duplicate assembly", [](J& j) { j["version"] = 2; j["assemblies"] = J::parse(R"([{"id": 1, "name": "r", "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}, {"id": 1, "name": "s", "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])"); },
         ErrorCode::Malformed, "assemblies[1].id: duplicate id 1"},
        {"no fragments", [](J& j) { j.erase("fragments"); }, ErrorCode::Malformed, "fragments: is missing"},
        {"fragments object", [](J& j) { j["fragments"] = J::object(); }, ErrorCode::Malformed, "fragments: is not an array"},
        {"fragment number", [](J& j) { j["fragments"][0] = 3; }, ErrorCode::Malformed, "fragments[0]: is not an object"},
        {"no id", [](J& j) { j["fragments"][0].erase("id"); }, ErrorCode::Malformed, "fragments[0].id: is missing"},
        {"zero id", [](J& j) { j["fragments"][0]["id"] = 0; }, ErrorCode::Malformed, "fragments[0].id: is not a positive"},
        {"negative id", [](J& j) { j["fragments"][0]["id"] = -4; }, ErrorCode::Malformed, "fragments[0].id: "},
        {"real id", [](J& j) { j["fragments"][0]["id"] = 1.5; }, ErrorCode::Malformed, "fragments[0].id: "},
        {"duplicate id", [](J& j) { j["fragments"].push_back(j["fragments"][0]); }, ErrorCode::Malformed,
         "fragments[1].id: duplicate id 1"},
        {"no name", [](J& j) { j["fragments"][0].erase("name"); }, ErrorCode::Malformed, "fragments[0].name: is missing"},
        {"name number", [](J& j) { j["fragments"][0]["name"] = 5; }, ErrorCode::Malformed, "fragments[0].name: is not a string"},
        {"no octree", [](J& j) { j["fragments"][0].erase("octree"); }, ErrorCode::Malformed, "fragments[0].octree: is missing"},
        {"empty octree", [](J& j) { j["fragments"][0]["octree"] = ""; }, ErrorCode::Malformed, "fragments[0].octree: "},
        {"source bool", [](J& j) { j["fragments"][0]["source"] = true; }, ErrorCode::Malformed, "fragments[0].source: "},
        {"no pose", [](J& j) { j["fragments"][0].erase("pose"); }, ErrorCode::Malformed, "fragments[0].pose: is missing"},
        {"short pose", [](J& j) { j["fragments"][0]["pose"].erase(15); }, ErrorCode::Malformed,
         "fragments[0].pose: is not an array of 16"},
        {"text in pose", [](J& j) { j["fragments"][0]["pose"][3] = "0"; }, ErrorCode::Malformed, "fragments[0].pose: "},
        {"scaled pose", [](J& j) { j["fragments"][0]["pose"][0] = 2; }, ErrorCode::Malformed,
         "fragments[0].pose: is not a rigid transform"},
        {"bad colour", [](J& j) { j["fragments"][0]["colour"] = "red"; }, ErrorCode::Malformed, "fragments[0].colour: "},
        {"colour array", [](J& j) { j["fragments"][0]["colour"] = J::array({1, 2, 3}); }, ErrorCode::Malformed,
         "fragments[0].colour: "},
        {"visible text", [](J& j) { j["fragments"][0]["visible"] = "yes"; }, ErrorCode::Malformed, "fragments[0].visible: "},
        {"guides object", [](J& j) { j["fragments"][0]["guides"] = J::object(); }, ErrorCode::Malformed,
         "fragments[0].guides: is not an array"},
        {"guide text", [](J& j) { j["fragments"][0]["guides"][0] = "axis"; }, ErrorCode::Malformed,
         "fragments[0].guides[0]: is not an object"},
        {"guide name", [](J& j) { j["fragments"][0]["guides"][0].erase("name"); }, ErrorCode::Malformed,
         "fragments[0].guides[0].name: "},
        {"guide kind", [](J& j) { j["fragments"][0]["guides"][0]["kind"] = "flute"; }, ErrorCode::Malformed,
         "fragments[0].guides[0].kind: "},
        {"guide origin", [](J& j) { j["fragments"][0]["guides"][0]["origin"] = J::array({0, 0}); }, ErrorCode::Malformed,
         "fragments[0].guides[0].origin: "},
        {"guide direction", [](J& j) { j["fragments"][0]["guides"][0]["direction"] = J::array({0, 0, 2}); },
         ErrorCode::Malformed, "fragments[0].guides[0].direction: is not a unit vector"},
        {"annotations number", [](J& j) { j["fragments"][0]["annotations"] = 1; }, ErrorCode::Malformed,
         "fragments[0].annotations: "},
        {"unknown up axis", [](J& j) { j["fragments"][0]["up"] = "+W"; }, ErrorCode::Malformed,
         "fragments[0].up: is \"+W\", not one of the up axes +X, -X, +Y, -Y, +Z or -Z"},
        {"up axis number", [](J& j) { j["fragments"][0]["up"] = 2; }, ErrorCode::Malformed,
         "fragments[0].up: is 2, not one of"},
        {"unknown unit", [](J& j) { j["fragments"][0]["unit"] = "inch"; }, ErrorCode::Malformed,
         "fragments[0].unit: is \"inch\", not one of the units mm, cm or m"},
        {"short offset", [](J& j) { j["fragments"][0]["offset"] = J::array({1, 2}); }, ErrorCode::Malformed,
         "fragments[0].offset: is not an array of 3 finite numbers"},
        {"legend text", [](J& j) { j["legend"] = "defaults"; }, ErrorCode::Malformed, "legend: a legend must be"},
        {"legend class id", [](J& j) { j["legend"] = J::parse(annotation::Legend::defaults().toJson().dump()); j["legend"]["layers"]["material"][1]["id"] = 1; },
         ErrorCode::Malformed, "legend: layers.material[1].id: "},
        {"low nextId", [](J& j) { j["nextId"] = 1; }, ErrorCode::Malformed, "nextId: "},
        {"text nextId", [](J& j) { j["nextId"] = "2"; }, ErrorCode::Malformed, "nextId: "},
    };
    const fs::path file = "/projects/site.stylos";
    for (const BadCase& c : cases) {
        nlohmann::json document = validDocument();
        c.edit(document);
        const auto result = ProjectFile::fromJson(document.dump(), file);
        ASSERT_FALSE(result.ok()) << c.what;
        EXPECT_EQ(result.error().code, c.code) << c.what;
        EXPECT_EQ(result.error().message.rfind(file.string() + ": " + c.position, 0), 0u)
            << c.what << ": " << result.error().message;
    }
}

TEST(ProjectFileTest, AVersionOneProjectStillOpensWithEveryFragmentAtTheTop)
{
    nlohmann::json document = validDocument(); // version 1: no assemblies
    document["assemblies"] = nlohmann::json::parse(R"([{"id": 1, "name": "ignored in version 1", "pose": 0}])");
    const auto result = ProjectFile::fromJson(document.dump(), "/projects/site.stylos");
    ASSERT_TRUE(result.ok()) << result.error().message;
    EXPECT_TRUE(result->scene.assemblies().empty());
    EXPECT_EQ(result->scene.fragments().at(0).assembly, NoAssembly);
    EXPECT_EQ(result->scene.nextAssemblyId(), 1u);
}

TEST(ProjectFileTest, AnAssemblysMembersKeepTheirPlaceInTheScene)
{
    test::TempDir dir;
    const Scene scene = sampleScene(dir / "project");
    const fs::path path = dir / "project" / "site.stylos";
    ASSERT_TRUE(ProjectFile::save(scene, path).ok());
    const auto loaded = ProjectFile::load(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    ASSERT_EQ(loaded->scene.assemblies().size(), 1u);
    EXPECT_EQ(loaded->scene.assemblies()[0].drum, 1u);
    EXPECT_EQ(loaded->scene.nextAssemblyId(), 3u);
    EXPECT_EQ(loaded->scene.membersOf(loaded->scene.assemblies()[0].id), std::vector<FragmentId>{2});
    EXPECT_EQ(loaded->scene.worldPose(2), scene.worldPose(2));
    const auto json = nlohmann::json::parse(contents(path));
    EXPECT_EQ(json["fragments"][1]["assembly"], 1);
    EXPECT_EQ(json["fragments"][0]["assembly"], 0);
}

TEST(ProjectFileTest, TheLegendTravelsWithTheProject)
{
    test::TempDir dir;
    const Scene scene = sampleScene(dir / "project");
    const fs::path path = dir / "project" / "site.stylos";
    ASSERT_TRUE(ProjectFile::save(scene, path).ok());
    const auto loaded = ProjectFile::load(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ(loaded->scene.legend(), scene.legend());
    EXPECT_EQ(loaded->scene.legend().material[0].name, "marbre conservé");
    ASSERT_NE(loaded->scene.legend().find(annotation::AnnotationLayer::Material, 9), nullptr);
    EXPECT_EQ(loaded->scene.legend().toolmark.size(), annotation::Legend::defaults().toolmark.size() - 1);
    const auto json = nlohmann::json::parse(contents(path));
    EXPECT_EQ(json["legend"]["format"], "stylos-legend");
    EXPECT_EQ(json["legend"]["layers"]["material"][4]["name"], "patine");
}

TEST(ProjectFileTest, OptionalKeysTakeTheirDefaults)
{
    nlohmann::json document = validDocument();
    for (const char* key : {"source", "colour", "visible", "guides", "annotations"}) document["fragments"][0].erase(key);
    document.erase("nextId");
    document["comment"] = "unknown keys are ignored";
    const auto result = ProjectFile::fromJson(document.dump(), "/projects/site.stylos");
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Fragment& f = result->scene.fragments().at(0);
    EXPECT_EQ(f.octreePath, fs::path("/projects/a.poct"));
    EXPECT_TRUE(f.sourcePath.empty());
    EXPECT_EQ(f.colour, Rgb{});
    EXPECT_TRUE(f.visible);
    EXPECT_TRUE(f.guides.empty());
    EXPECT_EQ(f.annotationLayer, "");
    EXPECT_EQ(result->scene.nextId(), 2u);
    EXPECT_EQ(result->scene.dockingDrum(), NoFragment); // no "dockingDrum": none
    EXPECT_EQ(result->scene.legend(), annotation::Legend::defaults()); // no "legend": the default vocabulary
    // /projects/a.poct does not exist: reported, still loaded.
    EXPECT_TRUE(f.octreeMissing);
    ASSERT_EQ(result->problems.size(), 1u);
    EXPECT_EQ(result->problems[0].message.rfind("/projects/a.poct: ", 0), 0u);
}

TEST(ProjectFileTest, TheImportFrameIsKeptPerFragmentAndDefaultsToZUpMetres)
{
    test::TempDir dir;
    const Scene scene = sampleScene(dir / "project");
    const fs::path path = dir / "project" / "site.stylos";
    ASSERT_TRUE(ProjectFile::save(scene, path).ok());
    const auto json = nlohmann::json::parse(contents(path));
    EXPECT_EQ(json["fragments"][0]["up"], "-X");
    EXPECT_EQ(json["fragments"][0]["unit"], "mm");
    EXPECT_EQ(json["fragments"][0]["offset"], nlohmann::json::array({512000.25, -4.5e6, 1e-3}));
    EXPECT_EQ(json["fragments"][1]["up"], "+Z");
    EXPECT_EQ(json["fragments"][1]["unit"], "m");
    const auto loaded = ProjectFile::load(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const io::ImportFrame expected{io::UpAxis::NegX, io::LengthUnit::Millimetre, {512000.25, -4.5e6, 1e-3}};
    EXPECT_EQ(loaded->scene.fragments()[0].importFrame, expected);
    EXPECT_EQ(loaded->scene.fragments()[1].importFrame, io::ImportFrame{});

    // A project written before the import options: every fragment Z up, in metres.
    const auto old = ProjectFile::fromJson(validDocument().dump(), "/projects/site.stylos");
    ASSERT_TRUE(old.ok()) << old.error().message;
    EXPECT_TRUE(old->scene.fragments().at(0).importFrame.isIdentity());
    // The words as the command line takes them, too.
    nlohmann::json lower = validDocument();
    lower["fragments"][0]["up"] = "y";
    lower["fragments"][0]["unit"] = "CM";
    const auto read = ProjectFile::fromJson(lower.dump(), "/projects/site.stylos");
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->scene.fragments().at(0).importFrame.up, io::UpAxis::PosY);
    EXPECT_EQ(read->scene.fragments().at(0).importFrame.unit, io::LengthUnit::Centimetre);
}

TEST(ProjectFileTest, KeysThisVersionDoesNotReadAreListed)
{
    // A hand edit or a later version's keys: the project opens, and the keys that will not be saved are named.
    Scene scene;
    Fragment f;
    f.name = "drum";
    f.octreePath = "/p/drum.poct"; // need not exist: it is reported apart (problems)
    f.guides.push_back({"axis", GuideKind::Axis, {0, 0, 0}, {0, 0, 1}});
    scene.add(f);
    auto json = nlohmann::json::parse(ProjectFile::toJson(scene, "/p/a.stylos"));
    json["mystery"] = true;
    json["fragments"][0]["frobnicate"] = 42;
    json["fragments"][0]["guides"][0]["colour"] = "red";
    const auto loaded = ProjectFile::fromJson(json.dump(), "/p/a.stylos");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ(loaded->unknownKeys,
              (std::vector<std::string>{"mystery", "fragments[0].frobnicate", "fragments[0].guides[0].colour"}));
    // What this version writes it reads: nothing unknown.
    const auto clean = ProjectFile::fromJson(ProjectFile::toJson(loaded->scene, "/p/a.stylos"), "/p/a.stylos");
    ASSERT_TRUE(clean.ok());
    EXPECT_TRUE(clean->unknownKeys.empty());
}

} // namespace
} // namespace stylos::core::scene
