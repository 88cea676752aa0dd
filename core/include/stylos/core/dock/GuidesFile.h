#pragma once
/** @file
 * @brief The guides of a drum as JSON: the object `stylos-cli guides` writes (keys axis_point, axis_dir,
 *        radius, flute_depth, flutes, flute_lines, phase_deg, rms, seconds — the command-line contract —
 *        and profile, the 64-bin flute profile a fragment docks against) and reading it back, so a guides
 *        file fitted once serves every fragment (`stylos-cli dock --guides`). Units: metres, degrees for
 *        phase_deg. Thread-safety: reentrant.
 */
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/util/Result.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>

namespace stylos::core::dock {

/** The guides as the contract's object, @p seconds as its "seconds". */
nlohmann::json guidesToJson(const DrumGuides& guides, double seconds);

/**
 * @brief Guides from such an object. axis_point, axis_dir (not zero; normalised), radius (> 0),
 *        flute_depth (≥ 0), flutes (3..1000) and phase_deg are required; profile (DrumGuides::ProfileBins
 *        positive radii) and rms are optional (an empty profile: dockFragment refuses it, the caller
 *        refits it from the drum). The flute lines are recomputed from the axis, phase and depth; the
 *        reference direction is the développée's (unroll::defaultReferenceDir). InvalidArgument naming
 *        @p source and the key at fault.
 */
Result<DrumGuides> guidesFromJson(const nlohmann::json& object, const std::string& source);

/** Reads and parses @p path (guidesFromJson()); NotFound / Unreadable / Malformed (not JSON) / InvalidArgument naming the file. */
Result<DrumGuides> readGuidesFile(const std::filesystem::path& path);

} // namespace stylos::core::dock
