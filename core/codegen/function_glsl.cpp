#include "core/codegen/function_glsl.hpp"

#include "core/codegen/glsl_emitter.hpp"

#include <sstream>
#include <stdexcept>

namespace lc::codegen {

std::string functionGlsl(const std::string& signature, const std::vector<Expr>& result, const std::string& origin) {
    if (result.empty() || result.size() > 4)
        throw std::invalid_argument("codegen: a GLSL function returns 1 to 4 values, not " +
                                    std::to_string(result.size()));
    GlslEmitter emit;
    std::string value = result.size() == 1 ? "" : "vec" + std::to_string(result.size()) + "(";
    for (std::size_t i = 0; i < result.size(); ++i) value += (i ? ", " : "") + emit.name(result[i]);
    if (result.size() > 1) value += ")";
    std::ostringstream out;
    out << "// Generated from " << origin << ": do not edit.\n"
        << signature << "\n{\n"
        << emit.body() << "  return " << value << ";\n}\n";
    return out.str();
}

}  // namespace lc::codegen
