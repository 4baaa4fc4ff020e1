// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every views/shaders/glsl/*.glsl file, embedded at build time, by its file stem (e.g. "camera_direction"): the
// per-function GPU tests probe them one by one.
#include <map>
#include <string>

namespace lc::views {

const std::map<std::string, const char*>& glslSources();

// The text of glsl/<stem>.glsl; throws std::out_of_range naming an unknown stem.
std::string glslSource(const std::string& stem);

}  // namespace lc::views
