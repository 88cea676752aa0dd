#pragma once
// The geometric arguments shared by the commands: --axis PX,PY,PZ,DX,DY,DZ (unroll, guides, dock) and
// --pose R00,…,R22,TX,TY,TZ (dock), read from comma-separated numbers.
#include "stylos/core/unroll/Surface.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <string>
#include <vector>

namespace stylos::cli {

/** @p text's comma-separated items, each without the spaces and tabs around it; empty items kept ("", "r," give an
 *  empty item: a list that names nothing is the caller's to refuse). */
std::vector<std::string> splitCommaList(const std::string& text);

/** @p count comma-separated finite decimal numbers (an optional sign, digits, a point, an exponent, spaces around: no
 *  hexadecimal, no empty item); false with @p problem set (naming @p option and the item) otherwise. */
bool parseNumberList(const std::string& text, const std::string& option, std::size_t count, std::vector<double>& values,
                     std::string& problem);

/** "PX,PY,PZ,DX,DY,DZ" (metres) → an axis with a unit direction; false with @p problem set (naming
 *  --axis and what is wrong) otherwise. */
bool parseAxis(const std::string& text, core::unroll::Axis& axis, std::string& problem);

/** "R00,R01,R02,R10,R11,R12,R20,R21,R22,TX,TY,TZ" (row-major rotation, metres) → a rigid pose; the
 *  rotation must be one to 1e-4 (|R·Rᵀ − I| per entry; determinant > 0), as tools print it to 6 decimals, and is made
 *  exact (the nearest rotation): false with @p problem set (how far off) otherwise. */
bool parsePose(const std::string& text, Eigen::Isometry3d& pose, std::string& problem);

} // namespace stylos::cli
