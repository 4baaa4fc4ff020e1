#pragma once
#include "app/cli_args.hpp"

namespace lc::cli {
int runRender(const Args& args);
int runTrace(const Args& args);
}  // namespace lc::cli
