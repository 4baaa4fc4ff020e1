#pragma once
#include "app/cli_args.hpp"

namespace lc::cli {
int runRender(const Args& args);
int runTrace(const Args& args);
int runImages(const Args& args);
int runDiagram(const Args& args);  // VTK builds only
}  // namespace lc::cli
