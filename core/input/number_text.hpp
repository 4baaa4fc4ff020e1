// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Numbers in messages: six significant digits ("r = 2.32088 M"), the precision a reader of an
// error message or a report wants (formatBound in ranges.hpp gives the exact shortest form).
#include <cstdio>
#include <string>

namespace lc::input {

inline std::string significantDigits(double v, int digits = 6) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

}  // namespace lc::input
