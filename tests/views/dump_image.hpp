// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// With LIGHTCONE_TEST_DUMP=dir set, rendering tests write their images there as PPM for a look.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace lc::test {

inline void dump(const std::string& name, const std::vector<float>& rgb, int w, int h) {
    const char* dir = std::getenv("LIGHTCONE_TEST_DUMP");
    if (!dir) return;
    std::ofstream out(std::string(dir) + "/" + name + ".ppm", std::ios::binary);
    out << "P6\n" << w << " " << h << "\n255\n";
    for (float v : rgb)
        out.put(static_cast<char>(static_cast<unsigned char>(std::lround(255 * std::clamp(v, 0.0f, 1.0f)))));
}

}  // namespace lc::test
