#pragma once
// The --axis PX,PY,PZ,DX,DY,DZ argument shared by the commands that accept a given axis (unroll, guides).
#include "stylos/core/unroll/Surface.h"

#include <string>

namespace stylos::cli {

/** "PX,PY,PZ,DX,DY,DZ" (metres) → an axis with a unit direction; false with @p problem set (naming
 *  --axis and what is wrong) otherwise. */
bool parseAxis(const std::string& text, core::unroll::Axis& axis, std::string& problem);

} // namespace stylos::cli
