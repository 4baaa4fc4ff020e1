// SPDX-License-Identifier: BSD-3-Clause
#include "core/scene/animation.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

namespace lc {

int AnimationPath::frames() const {
    std::vector<std::pair<const char*, int>> counts;
    if (properTime) counts.emplace_back("proper time", properTime->frames);
    if (panDegrees) counts.emplace_back("pan", panDegrees->frames);
    if (orbitDegrees) counts.emplace_back("orbit", orbitDegrees->frames);
    if (sweep) counts.emplace_back("sweep", sweep->values.frames);
    if (counts.empty() && still) return 1;
    if (counts.empty())
        throw std::invalid_argument(
            "animate needs a path: --proper-time, --pan, --orbit or --sweep (or an \"animation\" block in the scene)");
    for (const auto& [what, n] : counts)
        if (n != counts.front().second)
            throw std::invalid_argument(std::string("the ") + what + " has " + std::to_string(n) + " frames but the " +
                                        counts.front().first + " has " + std::to_string(counts.front().second) +
                                        ": paths given together need the same number of frames");
    return counts.front().second;
}

}  // namespace lc
