// SPDX-License-Identifier: BSD-3-Clause
#include "core/codegen/function_glsl.hpp"

#include "core/codegen/glsl_emitter.hpp"

#include <sstream>
#include <stdexcept>

namespace lc::codegen {

std::string functionGlsl(const std::string& signature, const std::vector<Expr>& result, const std::string& origin) {
    GlslEmitter emit;
    const std::string value = emit.vector(result);
    std::ostringstream out;
    out << "// Generated from " << origin << ": do not edit.\n"
        << signature << "\n{\n"
        << emit.body() << "  return " << value << ";\n}\n";
    return out.str();
}

}  // namespace lc::codegen
