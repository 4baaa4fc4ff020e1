// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/provenance.hpp"

#include "lightcone_build_info.hpp"  // configured by app/CMakeLists.txt
#include "lightcone_git_commit.hpp"  // written at every build (cmake/LightconeGitCommit.cmake)

namespace lc::io {

std::string softwareName() {
    return std::string("Lightcone ") + LIGHTCONE_VERSION_STRING + " (commit " + LIGHTCONE_GIT_COMMIT + ")";
}

}  // namespace lc::io
