// libFuzzer harness: the développée sidecar (unroll/UnrollMap.cpp: UnrollMap::readSidecar, with the surface
// it holds, unroll/Surface.cpp), read from a file as `stylos-cli annotate --map` and the workbench do. A map
// that reads must then map pixels to 3D and back without tripping an assertion (the fuzz build keeps them).
#include "FuzzSupport.h"

#include "stylos/core/unroll/UnrollMap.h"

#include <nlohmann/json.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos::core::unroll;
    auto map = UnrollMap::readSidecar(stylos::fuzz::writeScratch(data, size, "png.json"));
    if (!map) return 0;
    for (const auto& [column, row] : {std::pair{0.5, 0.5}, std::pair{map->width() - 0.5, map->height() - 0.5}}) {
        const Eigen::Vector3d world = map->worldAtPixel(column, row, 0.001);
        (void)map->pixelOf(world);
        (void)map->surfaceCoords(world);
    }
    (void)map->toJson().dump();
    return 0;
}
