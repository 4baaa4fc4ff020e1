// SPDX-License-Identifier: BSD-3-Clause
#include "offscreen_parts.hpp"

#include "lightcone_glsl_clip_quad_vertex.h"

#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkCellArray.h>
#include <vtkCullerCollection.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPlaneSource.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkImageData.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkTexture.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace lc::views {

void updateOrThrow(std::initializer_list<vtkAlgorithm*> chain, const std::string& what) {
    if (chain.size() == 0) return;
    std::string error;
    vtkNew<vtkCallbackCommand> onError;
    onError->SetClientData(&error);
    onError->SetCallback([](vtkObject*, unsigned long, void* text, void* message) {
        auto& e = *static_cast<std::string*>(text);
        if (e.empty() && message) e = static_cast<const char*>(message);
    });
    // The algorithms' own messages, and their executives' "returned failure" after them.
    std::vector<std::pair<vtkObject*, unsigned long>> observers;
    for (vtkAlgorithm* a : chain) {
        observers.emplace_back(a, a->AddObserver(vtkCommand::ErrorEvent, onError));
        observers.emplace_back(a->GetExecutive(), a->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, onError));
    }
    const auto removeObservers = [&observers] {
        for (const auto& [object, tag] : observers) object->RemoveObserver(tag);
    };
    try {
        (*(chain.end() - 1))->Update();
    } catch (...) {
        removeObservers();
        throw;
    }
    removeObservers();
    if (error.empty()) return;
    // VTK counts a failed execution as done: without this the next Update() would not run again
    // and the failure would pass unseen.
    for (vtkAlgorithm* a : chain) a->Modified();
    throw std::runtime_error(what + ": " + error);
}

vtkSmartPointer<vtkActor> clipSpaceQuadActor(vtkOpenGLPolyDataMapper* given) {
    vtkSmartPointer<vtkOpenGLPolyDataMapper> mapper = given;
    if (!mapper) mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
    // Clip space covered by one quad from a standard source (its points are clip-space positions,
    // its texture coordinates make a mapper declare the actor's texture sampler).
    vtkNew<vtkPlaneSource> quad;
    quad->SetOrigin(-1, -1, 0);
    quad->SetPoint1(1, -1, 0);
    quad->SetPoint2(-1, 1, 0);
    mapper->SetInputConnection(quad->GetOutputPort());
    mapper->ScalarVisibilityOff();
    mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->GetShaderProperty()->AddVertexShaderReplacement("//VTK::PositionVC::Impl", true,
                                                           lightcone_glsl_clip_quad_vertex, false);
    return actor;
}

vtkSmartPointer<vtkRenderWindow> offscreenWindow(int width, int height) {
    vtkNew<vtkRenderer> renderer;
    renderer->GetCullers()->RemoveAllItems();
    renderer->SetUseDepthPeeling(false);
    renderer->SetUseFXAA(false);
    renderer->SetBackground(0, 0, 0);
    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(width, height);
    window->AddRenderer(renderer);
    return window;
}

vtkRenderer* rendererOf(vtkRenderWindow* window) { return window->GetRenderers()->GetFirstRenderer(); }

vtkSmartPointer<vtkFloatArray> floatArray(const char* name, int components, vtkIdType tuples) {
    auto a = vtkSmartPointer<vtkFloatArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(tuples);
    return a;
}

void putVec3(vtkFloatArray* array, vtkIdType i, const Vec3& v) {
    float* p = array->GetPointer(3 * i);
    p[0] = float(v.x()), p[1] = float(v.y()), p[2] = float(v.z());
}

namespace {

// w x h samples of `tex` (or `fallback` everywhere) as 8-bit RGB, into rows `stride` texels apart.
void sampleTexels(unsigned char* p, int stride, int w, int h, const TexturePtr& tex, const Vec3& fallback) {
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const Vec3 c = tex ? tex->sample((i + 0.5) / w, (j + 0.5) / h) : fallback;
            for (int k = 0; k < 3; ++k)
                p[3 * (static_cast<std::size_t>(j) * stride + i) + k] =
                    static_cast<unsigned char>(std::lround(255.0 * std::clamp(c(k), 0.0, 1.0)));
        }
}

vtkSmartPointer<vtkTexture> repeatingTexture(vtkImageData* data, bool interpolate) {
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(data);
    texture->SetInterpolate(interpolate);
    texture->RepeatOn();  // u runs past 1 on triangles across the texture seam, and the sky wraps
    texture->MipmapOff();
    return texture;
}

}  // namespace

vtkSmartPointer<vtkTexture> bakeTexture(const TexturePtr& tex, const Vec3& fallback, int n) {
    const auto* image = dynamic_cast<const ImageTexture*>(tex.get());
    const int w = image ? image->width() : 2 * n, h = image ? image->height() : n;
    vtkNew<vtkImageData> data;
    data->SetDimensions(w, h, 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    sampleTexels(static_cast<unsigned char*>(data->GetScalarPointer()), w, w, h, tex, fallback);
    return repeatingTexture(data, image != nullptr);
}

vtkSmartPointer<vtkTexture> bakeSkies(const TexturePtr& sky, const TexturePtr& otherSky, const Vec3& fallback, int n) {
    const int w = 2 * n, h = n;
    vtkNew<vtkImageData> data;
    data->SetDimensions(2 * w, h, 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* p = static_cast<unsigned char*>(data->GetScalarPointer());
    sampleTexels(p, 2 * w, w, h, sky, fallback);
    sampleTexels(p + 3 * w, 2 * w, w, h, otherSky, fallback);
    return repeatingTexture(data, false);  // nearest: the two halves must not bleed into each other
}

}  // namespace lc::views
