#include "stylos/core/scene/ProjectOctrees.h"

#include <cstdio>

#include <map>

#include "stylos/core/scene/ProjectFile.h"

#include <algorithm>
#include <set>
#include <system_error>

namespace fs = std::filesystem;

namespace stylos::core::scene {

namespace {

fs::path normalised(const fs::path& p)
{
    std::error_code ec;
    fs::path n = fs::weakly_canonical(p, ec);
    return ec ? p.lexically_normal() : n;
}

/** Whether @p file lies in @p folder or below it (both normalised). */
bool isInside(const fs::path& file, const fs::path& folder)
{
    const fs::path relative = file.lexically_relative(folder);
    if (relative.empty()) return false;
    const auto first = *relative.begin();
    return first != ".." && first != ".";
}

/** A name for @p source in @p folder that no other file (on disk or already planned) has. */
fs::path destinationFor(const fs::path& source, const fs::path& folder, std::set<fs::path>& taken)
{
    const std::string stem = source.stem().string();
    const std::string extension = source.extension().string();
    for (int n = 1;; ++n) {
        const fs::path candidate = folder / (n == 1 ? stem + extension : stem + "-" + std::to_string(n) + extension);
        std::error_code ec;
        if (!taken.count(candidate) && !fs::exists(candidate, ec)) {
            taken.insert(candidate);
            return candidate;
        }
    }
}

Status copyWhole(const fs::path& from, const fs::path& to)
{
    const fs::path part = to.string() + ".part";
    std::error_code ec;
    fs::copy_file(from, part, fs::copy_options::overwrite_existing, ec);
    if (!ec) fs::rename(part, to, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(part, ignored);
        return Error::at(ErrorCode::WriteFailed, to.string(), "",
                         "could not copy the octree " + from.string() + " here: " + ec.message());
    }
    return {};
}

} // namespace

GatherPlan planGather(const Scene& scene, const fs::path& projectPath, const fs::path& cacheFolder,
                      const std::set<fs::path>& reserved)
{
    GatherPlan plan;
    const fs::path folder = normalised(fs::absolute(projectPath).parent_path());
    const fs::path cache = cacheFolder.empty() ? fs::path{} : normalised(cacheFolder);
    std::set<fs::path> taken;
    for (const fs::path& path : reserved) taken.insert(normalised(path));
    for (const Fragment& f : scene.fragments()) {
        if (f.octreeMissing || f.octreePath.empty()) continue;
        const fs::path from = normalised(f.octreePath);
        if (isInside(from, folder)) continue;
        auto same = std::find_if(plan.transfers.begin(), plan.transfers.end(),
                                 [&](const OctreeTransfer& t) { return t.from == from; });
        if (same != plan.transfers.end()) {
            same->fragments.push_back(f.id);
            continue;
        }
        std::error_code ec;
        const std::uintmax_t bytes = fs::file_size(from, ec);
        if (ec) continue; // vanished since it was opened: the save keeps its path, the next open reports it
        OctreeTransfer t;
        t.from = from;
        t.bytes = bytes;
        t.fromCache = !cache.empty() && isInside(from, cache);
        // A cache's octree is named after the scan it was built from: the cache's own name may carry a "-2" made
        // unique among the cache's files (an earlier session's drum.poct), meaningless in the project's folder.
        const fs::path named = t.fromCache && !f.sourcePath.empty()
                                   ? from.parent_path() / (f.sourcePath.stem().string() + from.extension().string())
                                   : from;
        t.to = destinationFor(named, folder, taken);
        t.fragments.push_back(f.id);
        (t.fromCache ? plan.cacheBytes : plan.copyBytes) += bytes;
        plan.transfers.push_back(std::move(t));
    }
    return plan;
}

Result<GatherReport> gather(Scene& scene, const GatherPlan& plan, bool copies)
{
    GatherReport report;
    // Room for every copy before the first: a disk that fills halfway would leave some octrees copied and the project
    // unsaved (and the system's word for it, mid-copy, is often "Input/output error").
    std::map<fs::path, std::uintmax_t> needed; // per folder
    for (const OctreeTransfer& t : plan.transfers)
        if (t.fromCache || copies) needed[t.to.parent_path()] += t.bytes;
    for (const auto& [folder, bytes] : needed) {
        std::error_code ec;
        const fs::space_info space = fs::space(folder, ec);
        if (!ec && space.available < bytes) {
            char text[240];
            std::snprintf(text, sizeof text,
                          "not enough space to bring the octrees into the project's folder: %.1f MB needed, %.1f MB free",
                          double(bytes) / 1e6, double(space.available) / 1e6);
            return Error::at(ErrorCode::WriteFailed, folder.string(), "", text);
        }
    }
    for (const OctreeTransfer& t : plan.transfers) {
        if (!t.fromCache && !copies) continue;
        std::error_code ec;
        if (!fs::exists(t.from, ec))
            return Error::at(ErrorCode::NotFound, t.from.string(), "", "the octree is gone; it cannot be brought into "
                                                                      "the project's folder");
        // Copied, never moved: the undo history may still name the cache's file; cleanCache() removes it
        // once nothing uses it.
        if (const Status copied = copyWhole(t.from, t.to); !copied) return copied.error();
        for (FragmentId id : t.fragments)
            if (Fragment* f = scene.find(id)) f->octreePath = t.to;
        (t.fromCache ? report.fromCache : report.copied) += 1;
        report.bytes += t.bytes;
    }
    return report;
}

CacheCleanReport cleanCache(const fs::path& cacheFolder, const std::vector<fs::path>& inUse,
                            const std::vector<fs::path>& projects, std::chrono::seconds grace,
                            fs::file_time_type now)
{
    CacheCleanReport report;
    std::error_code ec;
    if (!fs::is_directory(cacheFolder, ec)) return report;

    std::set<fs::path> used;
    for (const fs::path& p : inUse) used.insert(normalised(p));
    for (const fs::path& project : projects) {
        auto loaded = ProjectFile::load(project);
        if (!loaded) continue;
        for (const Fragment& f : loaded->scene.fragments()) used.insert(normalised(f.octreePath));
    }

    for (const fs::directory_entry& entry : fs::directory_iterator(cacheFolder, ec)) {
        if (!entry.is_regular_file(ec)) continue;
        const fs::path path = entry.path();
        const std::string name = path.filename().string();
        const bool octree = path.extension() == ".poct";
        const bool partial = name.size() > 5 && name.ends_with(".part");
        if (!octree && !partial) continue;
        std::error_code sizeError, timeError;
        const std::uintmax_t bytes = entry.file_size(sizeError);
        const auto written = entry.last_write_time(timeError);
        const bool old = !timeError && now - written > grace;
        if ((partial || !used.count(normalised(path))) && old && fs::remove(path, ec)) {
            report.removed.push_back(path);
            report.bytesFreed += bytes;
        } else if (octree) {
            report.bytesKept += bytes;
        }
    }
    std::sort(report.removed.begin(), report.removed.end());
    return report;
}

} // namespace stylos::core::scene
