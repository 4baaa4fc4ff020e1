// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconePostRenderMapper.h"

#include "core_formula_glsl.hpp"
#include "planck_texture.hpp"
#include "lightcone_glsl_blackbody_light.h"
#include "lightcone_glsl_disk_colour.h"
#include "lightcone_glsl_planck_uniforms.h"
#include "lightcone_glsl_post_render_dec.h"
#include "lightcone_glsl_post_render_pixel.h"
#include "lightcone_glsl_texture_atlas.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include <algorithm>
#include <map>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconePostRenderMapper);

namespace {

// The GL limit the atlas must fit (llvmpipe and desktop GPUs: at least 16384).
constexpr int kMaxAtlasSide = 16384;

// A texture as float RGB texels: an image keeps its own (sampled bilinearly, as on the CPU); a
// checker is one texel per cell and a solid colour one texel (sampled nearest: exact).
struct BakedTexture {
    int width = 1, height = 1;
    bool linear = false;
    std::vector<float> rgb;
};

BakedTexture bake(const lc::Texture& texture) {
    BakedTexture b;
    if (const lc::LightMap* light = texture.lightMap()) {  // a star sky: (b, b T, 0), as lc::LightMap::at blends
        b.width = light->width;
        b.height = light->height;
        b.linear = true;
        b.rgb.resize(3 * static_cast<std::size_t>(b.width) * b.height, 0.0f);
        for (std::size_t k = 0; k < light->texels.size() / 2; ++k) {
            b.rgb[3 * k] = light->texels[2 * k];
            b.rgb[3 * k + 1] = light->texels[2 * k + 1];
        }
        return b;
    }
    if (const auto* image = dynamic_cast<const lc::ImageTexture*>(&texture)) {
        b.width = image->width();
        b.height = image->height();
        b.linear = true;
        b.rgb = image->texels();
        return b;
    }
    if (const auto* checker = dynamic_cast<const lc::CheckerTexture*>(&texture)) {
        b.width = checker->cellsU();
        b.height = checker->cellsV();
    } else if (!dynamic_cast<const lc::SolidTexture*>(&texture)) {
        b.width = 1024;  // another procedural texture: sampled at texel centres
        b.height = 512;
    }
    b.rgb.resize(3 * static_cast<std::size_t>(b.width) * b.height);
    for (int j = 0; j < b.height; ++j)
        for (int i = 0; i < b.width; ++i) {
            const lc::Vec3 c = texture.sample((i + 0.5) / b.width, (j + 0.5) / b.height);
            for (int k = 0; k < 3; ++k) b.rgb[3 * (static_cast<std::size_t>(j) * b.width + i) + k] = float(c(k));
        }
    return b;
}

vtkSmartPointer<vtkTextureObject> floatTexture(vtkOpenGLRenderWindow* window, int width, int height, int components,
                                               const float* data, const char* what) {
    auto t = vtkSmartPointer<vtkTextureObject>::New();
    t->SetContext(window);
    t->SetMinificationFilter(vtkTextureObject::Nearest);
    t->SetMagnificationFilter(vtkTextureObject::Nearest);
    t->SetWrapS(vtkTextureObject::ClampToEdge);
    t->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!t->Create2DFromRaw(static_cast<unsigned>(width), static_cast<unsigned>(height), components, VTK_FLOAT,
                            const_cast<float*>(data)))
        throw std::runtime_error(std::string("vtkLightconePostRenderMapper: cannot create the ") + what + " texture");
    return t;
}

void bindTexture(vtkShaderProgram* program, vtkTextureObject* texture, const char* uniform) {
    texture->Activate();
    program->SetUniformi(uniform, texture->GetTextureUnit());
}

}  // namespace

vtkLightconePostRenderMapper::vtkLightconePostRenderMapper()
    : Planck(std::make_unique<lc::views::PlanckTexture>(lc::kShadeMinTemperature, lc::kShadeMaxTemperature, 4096)) {
    this->ScalarVisibilityOff();
}
vtkLightconePostRenderMapper::~vtkLightconePostRenderMapper() = default;

void vtkLightconePostRenderMapper::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Image: " << this->Width << " x " << this->Height << "\n"
       << indent << "Objects: " << lc::objectCount(this->Scene) << "\n"
       << indent << "Atlas: " << this->AtlasWidth << " x " << this->AtlasHeight << " texels, "
       << this->UploadedTextures.size() << " textures\n"
       << indent << "UvOffset: " << this->Post.uOffset << ", " << this->Post.vOffset << "\n"
       << indent << "UvScale: " << this->Post.uScale << ", " << this->Post.vScale << "\n"
       << indent << "Temperature: " << this->Post.temperature.value_or(0) << "\n"
       << indent << "TimeWindow: "
       << (this->Post.timeWindow
               ? std::to_string(this->Post.timeWindow->first) + " to " + std::to_string(this->Post.timeWindow->second)
               : std::string("(none)"))
       << "\n"
       << indent << "BlinkPeriod: " << this->Post.blinkPeriod << "\n";
}

void vtkLightconePostRenderMapper::SetScene(const lc::Scene& scene) {
    this->Scene = scene;
    this->SceneChanged = true;
    this->Modified();
}

void vtkLightconePostRenderMapper::SetPixelData(const lc::RenderResult& data) {
    const std::size_t n = static_cast<std::size_t>(data.width) * data.height;
    if (data.width <= 0 || data.height <= 0 || data.pixels.size() != n)
        throw std::invalid_argument("vtkLightconePostRenderMapper: pixel data of " +
                                    std::to_string(data.pixels.size()) + " records for a " +
                                    std::to_string(data.width) + " x " + std::to_string(data.height) + " image");
    const std::size_t objects = lc::objectCount(this->Scene);
    this->PixelA.resize(4 * n);
    this->PixelB.resize(4 * n);
    this->PixelC.resize(4 * n);
    for (std::size_t k = 0; k < n; ++k) {
        const lc::PixelRecord& p = data.pixels[k];
        if (p.kind == lc::PixelRecord::Object && (p.object < 0 || static_cast<std::size_t>(p.object) >= objects))
            throw std::invalid_argument("vtkLightconePostRenderMapper: pixel " + std::to_string(k) + " shows object " +
                                        std::to_string(p.object) + "; the scene has " + std::to_string(objects));
        // The far side's sky of a two-ended metric is kind 6 here (post_render_pixel.glsl).
        const bool otherEnd = p.kind == lc::PixelRecord::Sky && p.end;
        const float a[4] = {otherEnd ? 6.f : float(p.kind), float(p.object), p.u, p.v};
        const float b[4] = {p.frequencyRatio, p.emissionTime, p.affine, 0.0f};
        if (p.kind == lc::PixelRecord::Disk &&
            (p.object < 0 || static_cast<std::size_t>(p.object) >= this->Scene.disks.size()))
            throw std::invalid_argument("vtkLightconePostRenderMapper: pixel " + std::to_string(k) + " shows disk " +
                                        std::to_string(p.object) + "; the scene has " +
                                        std::to_string(this->Scene.disks.size()));
        const bool disk = p.kind == lc::PixelRecord::Disk;  // its light is unused: the intensity instead
        const float c[4] = {disk ? p.intensity : p.light[0], disk ? 0.0f : p.light[1], disk ? 0.0f : p.light[2], 0.0f};
        std::copy(a, a + 4, &this->PixelA[4 * k]);
        std::copy(b, b + 4, &this->PixelB[4 * k]);
        std::copy(c, c + 4, &this->PixelC[4 * k]);
    }
    this->Width = data.width;
    this->Height = data.height;
    this->PixelsChanged = true;
    this->Modified();
}

// Uniforms (and, if the textures changed, the atlas) only: Modified() would make VTK rebuild the
// shader program at the next draw, which costs 0.1 s a frame on llvmpipe.
void vtkLightconePostRenderMapper::SetPostRender(const lc::PostRender& post) { this->Post = post; }

// Per object (spheres, then meshes) the texture it shows: the chosen one, or its own.
std::vector<lc::TexturePtr> vtkLightconePostRenderMapper::ChosenTextures() const {
    std::vector<lc::TexturePtr> chosen(lc::objectCount(this->Scene));
    for (std::size_t k = 0; k < chosen.size(); ++k) chosen[k] = lc::shownTexture(this->Scene, this->Post, k);
    return chosen;
}

// Every texture a pixel can show: per object the one it shows and its night texture, the second
// texture of the time window, the sky. Deduplicated by identity.
std::vector<lc::TexturePtr> vtkLightconePostRenderMapper::ShownTextures() const {
    std::vector<lc::TexturePtr> shown;
    auto add = [&shown](const lc::TexturePtr& t) {
        if (t && std::find(shown.begin(), shown.end(), t) == shown.end()) shown.push_back(t);
    };
    for (const auto& t : this->ChosenTextures()) add(t);
    for (const auto& s : this->Scene.spheres) add(s.nightTexture);
    add(this->Post.outsideTexture);
    add(this->Scene.sky);
    add(this->Scene.otherSky);
    for (const auto& d : this->Scene.disks) add(d.texture);
    return shown;
}

void vtkLightconePostRenderMapper::Upload(vtkRenderWindow* renderWindow) {
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderWindow);
    if (!window) throw std::runtime_error("vtkLightconePostRenderMapper: not an OpenGL render window");
    if (this->PixelsChanged || !this->PixelTextureA) {
        if (this->Width > kMaxAtlasSide || this->Height > kMaxAtlasSide)
            throw std::invalid_argument("vtkLightconePostRenderMapper: a " + std::to_string(this->Width) + " x " +
                                        std::to_string(this->Height) + " image exceeds the GL texture limit " +
                                        std::to_string(kMaxAtlasSide));
        this->PixelTextureA = floatTexture(window, this->Width, this->Height, 4, this->PixelA.data(), "pixel data");
        this->PixelTextureB = floatTexture(window, this->Width, this->Height, 4, this->PixelB.data(), "pixel data");
        this->PixelTextureC = floatTexture(window, this->Width, this->Height, 4, this->PixelC.data(), "light");
        this->PixelsChanged = false;
    }
    const std::vector<lc::TexturePtr> shown = this->ShownTextures();
    const bool atlasChanged = !this->AtlasTexture || shown != this->UploadedTextures;
    if (atlasChanged) {
        std::vector<BakedTexture> baked;
        int width = 1, height = 0;
        for (const auto& t : shown) {
            baked.push_back(bake(*t));
            width = std::max(width, baked.back().width);
            height += baked.back().height;
        }
        height = std::max(height, 1);
        if (width > kMaxAtlasSide || height > kMaxAtlasSide)
            throw std::invalid_argument("vtkLightconePostRenderMapper: the scene's textures need a " +
                                        std::to_string(width) + " x " + std::to_string(height) +
                                        " texel atlas; the GL limit is " + std::to_string(kMaxAtlasSide) +
                                        " (use smaller or fewer image textures)");
        std::vector<float> atlas(3 * static_cast<std::size_t>(width) * height, 0.0f);
        std::vector<float> entries(4 * std::max<std::size_t>(shown.size(), 1), 0.0f);
        int row = 0;
        for (std::size_t e = 0; e < baked.size(); ++e) {
            const BakedTexture& b = baked[e];
            for (int j = 0; j < b.height; ++j)
                std::copy_n(&b.rgb[3 * static_cast<std::size_t>(j) * b.width], 3 * b.width,
                            &atlas[3 * static_cast<std::size_t>(row + j) * width]);
            const float entry[4] = {float(row), float(b.width), float(b.height), b.linear ? 1.0f : 0.0f};
            std::copy(entry, entry + 4, &entries[4 * e]);
            row += b.height;
        }
        this->AtlasTexture = floatTexture(window, width, height, 3, atlas.data(), "texture atlas");
        this->EntryTexture =
            floatTexture(window, static_cast<int>(entries.size() / 4), 1, 4, entries.data(), "atlas entry");
        this->AtlasWidth = width;
        this->AtlasHeight = height;
        this->UploadedTextures = shown;
    }
    // Per object: its texture's entry, its night texture's, its temperature (again only when those change).
    auto entryOf = [&shown](const lc::TexturePtr& t) {
        const auto it = std::find(shown.begin(), shown.end(), t);
        return t && it != shown.end() ? static_cast<int>(it - shown.begin()) : -1;
    };
    const std::vector<lc::TexturePtr> chosen = this->ChosenTextures();
    if (atlasChanged || this->SceneChanged || chosen != this->TableTextures || !this->ObjectTexture) {
        const std::size_t objects = chosen.size();
        std::vector<float> table(4 * std::max<std::size_t>(objects, 1), -1.0f);
        for (std::size_t k = 0; k < objects; ++k) {
            const float row[4] = {float(entryOf(chosen[k])), float(entryOf(lc::objectNightTexture(this->Scene, k))),
                                  float(lc::objectTemperature(this->Scene, k)), 0.0f};
            std::copy(row, row + 4, &table[4 * k]);
        }
        this->ObjectTexture =
            floatTexture(window, static_cast<int>(table.size() / 4), 1, 4, table.data(), "object table");
        this->TableTextures = chosen;
        this->SceneChanged = false;
    }
    this->SkyEntry = entryOf(this->Scene.sky);
    this->OtherSkyEntry = entryOf(this->Scene.otherSky);
    this->DiskEntry = this->Scene.disks.empty() ? -1 : entryOf(this->Scene.disks.front().texture);
    this->OutsideEntry = entryOf(this->Post.outsideTexture);
}

void vtkLightconePostRenderMapper::ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                                                       vtkActor* act) {
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    const std::string declarations =
        std::string(lightcone_glsl_post_render_dec) + lc::views::textureSampleGlsl() + lightcone_glsl_texture_atlas +
        lightcone_glsl_planck_uniforms + lc::views::planckLookupGlsl() + lc::views::srgbDecodeGlsl() +
        lc::views::dayNightGlsl() + lc::views::postRenderGlsl() + lightcone_glsl_blackbody_light +
        lc::views::diskGlsl() + lightcone_glsl_disk_colour;
    vtkShaderProgram::Substitute(fs, "//VTK::ValuePass::Dec", declarations, false);
    vtkShaderProgram::Substitute(fs, "//VTK::TCoord::Impl", lightcone_glsl_post_render_pixel, false);
    shaders[vtkShader::Fragment]->SetSource(fs);
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

void vtkLightconePostRenderMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
    vtkShaderProgram* p = cellBO.Program;
    if (!p) return;
    this->Upload(ren->GetRenderWindow());
    bindTexture(p, this->PixelTextureA, "lcPixelA");
    bindTexture(p, this->PixelTextureB, "lcPixelB");
    bindTexture(p, this->PixelTextureC, "lcPixelC");
    bindTexture(p, this->AtlasTexture, "lcAtlas");
    bindTexture(p, this->EntryTexture, "lcEntries");
    bindTexture(p, this->ObjectTexture, "lcObjects");
    this->Planck->bind(ren->GetRenderWindow(), p, "lcPlanck");
    this->Planck->setUniforms(p, lc::colour::ToneMap::ColourOnly);  // the tone map of lc::shadePixels
    const lc::PostRender& post = this->Post;
    const float background[3] = {float(this->Scene.background(0)), float(this->Scene.background(1)),
                                 float(this->Scene.background(2))};
    p->SetUniformi("lcHeight", this->Height);
    p->SetUniform3f("lcBackground", background);
    p->SetUniformi("lcSkyEntry", this->SkyEntry);
    p->SetUniformi("lcOtherSkyEntry", this->OtherSkyEntry);
    p->SetUniformf("lcSkyTemperature", float(this->Scene.skyTemperature.value_or(0.0)));   // 0: the texture
    p->SetUniformi("lcSkyStars", this->Scene.sky && this->Scene.sky->lightMap() ? 1 : 0);  // its entry is (b, b T)
    const lc::DiskObject* disk = this->Scene.disks.empty() ? nullptr : &this->Scene.disks.front();
    p->SetUniformi("lcDiskEmission", disk ? static_cast<int>(disk->emission) : 0);
    p->SetUniformf("lcDiskTemperature", float(disk ? disk->temperature : 0.0));
    p->SetUniformi("lcDiskEntry", this->DiskEntry);
    p->SetUniformi("lcOutsideEntry", this->OutsideEntry);
    p->SetUniformi("lcWindowOn", post.timeWindow ? 1 : 0);
    const float window[2] = {float(post.timeWindow ? post.timeWindow->first : 0),
                             float(post.timeWindow ? post.timeWindow->second : 0)};
    p->SetUniform2f("lcWindow", window);
    const float blink[4] = {float(post.blinkPeriod), float(post.blinkDuty), float(post.blinkPhase),
                            float(post.blinkOffLevel)};
    p->SetUniform4f("lcBlink", blink);
    const float offset[2] = {float(post.uOffset), float(post.vOffset)},
                scale[2] = {float(post.uScale), float(post.vScale)};
    p->SetUniform2f("lcUvOffset", offset);
    p->SetUniform2f("lcUvScale", scale);
    p->SetUniformf("lcTemperature", float(post.temperature.value_or(0.0)));
    p->SetUniformi("lcLit", this->Scene.lights.empty() ? 0 : 1);
    p->SetUniformf("lcAmbient", float(lc::kAmbientLight));
}

void vtkLightconePostRenderMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
    for (vtkTextureObject* t : {this->PixelTextureA.Get(), this->PixelTextureB.Get(), this->PixelTextureC.Get(),
                                this->AtlasTexture.Get(), this->EntryTexture.Get(), this->ObjectTexture.Get()})
        if (t) t->Deactivate();
    this->Planck->deactivate();
    this->Superclass::RenderPieceFinish(ren, act);
}

void vtkLightconePostRenderMapper::ReleaseGraphicsResources(vtkWindow* window) {
    for (auto* t : {&this->PixelTextureA, &this->PixelTextureB, &this->PixelTextureC, &this->AtlasTexture,
                    &this->EntryTexture, &this->ObjectTexture}) {
        if (*t) (*t)->ReleaseGraphicsResources(window);
        *t = nullptr;
    }
    this->UploadedTextures.clear();
    this->TableTextures.clear();
    this->PixelsChanged = true;
    this->Planck->release(vtkRenderWindow::SafeDownCast(window));
    this->Superclass::ReleaseGraphicsResources(window);
}
