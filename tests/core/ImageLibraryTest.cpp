// The image module (core/image/ImageLibrary.h): loaded on demand, it names OpenImageIO's formats, writes and reads
// back a file through the plain interface, reports errors as text, and refuses a caller of another version.
#include "TestSupport.h"
#include "stylos/core/image/ImageLibrary.h"

#include <gtest/gtest.h>

#include <fstream>

#include <dlfcn.h>

#include <array>
#include <cstdint>
#include <filesystem>

using namespace stylos::core::image;
using stylos::test::TempDir;

TEST(ImageLibrary, LoadsAndNamesTheFormatsStylosWrites)
{
    auto library = imageLibrary();
    ASSERT_TRUE(library) << library.error().message;
    std::string formats = ","; // appended, not "," + …: GCC 12 warns falsely (-Wrestrict) on the latter
    formats += (*library)->formatList();
    formats += ",";
    for (const char* name : {",png,", ",tiff,", ",openexr,"}) EXPECT_NE(formats.find(name), std::string::npos) << formats;
    EXPECT_EQ(imageLibrary().value(), library.value()); // loaded once
}

TEST(ImageLibrary, WritesAndReadsBackExactSamplesAndAttributes)
{
    TempDir dir;
    const std::string path = (dir / "grey.png").string();
    auto library = imageLibrary();
    ASSERT_TRUE(library);
    ImageHeader header;
    header.width = 3;
    header.height = 2;
    header.channels = 1;
    header.sample = ImageSample::UInt16;
    header.set("Software", std::string("Stylos"));
    const std::array<std::uint16_t, 6> samples{0, 1, 257, 32768, 65534, 65535};
    {
        std::string problem;
        auto out = (*library)->createWriter(path, &problem);
        ASSERT_TRUE(out) << problem;
        ASSERT_TRUE(out->open(path, header)) << out->takeError();
        ASSERT_TRUE(out->writeImage(ImageSample::UInt16, samples.data())) << out->takeError();
        ASSERT_TRUE(out->close()) << out->takeError();
    }
    std::string problem;
    auto in = (*library)->openReader(path, &problem);
    ASSERT_TRUE(in) << problem;
    EXPECT_EQ(in->header().width, 3);
    EXPECT_EQ(in->header().height, 2);
    EXPECT_EQ(in->header().channels, 1);
    EXPECT_TRUE(in->header().sampleKnown);
    EXPECT_EQ(in->header().sample, ImageSample::UInt16);
    EXPECT_EQ(in->header().sampleName, "uint16");
    std::array<std::uint16_t, 6> back{};
    ASSERT_TRUE(in->readImage(0, 1, ImageSample::UInt16, back.data())) << in->takeError();
    EXPECT_EQ(back, samples);
}

TEST(ImageLibrary, ErrorsAreTextNamingTheProblem)
{
    TempDir dir;
    auto library = imageLibrary();
    ASSERT_TRUE(library);
    std::string problem;
    EXPECT_FALSE((*library)->createWriter((dir / "picture.nosuchformat").string(), &problem));
    EXPECT_FALSE(problem.empty());
    problem.clear();
    EXPECT_FALSE((*library)->openReader((dir / "missing.png").string(), &problem));
    EXPECT_NE(problem.find("missing.png: No such file or directory"), std::string::npos) << problem;
    // A file that opens but is not an image: the library's reason alone, on one line (no stale system reason
    // from the library's own attempts elsewhere).
    {
        std::ofstream((dir / "empty.png").string());
    }
    problem.clear();
    EXPECT_FALSE((*library)->openReader((dir / "empty.png").string(), &problem));
    EXPECT_FALSE(problem.empty());
    EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
    EXPECT_EQ(problem.find(" ("), std::string::npos) << problem;

    ImageHeader header;
    header.width = 2;
    header.height = 2;
    header.channels = 1;
    const std::string inMissingFolder = (dir / "no-such-folder" / "x.png").string();
    auto out = (*library)->createWriter(inMissingFolder, &problem);
    ASSERT_TRUE(out);
    EXPECT_FALSE(out->open(inMissingFolder, header));
    EXPECT_NE(out->takeError().find("No such file or directory"), std::string::npos);
}

TEST(ImageLibrary, WriteWholeImageWritesEverySampleOrNamesTheFileShown)
{
    TempDir dir;
    ImageHeader header;
    header.width = 2;
    header.height = 2;
    header.channels = 2;
    header.sample = ImageSample::UInt8;
    const std::array<std::uint8_t, 8> samples{0, 255, 7, 255, 200, 0, 13, 255};
    const std::string path = (dir / "whole.tif").string();
    ASSERT_TRUE(writeWholeImage(path, header, samples.data(), "shown.tif"));
    auto library = imageLibrary();
    ASSERT_TRUE(library);
    std::string problem;
    auto in = (*library)->openReader(path, &problem);
    ASSERT_TRUE(in) << problem;
    EXPECT_EQ(in->header().channels, 2);
    std::array<std::uint8_t, 8> back{};
    ASSERT_TRUE(in->readImage(0, 2, ImageSample::UInt8, back.data())) << in->takeError();
    EXPECT_EQ(back, samples);

    // Failures name the file the user asked for, with the reason, and are WriteFailed.
    const auto missing = writeWholeImage((dir / "no-such-folder" / "x.png").string(), header, samples.data(), "plate.png");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, stylos::core::ErrorCode::WriteFailed);
    EXPECT_NE(missing.error().message.find("plate.png"), std::string::npos) << missing.error().message;
    EXPECT_NE(missing.error().message.find("No such file or directory"), std::string::npos) << missing.error().message;
    const auto unknown = writeWholeImage((dir / "x.nosuchformat").string(), header, samples.data(), "x.nosuchformat");
    ASSERT_FALSE(unknown);
    EXPECT_EQ(unknown.error().code, stylos::core::ErrorCode::WriteFailed);
    EXPECT_EQ(unknown.error().message.rfind("x.nosuchformat: the image library cannot write this format: ", 0), 0u)
        << unknown.error().message;
    // The missing folder: openImageWriter, the first steps of every write, names the temporary it could not create.
    const std::string temporary = (dir / "no-such-folder" / "x.part.png").string();
    const auto opened = openImageWriter(temporary, header, "plate.png");
    ASSERT_FALSE(opened);
    EXPECT_EQ(opened.error().message.rfind("plate.png: cannot create " + temporary + ": ", 0), 0u)
        << opened.error().message;
}

TEST(ImageLibrary, TheModuleRefusesACallerOfAnotherVersion)
{
    void* handle = dlopen(STYLOS_IMAGE_MODULE_FILE, RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(handle, nullptr) << dlerror();
    using Entry = const ImageLibrary* (*)(int);
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, "stylos_image_library"));
    ASSERT_NE(entry, nullptr);
    EXPECT_NE(entry(ImageLibraryVersion), nullptr);
    EXPECT_EQ(entry(ImageLibraryVersion + 1), nullptr);
    EXPECT_EQ(entry(ImageLibraryVersion - 1), nullptr);
}
