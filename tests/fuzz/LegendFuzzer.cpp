// libFuzzer harness: the legend file reader (annotation/Legend.cpp: Legend::read, as `--legend` and the
// project's "legend" key use it). A legend that reads must write and read back equal.
#include "FuzzSupport.h"

#include "stylos/core/annotation/Legend.h"

#include <nlohmann/json.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos::core::annotation;
    auto legend = Legend::read(stylos::fuzz::writeScratch(data, size, "json"));
    if (!legend) return 0;
    auto again = Legend::fromJson(nlohmann::json::parse(legend->toJson().dump()), "again");
    if (!again) stylos::fuzz::broken("a legend that reads does not read back once written");
    if (!(again.value() == legend.value())) stylos::fuzz::broken("a legend written and read back differs");
    return 0;
}
