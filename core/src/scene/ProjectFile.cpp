#include "stylos/core/scene/ProjectFile.h"

#include "stylos/core/util/AtomicTextFile.h"
#include "stylos/core/util/JsonText.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

namespace stylos::core::scene {

namespace {

using nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

OrderedJson vectorJson(const std::array<double, 3>& v)
{
    return OrderedJson::array({v[0], v[1], v[2]});
}

OrderedJson fragmentJson(const Fragment& f, const std::filesystem::path& folder)
{
    OrderedJson guides = OrderedJson::array();
    for (const Guide& g : f.guides) {
        OrderedJson guide;
        guide["name"] = g.name;
        guide["kind"] = guideKindName(g.kind);
        guide["origin"] = vectorJson(g.origin);
        guide["direction"] = vectorJson(g.direction);
        guides.push_back(std::move(guide));
    }
    OrderedJson pose = OrderedJson::array();
    for (double v : f.pose.rowMajor()) pose.push_back(v);

    OrderedJson out;
    out["id"] = f.id;
    out["name"] = f.name;
    out["octree"] = ProjectFile::storedPath(f.octreePath, folder);
    out["source"] = ProjectFile::storedPath(f.sourcePath, folder);
    out["pose"] = std::move(pose);
    out["colour"] = f.colour.toHex();
    out["visible"] = f.visible;
    out["guides"] = std::move(guides);
    out["annotations"] = f.annotationLayer;
    out["assembly"] = f.assembly;
    out["up"] = io::upAxisName(f.importFrame.up);
    out["unit"] = io::lengthUnitName(f.importFrame.unit);
    out["offset"] = vectorJson(f.importFrame.offset);
    return out;
}

OrderedJson assemblyJson(const Assembly& a)
{
    OrderedJson pose = OrderedJson::array();
    for (double v : a.pose.rowMajor()) pose.push_back(v);
    OrderedJson out;
    out["id"] = a.id;
    out["name"] = a.name;
    out["pose"] = std::move(pose);
    out["drum"] = a.drum;
    out["visible"] = a.visible;
    return out;
}

std::filesystem::path projectFolder(const std::filesystem::path& projectPath)
{
    std::error_code ignored;
    std::filesystem::path absolute = std::filesystem::absolute(projectPath, ignored);
    if (absolute.empty()) absolute = projectPath;
    return absolute.lexically_normal().parent_path();
}

/** Reads the JSON tree into a scene, naming the file and the key path in every error. */
class SceneReader {
public:
    SceneReader(std::string file, std::filesystem::path folder) : m_file(std::move(file)), m_folder(std::move(folder)) {}

    Result<LoadedProject> read(const json& root);

private:
    Error bad(const std::string& key, const std::string& problem) const
    {
        return Error::at(ErrorCode::Malformed, m_file, key, problem);
    }

    static const json* member(const json& object, const char* name)
    {
        const auto it = object.find(name);
        return it == object.end() ? nullptr : &*it;
    }

    static bool finiteNumbers(const json& value, std::size_t count, double* out)
    {
        if (!value.is_array() || value.size() != count) return false;
        for (std::size_t i = 0; i < count; ++i) {
            if (!value[i].is_number()) return false;
            out[i] = value[i].get<double>();
            if (!std::isfinite(out[i])) return false;
        }
        return true;
    }

    Result<Fragment> readFragment(const json& value, const std::string& key) const;
    Result<Assembly> readAssembly(const json& value, const std::string& key) const;
    Result<Pose> readPose(const json* pose, const std::string& key) const;
    Result<Guide> readGuide(const json& value, const std::string& key) const;

    /** Notes the keys of @p object (at @p at) that this version does not read: they are not kept on save. */
    void noteUnknown(const json& object, const std::string& at, std::initializer_list<const char*> known) const
    {
        for (auto it = object.begin(); it != object.end(); ++it)
            if (std::none_of(known.begin(), known.end(), [&](const char* k) { return it.key() == k; }))
                m_unknown.push_back(at.empty() ? it.key() : at + "." + it.key());
    }

    std::string m_file;
    std::filesystem::path m_folder;
    mutable std::vector<std::string> m_unknown;
};

Result<LoadedProject> SceneReader::read(const json& root)
{
    if (!root.is_object())
        return Error::at(ErrorCode::UnknownFormat, m_file, {}, "not a Stylos project (not a JSON object)");
    const json* format = member(root, "format");
    if (!format || !format->is_string() || format->get<std::string>() != ProjectFormatName)
        return Error::at(ErrorCode::UnknownFormat, m_file, "format",
                         "not a Stylos project (\"format\" is not \"" + std::string(ProjectFormatName) + "\")");
    const json* version = member(root, "version");
    if (!version) return bad("version", "is missing");
    if (!version->is_number_integer()) return bad("version", "is not an integer");
    const std::int64_t versionNumber = version->get<std::int64_t>();
    if (versionNumber < 1 || versionNumber > ProjectFormatVersion)
        return Error::at(ErrorCode::Unsupported, m_file, "version",
                         "version " + std::to_string(versionNumber) + " is not supported (this Stylos reads versions 1 to " +
                             std::to_string(ProjectFormatVersion) + ")");

    const json* fragments = member(root, "fragments");
    if (!fragments) return bad("fragments", "is missing");
    if (!fragments->is_array()) return bad("fragments", "is not an array");

    LoadedProject project;
    noteUnknown(root, "", {"format", "version", "nextId", "nextAssemblyId", "dockingDrum", "assemblies", "fragments", "legend",
                        "plate"});
    // Version 2: the assemblies, before the fragments that refer to them.
    if (const json* assemblies = versionNumber >= 2 ? member(root, "assemblies") : nullptr) {
        if (!assemblies->is_array()) return bad("assemblies", "is not an array");
        for (std::size_t i = 0; i < assemblies->size(); ++i) {
            const std::string key = "assemblies[" + std::to_string(i) + "]";
            auto assembly = readAssembly((*assemblies)[i], key);
            if (!assembly) return assembly.error();
            if (project.scene.addAssembly(*assembly) == NoAssembly)
                return bad(key + ".id", "duplicate id " + std::to_string(assembly->id));
        }
    }
    std::set<FragmentId> ids;
    for (std::size_t i = 0; i < fragments->size(); ++i) {
        const std::string key = "fragments[" + std::to_string(i) + "]";
        auto fragment = readFragment((*fragments)[i], key);
        if (!fragment) return fragment.error();
        if (!ids.insert(fragment->id).second)
            return bad(key + ".id", "duplicate id " + std::to_string(fragment->id));
        if (fragment->assembly != NoAssembly && !project.scene.findAssembly(fragment->assembly))
            return bad(key + ".assembly", "no assembly has id " + std::to_string(fragment->assembly));
        if (!fragment->octreePath.empty() && !std::filesystem::exists(fragment->octreePath)) {
            fragment->octreeMissing = true;
            project.problems.push_back(Error::at(ErrorCode::NotFound, fragment->octreePath.string(), {},
                                                 "the octree of fragment \"" + fragment->name + "\" does not exist"));
        }
        project.scene.add(std::move(fragment).value());
    }

    if (const json* nextId = member(root, "nextId")) {
        if (!nextId->is_number_unsigned() || !project.scene.setNextId(nextId->get<FragmentId>()))
            return bad("nextId", "is not an integer above every fragment id");
    }
    for (std::size_t i = 0; i < project.scene.assemblies().size(); ++i) {
        const FragmentId drum = project.scene.assemblies()[i].drum;
        if (drum != NoFragment && !project.scene.find(drum))
            return bad("assemblies[" + std::to_string(i) + "].drum", "no fragment has id " + std::to_string(drum));
    }
    if (const json* drum = member(root, "dockingDrum")) {
        if (!drum->is_number_unsigned()) return bad("dockingDrum", "is not a fragment id");
        if (!project.scene.setDockingDrum(drum->get<FragmentId>()))
            return bad("dockingDrum", "no fragment has id " + std::to_string(drum->get<FragmentId>()));
    }
    if (const json* nextAssemblyId = versionNumber >= 2 ? member(root, "nextAssemblyId") : nullptr) {
        if (!nextAssemblyId->is_number_unsigned() || !project.scene.setNextAssemblyId(nextAssemblyId->get<AssemblyId>()))
            return bad("nextAssemblyId", "is not an integer above every assembly id");
    }
    if (const json* legend = member(root, "legend")) {
        auto read = annotation::Legend::fromJson(*legend, m_file + ": legend");
        if (!read) return read.error();
        project.scene.setLegend(std::move(read).value());
    }
    if (const json* plate = member(root, "plate")) {
        // The plate only remembers the last export's layout: one this version cannot read (a misspelt key,
        // a later version's layout) must not keep the fragments, poses and labels from opening.
        auto read = plate::PlateSpec::fromJson(*plate, m_file + ": plate");
        if (read) {
            project.scene.setPlate(std::move(read).value());
        } else {
            project.plateProblem = read.error();
            project.scene.setUnreadPlate(plate->dump());
        }
    }
    project.unknownKeys = std::move(m_unknown);
    return project;
}

Result<Pose> SceneReader::readPose(const json* pose, const std::string& key) const
{
    if (!pose) return bad(key, "is missing");
    std::array<double, 16> m{};
    if (!finiteNumbers(*pose, 16, m.data())) return bad(key, "is not an array of 16 finite numbers");
    Pose p(m);
    if (!p.isRigid()) return bad(key, "is not a rigid transform (a rotation and a translation)");
    return p;
}

Result<Assembly> SceneReader::readAssembly(const json& value, const std::string& key) const
{
    if (!value.is_object()) return bad(key, "is not an object");
    noteUnknown(value, key, {"id", "name", "pose", "drum", "visible"});
    Assembly a;
    const json* id = member(value, "id");
    if (!id) return bad(key + ".id", "is missing");
    if (!id->is_number_unsigned() || id->get<AssemblyId>() == NoAssembly) return bad(key + ".id", "is not a positive integer");
    a.id = id->get<AssemblyId>();
    const json* name = member(value, "name");
    if (!name || !name->is_string()) return bad(key + ".name", "is missing or not a string");
    a.name = name->get<std::string>();
    auto pose = readPose(member(value, "pose"), key + ".pose");
    if (!pose) return pose.error();
    a.pose = *pose;
    if (const json* drum = member(value, "drum")) {
        if (!drum->is_number_unsigned()) return bad(key + ".drum", "is not a fragment id");
        a.drum = drum->get<FragmentId>();
    }
    if (const json* visible = member(value, "visible")) {
        if (!visible->is_boolean()) return bad(key + ".visible", "is not true or false");
        a.visible = visible->get<bool>();
    }
    return a;
}

Result<Fragment> SceneReader::readFragment(const json& value, const std::string& key) const
{
    if (!value.is_object()) return bad(key, "is not an object");
    noteUnknown(value, key, {"id", "name", "octree", "source", "pose", "colour", "visible", "guides", "annotations", "assembly", "up", "unit", "offset"});
    Fragment f;

    const json* id = member(value, "id");
    if (!id) return bad(key + ".id", "is missing");
    if (!id->is_number_unsigned() || id->get<FragmentId>() == NoFragment)
        return bad(key + ".id", "is not a positive integer");
    f.id = id->get<FragmentId>();

    const json* name = member(value, "name");
    if (!name) return bad(key + ".name", "is missing");
    if (!name->is_string()) return bad(key + ".name", "is not a string");
    f.name = name->get<std::string>();

    const json* octree = member(value, "octree");
    if (!octree) return bad(key + ".octree", "is missing");
    if (!octree->is_string() || octree->get<std::string>().empty()) return bad(key + ".octree", "is not a file name");
    f.octreePath = ProjectFile::resolvedPath(octree->get<std::string>(), m_folder);

    if (const json* source = member(value, "source")) {
        if (!source->is_string()) return bad(key + ".source", "is not a string");
        f.sourcePath = ProjectFile::resolvedPath(source->get<std::string>(), m_folder);
    }

    auto pose = readPose(member(value, "pose"), key + ".pose");
    if (!pose) return pose.error();
    f.pose = *pose;
    if (const json* assembly = member(value, "assembly")) {
        if (!assembly->is_number_unsigned()) return bad(key + ".assembly", "is not an assembly id");
        f.assembly = assembly->get<std::uint64_t>();
    }

    if (const json* colour = member(value, "colour")) {
        const auto rgb = colour->is_string() ? Rgb::fromHex(colour->get<std::string>()) : std::nullopt;
        if (!rgb) return bad(key + ".colour", "is not a colour \"#rrggbb\"");
        f.colour = *rgb;
    }
    if (const json* visible = member(value, "visible")) {
        if (!visible->is_boolean()) return bad(key + ".visible", "is not true or false");
        f.visible = visible->get<bool>();
    }
    if (const json* guides = member(value, "guides")) {
        if (!guides->is_array()) return bad(key + ".guides", "is not an array");
        for (std::size_t i = 0; i < guides->size(); ++i) {
            auto guide = readGuide((*guides)[i], key + ".guides[" + std::to_string(i) + "]");
            if (!guide) return guide.error();
            f.guides.push_back(std::move(guide).value());
        }
    }
    if (const json* annotations = member(value, "annotations")) {
        if (!annotations->is_string()) return bad(key + ".annotations", "is not a string");
        f.annotationLayer = annotations->get<std::string>();
    }
    if (const json* up = member(value, "up")) {
        const auto axis = up->is_string() ? io::upAxisFromName(up->get<std::string>()) : std::nullopt;
        if (!axis)
            return bad(key + ".up", "is " + up->dump() + ", not one of the up axes " + io::upAxisChoices());
        f.importFrame.up = *axis;
    }
    if (const json* unit = member(value, "unit")) {
        const auto parsed = unit->is_string() ? io::lengthUnitFromName(unit->get<std::string>()) : std::nullopt;
        if (!parsed)
            return bad(key + ".unit", "is " + unit->dump() + ", not one of the units " + io::lengthUnitChoices());
        f.importFrame.unit = *parsed;
    }
    if (const json* offset = member(value, "offset")) {
        if (!finiteNumbers(*offset, 3, f.importFrame.offset.data()))
            return bad(key + ".offset", "is not an array of 3 finite numbers");
    }
    return f;
}

Result<Guide> SceneReader::readGuide(const json& value, const std::string& key) const
{
    if (!value.is_object()) return bad(key, "is not an object");
    noteUnknown(value, key, {"name", "kind", "origin", "direction"});
    Guide g;
    const json* name = member(value, "name");
    if (!name || !name->is_string()) return bad(key + ".name", "is missing or not a string");
    g.name = name->get<std::string>();
    const json* kind = member(value, "kind");
    const auto parsed = kind && kind->is_string() ? guideKindFromName(kind->get<std::string>()) : std::nullopt;
    if (!parsed) return bad(key + ".kind", "is not \"axis\" or \"groove\"");
    g.kind = *parsed;
    const json* origin = member(value, "origin");
    if (!origin || !finiteNumbers(*origin, 3, g.origin.data()))
        return bad(key + ".origin", "is not an array of 3 finite numbers");
    const json* direction = member(value, "direction");
    if (!direction || !finiteNumbers(*direction, 3, g.direction.data()))
        return bad(key + ".direction", "is not an array of 3 finite numbers");
    const auto& d = g.direction;
    if (std::abs(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - 1.0) > 1e-6)
        return bad(key + ".direction", "is not a unit vector");
    return g;
}

} // namespace

std::string ProjectFile::toJson(const Scene& scene, const std::filesystem::path& projectPath)
{
    const std::filesystem::path folder = projectFolder(projectPath);
    OrderedJson fragments = OrderedJson::array();
    for (const Fragment& f : scene.fragments()) fragments.push_back(fragmentJson(f, folder));
    OrderedJson root;
    root["format"] = ProjectFormatName;
    root["version"] = ProjectFormatVersion;
    root["nextId"] = scene.nextId();
    root["nextAssemblyId"] = scene.nextAssemblyId();
    root["dockingDrum"] = scene.dockingDrum();
    OrderedJson assemblies = OrderedJson::array();
    for (const Assembly& a : scene.assemblies()) assemblies.push_back(assemblyJson(a));
    root["assemblies"] = std::move(assemblies);
    root["fragments"] = std::move(fragments);
    root["legend"] = OrderedJson::parse(scene.legend().toJson().dump());
    if (scene.plate())
        root["plate"] = OrderedJson::parse(scene.plate()->toJson().dump());
    else if (!scene.unreadPlate().empty())
        root["plate"] = OrderedJson::parse(scene.unreadPlate());
    return root.dump(2) + "\n";
}

Result<LoadedProject> ProjectFile::fromJson(std::string_view text, const std::filesystem::path& projectPath)
{
    const std::string file = projectPath.string();
    if (std::all_of(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }))
        return Error::at(ErrorCode::Empty, file, {}, "the project file is empty");
    auto root = parseJsonText(text, file);
    if (!root) return root.error();
    return SceneReader(file, projectFolder(projectPath)).read(root.value());
}

Status ProjectFile::save(const Scene& scene, const std::filesystem::path& projectPath)
{
    return writeTextFileAtomically(projectPath, toJson(scene, projectPath));
}

Result<LoadedProject> ProjectFile::load(const std::filesystem::path& projectPath)
{
    const std::string name = projectPath.string();
    std::error_code error;
    const auto status = std::filesystem::status(projectPath, error);
    if (!std::filesystem::exists(status)) return Error::at(ErrorCode::NotFound, name, {}, "no such file");
    if (std::filesystem::is_directory(status)) return Error::at(ErrorCode::Unreadable, name, {}, "is a folder");
    std::ifstream in(projectPath, std::ios::binary);
    if (!in) return Error::at(ErrorCode::Unreadable, name, {}, std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return Error::at(ErrorCode::Unreadable, name, {}, "read failed");
    return fromJson(text.str(), projectPath);
}

std::string ProjectFile::storedPath(const std::filesystem::path& file, const std::filesystem::path& folder)
{
    if (file.empty()) return {};
    std::error_code ignored;
    std::filesystem::path absolute = file.is_absolute() ? file : std::filesystem::absolute(file, ignored);
    absolute = absolute.lexically_normal();
    const std::filesystem::path relative = absolute.lexically_relative(folder.lexically_normal());
    // No relative form (another root, e.g. another drive): keep it absolute.
    return relative.empty() ? absolute.generic_string() : relative.generic_string();
}

std::filesystem::path ProjectFile::resolvedPath(std::string_view stored, const std::filesystem::path& folder)
{
    if (stored.empty()) return {};
    const std::filesystem::path path{std::string(stored)};
    if (path.is_absolute()) return path.lexically_normal();
    return (folder / path).lexically_normal();
}

} // namespace stylos::core::scene
