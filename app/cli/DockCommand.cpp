// stylos-cli dock FRAGMENT --drum DRUM [--guides G.json] [--pose R00,…,R22,TX,TY,TZ] [--lock z,r,theta,tilt]
//                 [--threads N] [--json] [--up AXIS] [--unit UNIT] [--offset X,Y,Z]
#include "AxisArgument.h"
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "ReadArguments.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/dock/DockRegistration.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/dock/GuidesFile.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/octree/PackedOctree.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>

namespace stylos::cli {

namespace {
/** A dock whose RMS exceeds this many times the drum's own profile RMS is said to be poor (good docks: 1–2 times). */
constexpr double kPoorDockRatio = 3.0;
} // namespace

namespace {

namespace dock = core::dock;

struct DockRequest {
    std::string fragment, drum, guides;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    dock::DockOptions options;
    unsigned threads = 0;
    bool json = false;
    core::cloud::CloudLoadOptions load; ///< the import frame (--up, --unit, --offset) of the point-file inputs
};

bool parseRequest(CommandLine& cl, DockRequest& r, std::string& problem)
{
    if (cl.positionals().size() != 1) return problem = "dock takes exactly one fragment file", false;
    r.fragment = cl.positionals()[0];
    r.drum = cl.value("drum").value_or("");
    if (r.drum.empty()) return problem = "dock needs --drum DRUM", false;
    r.guides = cl.value("guides").value_or("");
    r.json = cl.flag("json");
    if (const auto pose = cl.value("pose"); pose && !parsePose(*pose, r.pose, problem)) return false;
    if (const auto lock = cl.value("lock")) {
        // Every comma-separated name ("z, r" as the number lists take "0, 0, 0"), an empty one included ("", "r,": a
        // lock that names nothing is refused).
        for (const std::string& name : splitCommaList(*lock)) {
            const auto unknowns = dock::dockUnknownsFromName(name);
            if (unknowns.empty())
                return problem = "--lock: unknown \"" + name + "\" (z, r, theta, tilt, tangent, tilt_lean, tilt_roll)", false;
            for (dock::DockUnknown u : unknowns) r.options.locked[std::size_t(u)] = true;
        }
    }
    long long threads = 0;
    if (!cl.integer("threads", threads)) return problem = cl.error(), false;
    if (threads < 0 || threads > 1024) return problem = "--threads must be between 0 and 1024", false;
    r.threads = unsigned(threads);
    if (!parseReadOptions(cl, r.load.read, problem)) return false;
    if (hasFrameOptions(cl) && core::cloud::isPoctPath(r.fragment) && core::cloud::isPoctPath(r.drum))
        return problem = "--up, --unit and --offset apply to point-file inputs only, and both " + r.fragment +
                         " and " + r.drum + " are octrees", false;
    return true;
}

int fail(const core::Error& error)
{
    std::cerr << "stylos-cli: " << error.message << "\n";
    return ExitFailure;
}

/** The drum named with --guides is the frame the pose is given in, not read for its points: still a cloud or
 *  an octree, whose header opens (a folder, an empty or foreign file is named as such). */
core::Status checkDrumFile(const DockRequest& r)
{
    if (core::cloud::isPoctPath(r.drum)) {
        auto octree = core::octree::PackedOctree::open(r.drum);
        if (!octree) return octree.error();
        return {};
    }
    auto reader = core::io::openPointReader(r.drum, r.load.read);
    if (!reader) return reader.error();
    return {};
}

/** The guides: from --guides (refitted from the drum about its axis when the file has no profile), or
 *  fitted on the drum. */
core::Result<dock::DrumGuides> guidesFor(const DockRequest& r)
{
    std::error_code ec;
    if (!std::filesystem::exists(r.drum, ec)) return core::Error::at(core::ErrorCode::NotFound, r.drum, {}, "no such file");
    dock::GuideOptions options;
    options.threads = r.threads;
    if (!r.guides.empty()) {
        if (const core::Status drum = checkDrumFile(r); !drum) return drum.error();
        auto guides = dock::readGuidesFile(r.guides);
        if (!guides || !guides->profile.empty()) return guides;
        options.axis = guides->axis;
        options.flutes = guides->flutes;
    }
    auto drum = core::cloud::loadPointCloud(r.drum, r.load);
    if (!drum) return drum.error();
    drum->source = r.drum;
    ConsoleProgress progress("fitting the guides of " + r.drum);
    return dock::fitDrumGuides(*drum, options, &progress);
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

/** The command-line contract's object: exactly its keys. Uncertainty in degrees (theta, tilts) and
 *  millimetres (r, tangent, z). */
nlohmann::json dockJson(const dock::DockResult& d, double seconds)
{
    nlohmann::json rotation = nlohmann::json::array(), translation = nlohmann::json::array();
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) rotation.push_back(d.pose.linear()(i, k));
        translation.push_back(d.pose.translation()[i]);
    }
    nlohmann::json unobservable = nlohmann::json::array(), uncertainty = nlohmann::json::object();
    for (dock::DockUnknown u : d.unobservable) unobservable.push_back(dock::dockUnknownName(u));
    for (const dock::DockUncertainty& u : d.uncertainty) {
        const bool angular = u.unknown == dock::DockUnknown::Theta || u.unknown == dock::DockUnknown::TiltLean ||
                             u.unknown == dock::DockUnknown::TiltRoll;
        uncertainty[dock::dockUnknownName(u.unknown)] = angular ? degrees(u.sigma) : u.sigma * 1e3;
    }
    return {{"rotation", std::move(rotation)}, {"translation", std::move(translation)},
            {"rms_mm", d.rms * 1e3},           {"flute_shift", d.fluteShift},
            {"unobservable", std::move(unobservable)}, {"uncertainty", std::move(uncertainty)},
            {"iterations", d.iterations},      {"seconds", seconds}};
}

} // namespace

int runDock(const std::vector<std::string>& args)
{
    CommandLine cl("dock", "FRAGMENT --drum DRUM [options]",
                   withFrameOptions({{"drum", "DRUM", "the intact drum (point file or .poct) the fragment docks against"},
                    {"guides", "G.json", "the drum's guides from `stylos-cli guides` (default: fitted on DRUM)"},
                    {"pose", "R00,R01,R02,R10,R11,R12,R20,R21,R22,TX,TY,TZ",
                     "starting placement: fragment file frame -> drum file frame (default: identity)"},
                    {"lock", "z,r,theta,tilt", "unknowns kept as the start has them (also tangent, tilt_lean, tilt_roll)"},
                    {"threads", "N", "worker threads of the guides' fit (default: all cores)"},
                    {"json", "", "print the docked pose as one JSON object on stdout"}}));
    // (frame options: the same frame for both inputs, when they are point files; a .poct is already in its frame)
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Docks a fragment against the guides of an intact drum: from the starting placement, snaps its\n"
                     "flutes onto the nearest guide flutes and refines its pose in the drum frame (theta about the\n"
                     "axis, r, tangent, two tilts) by point-to-plane registration of its outer face on the flute\n"
                     "profile; locked unknowns stay out of the solve. z along the flutes cannot be fixed by them and\n"
                     "is reported unobservable. Prints the docked pose (fragment file frame -> drum file frame).\n"
                  << cl.usage();
        return ExitOk;
    }
    DockRequest r;
    std::string problem;
    if (!parseRequest(cl, r, problem)) return usageError(cl, problem);

    const auto start = std::chrono::steady_clock::now();
    auto guides = guidesFor(r);
    if (!guides) return fail(guides.error());
    auto fragment = core::cloud::loadPointCloud(r.fragment, r.load);
    if (!fragment) return fail(fragment.error());
    fragment->source = r.fragment;
    ConsoleProgress progress("docking " + r.fragment);
    auto docked = dock::dockFragment(*fragment, *guides, r.pose, r.options, &progress);
    if (!docked) return fail(docked.error());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // A dock that ends far off the profile (a wrong flute, a lock that holds it off its place) is said, not only
    // printed as a number: the drum's own points lie within guides->rms of it.
    if (guides->rms > 0.0 && docked->rms > kPoorDockRatio * guides->rms)
        std::fprintf(stderr,
                     "stylos-cli: %s sits %.2f mm RMS from the flute profile, %.1f times the drum's own %.3f mm: it may "
                     "rest on the wrong flute or be held off its place by a lock; start it nearer its place or free a "
                     "lock\n",
                     r.fragment.c_str(), docked->rms * 1e3, docked->rms / guides->rms, guides->rms * 1e3);

    if (r.json) {
        std::cout << dockJson(*docked, seconds).dump() << "\n";
        return ExitOk;
    }
    const dock::DockResult& d = *docked;
    const Eigen::Matrix3d& m = d.pose.linear();
    const Eigen::Vector3d& t = d.pose.translation();
    std::printf("docked %s against %s: RMS %.3f mm over %zu points, moved %.3f flutes about the axis, %d iterations, "
                "%.2f s\npose %.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n",
                r.fragment.c_str(), r.drum.c_str(), d.rms * 1e3, d.inliers, d.fluteShift, d.iterations, seconds, m(0, 0),
                m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2), t.x(), t.y(), t.z());
    for (dock::DockUnknown u : d.unobservable)
        std::printf("%s is not fixed by the flutes: left where the start put it (lock it, or dock against a shared bed)\n",
                    dock::dockUnknownName(u));
    return ExitOk;
}

} // namespace stylos::cli
