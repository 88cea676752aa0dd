#pragma once
/** @file
 * @brief The shadings of a développée, one table for every caller: the kind, the key the command line,
 *        the settings and the image metadata use ("height", "light", "skydome"), and the English display
 *        name (the workbench translates it). The table's first row is the default (skydome).
 *
 * Thread-safety: constant data. Failure modes: an unknown key gives std::nullopt.
 */
#include <optional>
#include <span>
#include <string_view>

namespace stylos::core::developpee {

/** @brief How the height field becomes grey. */
enum class Shading {
    Skydome, ///< the visible solid angle of the sky (horizon search over D azimuths), contrast-stretched 1–99 %
    Light,   ///< one directional light (Lambert)
    Height,  ///< height as grey, 1–99 % robust range
};

/** @brief One row of the table. */
struct ShadingInfo {
    Shading kind;
    const char* key;         ///< "skydome", "light", "height": the CLI's --shading words and settings values
    const char* displayName; ///< "Skydome", "Light", "Height": English, translated by the workbench
};

/** @brief Every shading, the default first. */
std::span<const ShadingInfo> shadings();
/** @brief The row of @p kind. */
const ShadingInfo& shadingInfo(Shading kind);
/** @brief The kind whose key is @p key (exact, lower case); nullopt otherwise. */
std::optional<Shading> shadingFromKey(std::string_view key);
/** @brief "skydome, light or height": the keys for a usage message. */
const char* shadingKeyList();

} // namespace stylos::core::developpee
