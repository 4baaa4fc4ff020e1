// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include "app/cli/command_options.hpp"
#include "core/render/photo_scene.hpp"
#include "core/render/post_render.hpp"
#include "core/render/special_relativity.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_edits.hpp"
#include "readers/io/scene_reader.hpp"

#include <functional>

namespace lc::cli {
// Scene-reading options of this build (mesh files through VTK where available).
io::SceneReadOptions sceneReadOptions();
// The scene file, or a session's scene with its edits, as an editable document (animate sweeps
// edit it per frame); a session's notice goes to stderr.
io::EditableScene loadEditableScene(const RenderOptions& options);

// argv: the arguments after the command name (parsed by app/cli/command_options.hpp).
int runRender(const std::vector<std::string>& argv);
int runAnimate(const std::vector<std::string>& argv);
int runSweep(const std::vector<std::string>& argv);
int runTrace(const std::vector<std::string>& argv);
int runMetric(const std::vector<std::string>& argv);
int runImages(const std::vector<std::string>& argv);
int runShade(const std::vector<std::string>& argv);
int runDiagram(const std::vector<std::string>& argv);    // VTK builds only
int runFigure(const std::vector<std::string>& argv);     // VTK builds only
int runExport(const std::vector<std::string>& argv);     // VTK builds only
int runCurvature(const std::vector<std::string>& argv);  // VTK builds only

// The work of the commands on a scene already read, shared with the GUI (the same files for the
// same scene). Each writes atomically and throws naming the output on failure.
// `labels` are drawn into the image file only (the per-pixel data stays as traced).
// `report` (RenderReport::figures) goes into the --data file's header as "lightcone:report".
void writeRenderOutputs(const ColouredImage& image, const std::string& output, const std::string& data = "",
                        const std::vector<io::ImageLabel>& labels = {}, const std::vector<std::string>& report = {});
// For scenes with travellers (spheres on world lines by proper time): "NAME tau = T" beside each
// image of each traveller's centre, and the observer's time in the corner; empty otherwise.
// `ages`: lc::ageImages(scene), solved once by the caller, which also prints them.
std::vector<io::ImageLabel> ageLabels(const Scene& scene, const std::vector<AgeImage>& ages);
int writeDiagrams(const Scene& scene, const std::vector<std::string>& outputs, int windings, int rays = 24,
                  int size = 900,
                  DiagramKind kind = DiagramKind::RPhi);  // returns the number of image paths; VTK builds only
// The figure of a render (views/diagrams/image_figure.hpp) in each output's format; quantity
// "image", "redshift" or "emission-time". VTK builds only.
void writeFigures(const Scene& scene, const ColouredImage& image, const std::vector<std::string>& outputs,
                  const std::string& quantity = "image", int size = 700);
// What an export may write and how it reports: maxBytes (0: no limit) is checked against an
// estimate before the light paths are traced and against the files as they are made, so a
// refused export costs little and writes nothing; progress gets the fraction of files made.
struct ExportLimits {
    double maxBytes = 500e6;
    std::function<void(double)> progress;
};
void exportScene(const Scene& scene, const std::string& directory, int rays = 24,
                 const ExportLimits& limits = {});  // VTK builds only
// Which views/ shader renderer draws a scene (the GUI's egocentric image, render --gpu).
enum class ShaderPath { None, SpecialRelativity, BlackHole, Godel };
ShaderPath shaderPathFor(const Scene& scene);
// Linear RGB, row 0 on top; VTK builds only. Goedel: `photos` built beforehand with
// lc::photoSceneOptions(scene) (e.g. off the GUI thread) leave only the drawing to this call.
std::vector<float> renderShaderImage(const Scene& scene,
                                     std::shared_ptr<const std::vector<PhotoSceneObject>> photos = nullptr);
// The per-pixel data `render --data` wrote (EXR/TIFF) as a render result of `scene`; throws
// naming the file, the pixel and the channel that is missing, non-finite or foreign to the scene.
RenderResult readPixelData(const std::string& path, const Scene& scene);
// shade's post-rendering settings with their textures loaded (names as in scene files,
// relative to the scene's folder); throws naming --texture or --outside-texture.
PostRender postRenderFor(const ShadeOptions& options, const Scene& scene);
int renderWithShaders(const Scene& scene, const std::string& output, int orbitFrames,
                      bool polygonDistortion);  // VTK builds only
}  // namespace lc::cli
