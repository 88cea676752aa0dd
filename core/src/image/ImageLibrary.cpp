#include "stylos/core/image/ImageLibrary.h"

#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>

namespace stylos::core::image {

namespace {

namespace fs = std::filesystem;

constexpr const char* ModuleName = "libstylos_oiio.so";
constexpr const char* EntryPoint = "stylos_image_library";

/** This program's directory (/proc/self/exe), or empty. */
fs::path programDirectory()
{
    std::array<char, 4096> buffer{};
    const ssize_t length = ::readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
    if (length <= 0) return {};
    return fs::path(std::string(buffer.data(), std::size_t(length))).parent_path();
}

/** Where the module may be, in the order tried. */
std::vector<fs::path> candidates()
{
    std::vector<fs::path> paths;
    if (const char* chosen = std::getenv("STYLOS_IMAGE_MODULE"); chosen && *chosen) return {fs::path(chosen)};
    const fs::path program = programDirectory();
    if (!program.empty()) paths.push_back(program / ".." / "lib" / "stylos" / ModuleName);
#if defined(STYLOS_IMAGE_MODULE_BUILD_PATH) && defined(STYLOS_BUILD_TREE)
    // The build tree's module, for its programs elsewhere in it (the tests): only for a program inside that tree,
    // so that an installed copy never loads a file from the folder it was once built in.
    std::error_code error;
    const std::string tree = fs::weakly_canonical(fs::path(STYLOS_BUILD_TREE), error).string() + "/";
    if (!error && (program.string() + "/").rfind(tree, 0) == 0) paths.emplace_back(STYLOS_IMAGE_MODULE_BUILD_PATH);
#endif
    return paths;
}

struct Loaded {
    const ImageLibrary* library = nullptr;
    std::string problem;
};

Loaded load()
{
    using Entry = const ImageLibrary* (*)(int);
    Loaded loaded;
    for (const fs::path& path : candidates()) {
        std::error_code error;
        if (!fs::exists(path, error)) {
            loaded.problem += "\n  " + path.lexically_normal().string() + ": not there";
            continue;
        }
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = ::dlerror();
            loaded.problem += "\n  " + path.lexically_normal().string() + ": " + (why ? why : "cannot be loaded");
            continue;
        }
        const auto entry = reinterpret_cast<Entry>(::dlsym(handle, EntryPoint));
        const ImageLibrary* library = entry ? entry(ImageLibraryVersion) : nullptr;
        if (!library) { // another version (or not the module): left loaded, as a module whose code ran may not unload
            loaded.problem += "\n  " + path.lexically_normal().string() + ": not version " +
                              std::to_string(ImageLibraryVersion) + " of the module";
            continue;
        }
        loaded.library = library; // never unloaded: its writers and readers may outlive any owner
        return loaded;
    }
    return loaded;
}

} // namespace

Result<const ImageLibrary*> imageLibrary()
{
    static const Loaded loaded = load(); // once, thread-safe
    if (loaded.library) return loaded.library;
    return Error::at(ErrorCode::Unsupported, ModuleName, {},
                     "the image library module (OpenImageIO) cannot be loaded; tried:" + loaded.problem);
}

Result<std::unique_ptr<ImageFileWriter>> openImageWriter(const std::string& path, const ImageHeader& header,
                                                         const std::string& shownName)
{
    const auto fail = [&](const std::string& why) { return Error::at(ErrorCode::WriteFailed, shownName, {}, why); };
    auto library = imageLibrary();
    if (!library) return fail("cannot write images: " + library.error().message);
    std::string problem;
    auto out = (*library)->createWriter(path, &problem);
    if (!out) return fail("the image library cannot write this format: " + problem);
    if (!out->open(path, header)) return fail("cannot create " + path + ": " + out->takeError());
    return out;
}

Status writeWholeImage(const std::string& path, const ImageHeader& header, const void* samples,
                       const std::string& shownName)
{
    auto opened = openImageWriter(path, header, shownName);
    if (!opened) return opened.error();
    const auto& out = opened.value();
    const bool written = out->writeImage(header.sample, samples);
    const bool closed = out->close(); // even after a failed write: the library lets go of the file
    if (!written || !closed) return Error::at(ErrorCode::WriteFailed, shownName, {}, "cannot write: " + out->takeError());
    return {};
}

} // namespace stylos::core::image
