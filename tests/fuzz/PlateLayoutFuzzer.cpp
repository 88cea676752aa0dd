// libFuzzer harness: the plate layout reader (plate/PlateSpec.cpp: PlateSpec::read, as `stylos-cli plate
// --layout` uses it), then its validation. A layout that reads must write and read back equal.
#include "FuzzSupport.h"

#include "stylos/core/plate/PlateSpec.h"

#include <nlohmann/json.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos::core::plate;
    auto spec = PlateSpec::read(stylos::fuzz::writeScratch(data, size, "json").string());
    if (!spec) return 0;
    (void)spec->validate("layout");
    auto again = PlateSpec::fromJson(nlohmann::json::parse(spec->toJson().dump()), "again");
    if (!again) stylos::fuzz::broken("a layout that reads does not read back once written");
    if (!(again.value() == spec.value())) stylos::fuzz::broken("a layout written and read back differs");
    return 0;
}
