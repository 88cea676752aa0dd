#pragma once
/** @file
 * @brief The project file (`.stylos`): the scene as JSON,
 *
 *     {"format": "stylos-project", "version": 2, "nextId": 3, "nextAssemblyId": 2, "dockingDrum": 2,
 *      "assemblies": [{"id": 1, "name": "Drum 1 reconstruction", "pose": [16 numbers, row-major],
 *                      "drum": 2, "visible": true}],
 *      "fragments": [{"id": 1, "name": "Drum 1", "octree": "drum1.poct", "source": "scans/drum1.ply",
 *                     "pose": [16 numbers, row-major], "colour": "#d6ccba", "visible": true,
 *                     "guides": [{"name": "axis", "kind": "axis", "origin": [x, y, z],
 *                                 "direction": [x, y, z]}],
 *                     "annotations": "", "assembly": 1, "up": "+Y", "unit": "mm", "offset": [0, 0, 0]}],
 *      "legend": {"format": "stylos-legend", "version": 1, "layers": {…}}}
 *
 * A fragment's "pose" is relative to its "assembly" (0 or absent: the scene's top level); an assembly's
 * "drum" is the fragment whose guides its members dock against (0: none); "dockingDrum" the one that fragments
 * outside such an assembly dock against (Scene::dockingDrum, 0: none). Version 1 files (no
 * assemblies, every fragment at the top level) are still read; files are written as version 2.
 *
 * Paths are stored relative to the project file's folder ('/' separators; absolute only when no relative
 * form exists) and resolved back to absolute on load, so a project folder can be moved or copied whole.
 * Doubles are written with enough digits to read back bit for bit: save then load gives an equal Scene.
 * Saving is atomic (util/AtomicTextFile.h). Every key listed is written, even when empty; unknown keys
 * are ignored (a later writer may add some). Optional on load (defaults in brackets): "nextId"
 * [above the largest id], "nextAssemblyId" [above the largest], "dockingDrum" [0], "assemblies" [[]], "source" [""], "colour"
 * [#c8c8c8], "visible" [true], "guides" [[]], "annotations" [""], "assembly" [0], "up" ["+Z"], "unit" ["m"], "offset" [[0, 0, 0]] (the
 * fragment's import frame, io/ImportFrame.h: a record of how its octree was built from its source; an
 * "up" or "unit" outside the lists is Malformed, naming the value and the choices), an assembly's "drum"
 * [0] and "visible" [true], "legend" [the default vocabulary, annotation::Legend::defaults()]: the
 * project's annotation classes as annotation/Legend.h writes them (a Malformed legend names the project
 * file, "legend" and the legend's key), "plate" [none: written only once a plate was exported]: the last
 * plate's statement as plate/PlateSpec.h writes it (a Malformed one names "plate" and its key); "id", "name", "octree" and "pose" are required (an assembly's "id", "name", "pose").
 *
 * Load failures name the file and the key: NotFound, Unreadable, Empty; Malformed (not JSON: "line L,
 * column C"; a key of the wrong type or out of range: its path, e.g. "fragments[1].pose"; a duplicate
 * id; a fragment's "assembly", an assembly's "drum" or the "dockingDrum" that names nothing); UnknownFormat (no "format":
 * "stylos-project"); Unsupported (a "version" other than 1 or 2).
 * A fragment whose octree file does not exist is not a failure: the project loads with that fragment's
 * octreeMissing set and one NotFound problem naming the octree file.
 * Thread-safety: reentrant.
 */
#include "stylos/core/scene/Scene.h"
#include "stylos/core/util/Result.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::scene {

/** @brief The value of "format". */
inline constexpr std::string_view ProjectFormatName = "stylos-project";
/** @brief The version this code writes; it reads 1 (no assemblies) up to this one. */
inline constexpr int ProjectFormatVersion = 2;
/** @brief The project file's extension, dot included. */
inline constexpr std::string_view ProjectExtension = ".stylos";

/** @brief A loaded project: the scene, and what was wrong with single fragments (missing octrees) or with
 *  its plate layout. */
struct LoadedProject {
    Scene scene;
    std::vector<Error> problems;  ///< one per fragment whose octree is missing, in fragment order
    /** The "plate" section could not be read (named key and problem): the project opens without a plate
     *  and keeps the section's text (Scene::unreadPlate). */
    std::optional<Error> plateProblem;
    /** Keys this version does not read ("mystery", "fragments[0].frobnicate"), in file order: a later version's or a
     *  hand edit's; they are not written back on save. */
    std::vector<std::string> unknownKeys;
};

class ProjectFile {
public:
    /** @brief The JSON text of @p scene for a project file at @p projectPath (paths made relative to its folder). */
    static std::string toJson(const Scene& scene, const std::filesystem::path& projectPath);
    /**
     * @brief Parses @p text as the project file @p projectPath (for the messages and to resolve paths).
     *        Checks the octree files' existence (see the file comment).
     */
    static Result<LoadedProject> fromJson(std::string_view text, const std::filesystem::path& projectPath);

    /** @brief Writes @p scene to @p projectPath atomically. Errors: WriteFailed naming the file. */
    static Status save(const Scene& scene, const std::filesystem::path& projectPath);
    /** @brief Reads @p projectPath (errors in the file comment). */
    static Result<LoadedProject> load(const std::filesystem::path& projectPath);

    /** @brief @p file as stored in a project in @p folder: relative with '/' when possible; "" stays "". */
    static std::string storedPath(const std::filesystem::path& file, const std::filesystem::path& folder);
    /** @brief A stored path back to absolute (normalised) against @p folder; "" stays "". */
    static std::filesystem::path resolvedPath(std::string_view stored, const std::filesystem::path& folder);
};

} // namespace stylos::core::scene
