#pragma once
/** @file
 * @brief Which kernel walks the skydome's horizons (SkydomeShading.h): the portable one, AVX2 or
 *        AVX-512. All give the same bits; they differ only in speed. Auto takes the fastest this CPU
 *        runs, unless the environment variable STYLOS_SKYDOME_KERNEL (auto, portable, avx2, avx512)
 *        names one, which is how a measurement forces a kernel on a whole program (stylos-cli, the GUI).
 */
#include "stylos/core/util/Result.h"

#include <string_view>

namespace stylos::core::shading {

/** @brief The horizon kernel of the skydome. */
enum class SkydomeKernel {
    Auto,     ///< STYLOS_SKYDOME_KERNEL when set, else the fastest the CPU runs (AVX-512, AVX2, portable)
    Portable, ///< plain C++, any CPU: the lanes one after the other
    Avx2,     ///< x86-64 with AVX2: 8 lanes per register, no FMA (so the same bits)
    Avx512,   ///< x86-64 with AVX-512F: 16 lanes per register
};

/** @brief "auto", "portable", "avx2" or "avx512". */
std::string_view skydomeKernelName(SkydomeKernel kernel);

/** @brief The kernel named @p name (as skydomeKernelName writes it); InvalidArgument otherwise. */
Result<SkydomeKernel> parseSkydomeKernel(std::string_view name);

/** @brief Whether this build and this CPU run @p kernel (Auto and Portable: always). */
bool skydomeKernelAvailable(SkydomeKernel kernel);

/**
 * @brief The kernel that runs for @p kernel: itself when available, Auto resolved (the environment
 *        variable, then the CPU). InvalidArgument when the kernel asked for (or named by the
 *        environment variable) is unknown or does not run on this CPU.
 */
Result<SkydomeKernel> resolveSkydomeKernel(SkydomeKernel kernel);

} // namespace stylos::core::shading
