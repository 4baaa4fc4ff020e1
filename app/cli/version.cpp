// SPDX-License-Identifier: BSD-3-Clause
#include "app/cli/version.hpp"

#include "lightcone_build_info.hpp"
#include "readers/io/provenance.hpp"

#include <Eigen/Core>
#include <boost/version.hpp>

namespace lc::cli {

std::string versionText() {
    const auto num = [](int v) { return std::to_string(v); };
    std::string text = "lightcone " + io::versionNumber() + " (commit " + io::buildCommit() + ", " +
                       LIGHTCONE_BUILD_TYPE + " build)\n";
    text += std::string("built with VTK ") + LIGHTCONE_VTK_VERSION + ", Qt " + LIGHTCONE_QT_VERSION + ", OpenImageIO " +
            LIGHTCONE_OIIO_VERSION + ", Eigen " + num(EIGEN_WORLD_VERSION) + "." + num(EIGEN_MAJOR_VERSION) + "." +
            num(EIGEN_MINOR_VERSION) + ", Boost " + num(BOOST_VERSION / 100000) + "." +
            num(BOOST_VERSION / 100 % 1000) + "." + num(BOOST_VERSION % 100) + ", " +
#if defined(__clang__)
            "clang " + __clang_version__
#else
            "GCC " + __VERSION__
#endif
            + "\n";
    text += "licence BSD-3-Clause (LICENSE); docs: README.md, docs/CLI.md\n";
    return text;
}

}  // namespace lc::cli
