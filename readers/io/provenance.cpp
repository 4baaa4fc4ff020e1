// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/provenance.hpp"

#include "lightcone_build_info.hpp"  // configured by app/CMakeLists.txt
#include "lightcone_git_commit.hpp"  // written at every build (cmake/LightconeGitCommit.cmake)

namespace lc::io {

std::string versionNumber() { return LIGHTCONE_VERSION_STRING; }
std::string buildCommit() { return LIGHTCONE_GIT_COMMIT; }

std::string softwareName() { return "Lightcone " + versionNumber() + " (commit " + buildCommit() + ")"; }

}  // namespace lc::io
