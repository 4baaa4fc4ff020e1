// SPDX-License-Identifier: BSD-3-Clause
#include "glsl_probe.hpp"

#include "offscreen_parts.hpp"
#include "read_back.hpp"
#include "lightcone_glsl_bit_encoding_extension.h"
#include "lightcone_glsl_probe_pixel.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkMapper.h>
#include <vtkShaderProgram.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkShaderProperty.h>
#include <vtkUniforms.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace lc::views {
namespace {

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

}  // namespace

std::vector<std::vector<float>> evaluateOnGpu(const GlslProbe& probe, const std::vector<std::array<float, 4>>& inputs) {
    const int n = static_cast<int>(inputs.size());
    if (n < 1 || n > 256) throw std::invalid_argument("evaluateOnGpu: 1 to 256 inputs");
    if (probe.outputs < 1 || probe.outputs > 512) throw std::invalid_argument("evaluateOnGpu: 1 to 512 outputs");
    const std::string outputs = std::to_string(probe.outputs);

    const vtkSmartPointer<vtkActor> actor = clipSpaceQuadActor();
    vtkShaderProperty* sp = actor->GetShaderProperty();
    sp->AddFragmentShaderReplacement("//VTK::System::Dec", true, lightcone_glsl_bit_encoding_extension, false);
    sp->AddFragmentShaderReplacement("//VTK::ValuePass::Dec", true,
                                     "//VTK::ValuePass::Dec\n" + probe.declarations,  // lcInputs: a custom uniform
                                     false);
    std::string pixel = replaceAll(lightcone_glsl_probe_pixel, "LC_PROBE_OUTPUTS", outputs);
    pixel = replaceAll(pixel, "LC_PROBE_BODY", probe.body);
    sp->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, pixel, false);
    std::vector<float> flat(4 * static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < inputs.size(); ++i) std::memcpy(&flat[4 * i], inputs[i].data(), 4 * sizeof(float));
    vtkUniforms* fs = sp->GetFragmentCustomUniforms();
    fs->SetUniform4fv("lcInputs", n, reinterpret_cast<const float(*)[4]>(flat.data()));
    for (const auto& [name, value] : probe.uniforms) {
        switch (value.size()) {
            case 1: fs->SetUniformf(name.c_str(), value[0]); break;
            case 2: fs->SetUniform2f(name.c_str(), value.data()); break;
            case 3: fs->SetUniform3f(name.c_str(), value.data()); break;
            case 4: fs->SetUniform4f(name.c_str(), value.data()); break;
            default: throw std::invalid_argument("evaluateOnGpu: uniform '" + name + "' needs 1 to 4 floats");
        }
    }
    for (const auto& [name, value] : probe.intUniforms) fs->SetUniformi(name.c_str(), value);

    const int width = 2 * probe.outputs;
    struct PlanckBinding {
        PlanckTexture* planck;
        vtkRenderWindow* window;
    } binding{probe.planck, nullptr};
    vtkNew<vtkCallbackCommand> binder;
    if (probe.planck) {
        probe.planck->setUniforms(fs, probe.planckToneMap);
        binder->SetClientData(&binding);
        binder->SetCallback([](vtkObject*, unsigned long, void* data, void* program) {
            auto* b = static_cast<PlanckBinding*>(data);
            b->planck->bind(b->window, static_cast<vtkShaderProgram*>(program));
        });
        actor->GetMapper()->AddObserver(vtkCommand::UpdateShaderEvent, binder);
    }
    // One window for every probe of the process: tests probe many small functions, and opening
    // and closing an X window per probe made Xvfb refuse connections after a dozen or so.
    static vtkSmartPointer<vtkRenderWindow> window;
    if (!window) window = offscreenWindow(width, n);
    vtkRenderer* renderer = rendererOf(window);
    binding.window = window;
    renderer->RemoveAllViewProps();
    renderer->AddActor(actor);
    window->SetSize(width, n);
    window->Render();
    const std::vector<unsigned char> rgb = readBackRgb(window, width, n, "evaluateOnGpu");
    renderer->RemoveAllViewProps();
    actor->ReleaseGraphicsResources(window);
    std::vector<std::vector<float>> out(inputs.size(), std::vector<float>(static_cast<std::size_t>(probe.outputs)));
    for (int row = 0; row < n; ++row)
        for (int q = 0; q < probe.outputs; ++q) {
            // readBackRgb puts row 0 at the top; the probe's input j is window row j from the bottom.
            const std::size_t base = 3 * (static_cast<std::size_t>(n - 1 - row) * width + 2 * q);
            const std::uint32_t lo = rgb[base] | (std::uint32_t(rgb[base + 1]) << 8);
            const std::uint32_t hi = rgb[base + 3] | (std::uint32_t(rgb[base + 4]) << 8);
            const std::uint32_t bits = lo | (hi << 16);
            if (rgb[base + 2] != 255 || rgb[base + 5] != 255)
                throw std::runtime_error(
                    "evaluateOnGpu: the probe drew nothing (the GLSL did not compile; see VTK's message)");
            std::memcpy(&out[static_cast<std::size_t>(row)][static_cast<std::size_t>(q)], &bits, 4);
        }
    return out;
}

}  // namespace lc::views
