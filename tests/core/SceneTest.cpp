// Scene and Fragment: stable ids never reused, order, insert/take round trips; colours and guide kinds.
#include "stylos/core/scene/Scene.h"
#include "stylos/core/scene/SceneEigen.h"

#include <gtest/gtest.h>

namespace stylos::core::scene {
namespace {

Fragment named(const std::string& name, FragmentId id = NoFragment)
{
    Fragment f;
    f.id = id;
    f.name = name;
    f.octreePath = "/data/" + name + ".poct";
    return f;
}

std::vector<std::string> names(const Scene& scene)
{
    std::vector<std::string> out;
    for (const Fragment& f : scene.fragments()) out.push_back(f.name);
    return out;
}

TEST(SceneTest, FragmentDefaultsAreAVisibleIdentityPlacement)
{
    const Fragment f;
    EXPECT_EQ(f.id, NoFragment);
    EXPECT_TRUE(f.visible);
    EXPECT_EQ(f.pose, Pose());
    EXPECT_EQ(f.pose(0, 0), 1.0);
    EXPECT_EQ(f.pose(0, 3), 0.0);
    EXPECT_TRUE(f.guides.empty());
    EXPECT_EQ(f.annotationLayer, "");
    EXPECT_FALSE(f.octreeMissing);
}

TEST(SceneTest, AddAssignsIncreasingIdsInOrder)
{
    Scene scene;
    EXPECT_TRUE(scene.empty());
    EXPECT_EQ(scene.nextId(), 1u);
    EXPECT_EQ(scene.add(named("a")), 1u);
    EXPECT_EQ(scene.add(named("b")), 2u);
    EXPECT_EQ(scene.add(named("c")), 3u);
    EXPECT_EQ(scene.size(), 3u);
    EXPECT_EQ(scene.nextId(), 4u);
    EXPECT_EQ(names(scene), (std::vector<std::string>{"a", "b", "c"}));
    ASSERT_NE(scene.find(2), nullptr);
    EXPECT_EQ(scene.find(2)->name, "b");
    EXPECT_EQ(scene.indexOf(3), 2u);
    EXPECT_EQ(scene.find(NoFragment), nullptr);
    EXPECT_EQ(scene.find(99), nullptr);
    EXPECT_FALSE(scene.indexOf(99).has_value());
}

TEST(SceneTest, RemovedIdsAreNeverReused)
{
    Scene scene;
    scene.add(named("a"));
    scene.add(named("b"));
    ASSERT_TRUE(scene.remove(2));
    EXPECT_FALSE(scene.remove(2));
    EXPECT_EQ(scene.add(named("c")), 3u);
    scene.clear();
    EXPECT_TRUE(scene.empty());
    EXPECT_EQ(scene.add(named("d")), 4u);
}

TEST(SceneTest, TakeThenInsertRestoresTheSceneExactly)
{
    Scene scene;
    scene.add(named("a"));
    Fragment b = named("b");
    b.pose = Pose::translation({1.5, -2.0, 1e6});
    b.colour = {1, 2, 3};
    b.visible = false;
    b.guides.push_back({"axis", GuideKind::Axis, {0.1, 0.2, 0.3}, {0.0, 1.0, 0.0}});
    b.annotationLayer = "class";
    scene.add(b);
    scene.add(named("c"));
    const Scene before = scene;

    const auto taken = scene.take(2);
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->name, "b");
    EXPECT_EQ(taken->guides.size(), 1u);
    EXPECT_EQ(names(scene), (std::vector<std::string>{"a", "c"}));
    EXPECT_FALSE(scene.take(2).has_value());

    EXPECT_EQ(scene.insert(1, *taken), 2u);
    EXPECT_EQ(scene, before);
}

TEST(SceneTest, InsertKeepsAGivenIdAndRefusesDuplicates)
{
    Scene scene;
    EXPECT_EQ(scene.insert(0, named("x", 7)), 7u);
    EXPECT_EQ(scene.nextId(), 8u);
    EXPECT_EQ(scene.insert(0, named("y", 7)), NoFragment);
    EXPECT_EQ(scene.size(), 1u);
    EXPECT_EQ(scene.insert(0, named("z", 3)), 3u);   // below nextId: kept, nextId unchanged
    EXPECT_EQ(scene.nextId(), 8u);
    EXPECT_EQ(scene.insert(100, named("w")), 8u);     // index clamped: appended
    EXPECT_EQ(names(scene), (std::vector<std::string>{"z", "x", "w"}));
}

TEST(SceneTest, AllocatedIdsAreSkippedByLaterAdds)
{
    Scene scene;
    const FragmentId reserved = scene.allocateId();
    EXPECT_EQ(reserved, 1u);
    EXPECT_EQ(scene.add(named("a")), 2u);
    EXPECT_EQ(scene.insert(0, named("r", reserved)), reserved);
    EXPECT_EQ(scene.indexOf(reserved), 0u);
}

TEST(SceneTest, SetNextIdMustStayAboveEveryId)
{
    Scene scene;
    scene.add(named("a"));
    scene.add(named("b"));
    EXPECT_FALSE(scene.setNextId(2));
    EXPECT_FALSE(scene.setNextId(NoFragment));
    EXPECT_EQ(scene.nextId(), 3u);
    EXPECT_TRUE(scene.setNextId(10));
    EXPECT_EQ(scene.add(named("c")), 10u);
}

TEST(SceneTest, ColoursConvertToAndFromHex)
{
    EXPECT_EQ((Rgb{0, 15, 255}).toHex(), "#000fff");
    EXPECT_EQ(Rgb::fromHex("#A0b1C2"), (Rgb{0xa0, 0xb1, 0xc2}));
    EXPECT_EQ(Rgb::fromHex("#000fff"), (Rgb{0, 15, 255}));
    for (const char* bad : {"", "#", "a0b1c2", "#a0b1c", "#a0b1c2d", "#g0b1c2", " #a0b1c2"})
        EXPECT_FALSE(Rgb::fromHex(bad).has_value()) << bad;
    EXPECT_NE(defaultFragmentColour(0), defaultFragmentColour(1));
    EXPECT_EQ(defaultFragmentColour(0), defaultFragmentColour(8));
}

TEST(SceneTest, GuideKindsHaveStableNames)
{
    EXPECT_STREQ(guideKindName(GuideKind::Axis), "axis");
    EXPECT_STREQ(guideKindName(GuideKind::Groove), "groove");
    EXPECT_EQ(guideKindFromName("groove"), GuideKind::Groove);
    EXPECT_EQ(guideKindFromName("axis"), GuideKind::Axis);
    EXPECT_FALSE(guideKindFromName("Axis").has_value());
}

Pose turned(double x, double angle)
{
    return Pose::fromTranslationAngles({{x, 0.0, 0.0}, {0.0, 0.0, angle}});
}

TEST(SceneTest, AssembliesHoldFragmentsWhosePosesAreRelativeToThem)
{
    Scene scene;
    const FragmentId a = scene.add(named("a")), b = scene.add(named("b"));
    scene.find(a)->pose = turned(1.0, 0.0);
    scene.find(b)->pose = turned(2.0, 0.0);
    Assembly assembly;
    assembly.name = "Drum 1 reconstruction";
    assembly.pose = turned(10.0, 0.5);
    const AssemblyId id = scene.addAssembly(assembly);
    EXPECT_EQ(id, 1u);
    EXPECT_EQ(scene.nextAssemblyId(), 2u);

    // Moving a fragment in keeps it where it is in the scene; its own pose becomes relative.
    const Pose before = scene.worldPose(a);
    ASSERT_TRUE(scene.moveToAssembly(a, id));
    EXPECT_EQ(scene.find(a)->assembly, id);
    EXPECT_TRUE(scene.worldPose(a).approxEqual(before, 1e-12));
    EXPECT_FALSE(scene.find(a)->pose.approxEqual(before, 1e-3));
    EXPECT_EQ(scene.membersOf(id), std::vector<FragmentId>{a});
    EXPECT_EQ(scene.membersOf(NoAssembly), std::vector<FragmentId>{b});

    // Moving the assembly moves its member, not the others.
    scene.findAssembly(id)->pose = turned(11.0, 0.5);
    EXPECT_NEAR(scene.worldPose(a).translationPart()[0] - before.translationPart()[0], 1.0, 1e-12);
    EXPECT_EQ(scene.worldPose(b), turned(2.0, 0.0));

    // Unknown ids are refused; removing the assembly puts its member back at the top, in place.
    EXPECT_FALSE(scene.moveToAssembly(a, 99));
    EXPECT_FALSE(scene.moveToAssembly(77, id));
    const Pose world = scene.worldPose(a);
    const auto taken = scene.takeAssembly(id);
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->name, "Drum 1 reconstruction");
    EXPECT_EQ(scene.find(a)->assembly, NoAssembly);
    EXPECT_TRUE(scene.find(a)->pose.approxEqual(world, 1e-12));
    EXPECT_EQ(scene.addAssembly(Assembly{}), 2u); // ids never reused
    EXPECT_FALSE(scene.setNextAssemblyId(2));
    EXPECT_TRUE(scene.setNextAssemblyId(5));
}

TEST(SceneTest, TheDockingDrumIsAFragmentOfTheSceneAndAnAssemblysDrumComesFirst)
{
    Scene scene;
    const FragmentId drum = scene.add(named("drum")), other = scene.add(named("other")), piece = scene.add(named("piece"));
    EXPECT_EQ(scene.dockingDrum(), NoFragment);
    EXPECT_FALSE(scene.setDockingDrum(99)); // not in the scene: refused, nothing changed
    EXPECT_EQ(scene.dockingDrum(), NoFragment);
    ASSERT_TRUE(scene.setDockingDrum(drum));
    EXPECT_EQ(drumFor(scene, piece), drum);
    // In an assembly with a drum, the assembly's drum; in one without, the docking drum.
    Assembly withDrum;
    withDrum.drum = other;
    const AssemblyId a = scene.addAssembly(withDrum);
    ASSERT_TRUE(scene.moveToAssembly(piece, a));
    EXPECT_EQ(drumFor(scene, piece), other);
    scene.findAssembly(a)->drum = NoFragment;
    EXPECT_EQ(drumFor(scene, piece), drum);
    EXPECT_EQ(drumFor(scene, 99), drum);
    // Taking the drum out unsets it; taking another fragment does not; clear() unsets it.
    ASSERT_TRUE(scene.remove(other));
    EXPECT_EQ(scene.dockingDrum(), drum);
    ASSERT_TRUE(scene.remove(drum));
    EXPECT_EQ(scene.dockingDrum(), NoFragment);
    EXPECT_EQ(drumFor(scene, piece), NoFragment);
    ASSERT_TRUE(scene.setDockingDrum(piece));
    scene.clear();
    EXPECT_EQ(scene.dockingDrum(), NoFragment);
}

TEST(SceneTest, AFragmentNamingAMissingAssemblyIsInsertedAtTheTop)
{
    Scene scene;
    Fragment f = named("orphan");
    f.assembly = 4;
    const FragmentId id = scene.add(f);
    EXPECT_EQ(scene.find(id)->assembly, NoAssembly);
}

} // namespace
} // namespace stylos::core::scene
