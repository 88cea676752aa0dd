#pragma once
/** @file
 * @brief Projects that travel: the octrees a project uses brought into its folder when it is saved, and the
 *        octree cache (where imports go while a project was never saved) kept to what something still uses.
 *
 * planGather() lists the fragments' octrees that lie outside the project's folder: those in the cache must
 * come (the cache is cleaned), the others (a demo, an octree built elsewhere with `stylos-cli build`) may
 * stay where they are, and the caller may ask first when they are big (GatherPlan::copyBytes). All are
 * copied, never moved: the undo history may still name the cache's file, which cleanCache() removes once
 * nothing uses it. Each goes to the project's folder under its own name (a cache's octree under the name of the scan it
 * was built from, not the cache's "drum-2.poct"), made unique with "-2",
 * "-3"… when a different file already has it; fragments sharing one octree keep sharing its one copy.
 * gather() writes each copy to "NAME.poct.part" then renames it, so an interrupted save leaves either the
 * whole octree or none, and repoints the fragments at each octree as soon as it is in place: after a
 * failure the scene names only files that exist.
 *
 * cleanCache() removes the cache's `.poct` files that nothing uses — not the open scene, not any project
 * listed (the recent projects) — once they are older than a grace period (another Stylos may be importing
 * into the same cache), plus any "*.part" left by an interrupted build or copy after the same delay.
 * Thread-safety: reentrant; concurrent gathers into one folder are not supported.
 */
#include "stylos/core/scene/Scene.h"
#include "stylos/core/util/Result.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace stylos::core::scene {

/** @brief One octree file to bring into the project's folder. */
struct OctreeTransfer {
    std::filesystem::path from;       ///< where it is now (absolute)
    std::filesystem::path to;         ///< where it goes, in the project's folder (absolute)
    std::uintmax_t bytes = 0;
    bool fromCache = false;           ///< from the cache: always brought (gather()'s @p copies aside)
    std::vector<FragmentId> fragments;///< the fragments that use it
};

struct GatherPlan {
    std::vector<OctreeTransfer> transfers;
    std::uintmax_t copyBytes = 0;     ///< bytes of the transfers not from the cache (the caller may ask)
    std::uintmax_t cacheBytes = 0;    ///< bytes of the transfers from the cache
};

/**
 * @brief What bringing @p scene's octrees into the folder of @p projectPath involves. Octrees already in
 *        that folder (or below it), missing ones and fragments without an octree are left alone; an octree
 *        counts as in @p cacheFolder when it lies in it or below. A copy never takes a name of @p reserved (absolute
 *        paths that something else is about to write: the octrees of imports still building).
 */
GatherPlan planGather(const Scene& scene, const std::filesystem::path& projectPath,
                      const std::filesystem::path& cacheFolder, const std::set<std::filesystem::path>& reserved = {});

/** @brief What gather() did. */
struct GatherReport {
    int fromCache = 0;                ///< octrees copied out of the cache
    int copied = 0;                   ///< other octrees copied
    std::uintmax_t bytes = 0;
};

/**
 * @brief Carries out @p plan's transfers (all, or only those from the cache when @p copies is false: the
 *        others keep their paths) and
 *        repoints @p scene's fragments. Errors: WriteFailed naming the folder, before any copy, when its free space
 *        is less than the bytes to copy into it; WriteFailed naming the source and the destination (the
 *        transfers done before it stay done, the scene names them); NotFound when a source vanished.
 */
Result<GatherReport> gather(Scene& scene, const GatherPlan& plan, bool copies = true);

/** @brief What cleanCache() removed. */
struct CacheCleanReport {
    std::vector<std::filesystem::path> removed;
    std::uintmax_t bytesFreed = 0;
    std::uintmax_t bytesKept = 0;     ///< what stays in the cache's octrees
};

/**
 * @brief Removes from @p cacheFolder (not below it) each `.poct` that neither @p inUse nor a project among
 *        @p projects names, and each "*.part" file, when its last write is more than @p grace before
 *        @p now. A project that cannot be read protects nothing (it is named in no error: a recent project
 *        may have been deleted). A folder that does not exist is an empty cache.
 */
CacheCleanReport cleanCache(const std::filesystem::path& cacheFolder,
                            const std::vector<std::filesystem::path>& inUse,
                            const std::vector<std::filesystem::path>& projects, std::chrono::seconds grace,
                            std::filesystem::file_time_type now = std::filesystem::file_time_type::clock::now());

} // namespace stylos::core::scene
