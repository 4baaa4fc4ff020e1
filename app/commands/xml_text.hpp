// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Text for XML attributes and elements (VTK's .vtm index, the sweep's SVG): &, <, > and ".
#include <string>

namespace lc::cli {

inline std::string xmlEscaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

}  // namespace lc::cli
