// SPDX-License-Identifier: BSD-3-Clause
// `lightcone figure`: a CPU render of a scene as a figure for a paper (views/diagrams/image_figure.hpp).
#include "app/cli/command_options.hpp"
#include "app/cli/progress_bar.hpp"
#include "app/commands/commands.hpp"
#include "image_figure.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"
#include "readers/io/scene_reader.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <unistd.h>

namespace lc::cli {

void writeFigures(const Scene& scene, const ColouredImage& image, const std::vector<std::string>& outputs,
                  const std::string& quantity, int size) {
    const auto q = views::figureQuantityNamed(quantity);
    if (!q)
        throw std::invalid_argument("option --quantity: unknown '" + quantity + "' (image, redshift, emission-time)");
    views::ImageFigure figure(scene, image, *q, size);
    // Every format is drawn before any file is replaced.
    io::OutputSet files;
    for (const auto& out : outputs) files.add(out, figure.encode(io::lowerCaseExtension(out)), "-o");
    files.commit();
}

int runFigure(const std::vector<std::string>& argv) {
    const FigureOptions o = parseFigureOptions(argv);
    for (const auto& out : o.outputs) io::checkOutputPath(out, {".svg", ".pdf", ".png"}, "-o");
    if (!std::getenv("DISPLAY"))
        throw std::runtime_error("VTK draws through GLX and needs an X display (hint: run under xvfb-run -a)");
    if (!views::figureQuantityNamed(o.quantity))
        throw std::invalid_argument("option --quantity: unknown '" + o.quantity + "'");
    const Scene scene = io::readScene(o.scene, sceneReadOptions());
    ProgressBar bar(::isatty(2) != 0);  // a terminal sees the render's progress; logs stay clean
    const ColouredImage image = renderColouredImage(scene, [&bar](double f) { bar(f); });
    writeFigures(scene, image, o.outputs, o.quantity, o.size);
    for (const auto& out : o.outputs) std::printf("wrote %s (%s)\n", out.c_str(), o.quantity.c_str());
    return 0;
}

}  // namespace lc::cli
