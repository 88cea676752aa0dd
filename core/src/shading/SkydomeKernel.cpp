#include "stylos/core/shading/SkydomeKernel.h"

#include "HorizonSweep.h"

#include <cassert>
#include <cstdlib>
#include <string>

namespace stylos::core::shading {
namespace {

constexpr const char* kEnvironment = "STYLOS_SKYDOME_KERNEL";

bool cpuHas(SkydomeKernel kernel)
{
#if STYLOS_HORIZON_X86_KERNELS
    static const bool avx2 = __builtin_cpu_supports("avx2");
    static const bool avx512 = __builtin_cpu_supports("avx512f");
    return kernel == SkydomeKernel::Avx2 ? avx2 : kernel == SkydomeKernel::Avx512 ? avx512 : true;
#else
    return kernel == SkydomeKernel::Auto || kernel == SkydomeKernel::Portable;
#endif
}

} // namespace

std::string_view skydomeKernelName(SkydomeKernel kernel)
{
    switch (kernel) {
    case SkydomeKernel::Auto:
        return "auto";
    case SkydomeKernel::Portable:
        return "portable";
    case SkydomeKernel::Avx2:
        return "avx2";
    case SkydomeKernel::Avx512:
        return "avx512";
    }
    return "auto";
}

Result<SkydomeKernel> parseSkydomeKernel(std::string_view name)
{
    for (const auto kernel : {SkydomeKernel::Auto, SkydomeKernel::Portable, SkydomeKernel::Avx2, SkydomeKernel::Avx512})
        if (name == skydomeKernelName(kernel)) return kernel;
    return Error{ErrorCode::InvalidArgument,
                 "skydome: kernel '" + std::string(name) + "' is not one of auto, portable, avx2, avx512"};
}

bool skydomeKernelAvailable(SkydomeKernel kernel)
{
    return cpuHas(kernel);
}

Result<SkydomeKernel> resolveSkydomeKernel(SkydomeKernel kernel)
{
    if (kernel == SkydomeKernel::Auto) {
        if (const char* named = std::getenv(kEnvironment); named != nullptr && *named != '\0') {
            auto parsed = parseSkydomeKernel(named);
            if (!parsed.ok())
                return Error{ErrorCode::InvalidArgument, "skydome: " + std::string(kEnvironment) + "=" + named +
                                                             " is not one of auto, portable, avx2, avx512"};
            kernel = *parsed;
        }
    }
    if (kernel == SkydomeKernel::Auto) {
        return cpuHas(SkydomeKernel::Avx512) ? SkydomeKernel::Avx512
               : cpuHas(SkydomeKernel::Avx2) ? SkydomeKernel::Avx2
                                             : SkydomeKernel::Portable;
    }
    if (!cpuHas(kernel))
        return Error{ErrorCode::InvalidArgument,
                     "skydome: the " + std::string(skydomeKernelName(kernel)) + " kernel does not run on this CPU"};
    return kernel;
}

namespace detail {

GroupKernel groupKernel(SkydomeKernel kernel)
{
    assert(kernel != SkydomeKernel::Auto && cpuHas(kernel) && "detail::groupKernel(): kernel not resolved");
    switch (kernel) {
#if STYLOS_HORIZON_X86_KERNELS
    case SkydomeKernel::Avx2:
        return walkGroupAvx2;
    case SkydomeKernel::Avx512:
        return walkGroupAvx512;
#endif
    default:
        return walkGroupScalar;
    }
}

} // namespace detail
} // namespace stylos::core::shading
