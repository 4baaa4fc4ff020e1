// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `lightcone --version`: the program's version, the git commit it was built from, the build
// type and the versions of the libraries it was built with (VTK, Qt, OpenImageIO, Eigen, Boost,
// the compiler). Known at build time, so printing it loads nothing. The version and the commit
// alone: io::versionNumber(), io::buildCommit() (readers/io/provenance).
#include <string>

namespace lc::cli {

std::string versionText();  // several lines, the first "lightcone 0.1.0 (commit abc1234, Release)"

}  // namespace lc::cli
