// SPDX-License-Identifier: BSD-3-Clause
#include "glsl_sources.hpp"

#include <stdexcept>

namespace lc::views {

std::string glslSource(const std::string& stem) {
    const auto& all = glslSources();
    const auto it = all.find(stem);
    if (it == all.end()) throw std::out_of_range("no views/shaders/glsl/" + stem + ".glsl");
    return it->second;
}

}  // namespace lc::views
