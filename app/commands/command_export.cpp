// SPDX-License-Identifier: BSD-3-Clause
// `lightcone export`: the VTK filter outputs of a scene as files ParaView opens
// (.vtp polylines and surfaces, .vti Killing fields, .vtm photo-objects).
#include "app/commands/commands.hpp"
#include "app/commands/vtk_xml_bytes.hpp"
#include "app/cli/command_options.hpp"
#include "app/cli/progress_bar.hpp"
#include "app/commands/xml_text.hpp"
#include "core/input/number_text.hpp"
#include "readers/io/atomic_output.hpp"
#include "filters_from_scene.hpp"
#include "vtkLightconeGodelHorizonSource.h"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKerrHorizonSource.h"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconeMeshLoader.h"
#include "vtkLightconeNullGeodesicSource.h"
#include "vtkLightconePhotoObjectFilter.h"
#include "vtkLightconeWorldLineSource.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkCompositeDataSet.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLWriter.h>

#include <cstdio>
#include <filesystem>

namespace lc::cli {
namespace {
namespace fs = std::filesystem;

// One export: every file is made in memory and the folder is written all at once at the end
// (readers/io/atomic_output.hpp), so a failed export leaves an earlier one untouched.
class ExportFiles {
public:
    ExportFiles(double maxBytes, std::function<void(double)> progress, int expectedFiles)
        : maxBytes_(maxBytes), progress_(std::move(progress)), expected_(expectedFiles) {}
    void add(const std::string& name, std::string bytes) {
        bytes_ += static_cast<double>(bytes.size());
        files_.emplace_back(name, std::move(bytes));
        if (maxBytes_ > 0 && bytes_ > maxBytes_)
            throw std::runtime_error("the export passes --max-size " + megabytes(maxBytes_) + " with " +
                                     megabytes(bytes_) + " after " + name + " (" + std::to_string(files_.size()) +
                                     " files); nothing was written: fewer --rays, fewer windings, or a larger "
                                     "--max-size (0: no limit)");
        if (progress_) progress_(std::min(0.99, static_cast<double>(files_.size()) / std::max(1, expected_)));
    }
    static std::string megabytes(double bytes) { return input::significantDigits(bytes / 1e6, 4) + " MB"; }
    void addXml(vtkXMLWriter* writer, vtkDataObject* data, const std::string& name) {
        add(name, vtkXmlBytes(writer, data, name));
    }
    void addPolyData(vtkAlgorithm* source, int port, const std::string& name) {
        source->Update();
        vtkNew<vtkXMLPolyDataWriter> w;
        addXml(w, source->GetOutputDataObject(port), name);
    }
    // A .vtm as VTK lays it out: the index file beside a folder of the same base name holding
    // one .vtp per block (written here so the pieces never pass through temporary names).
    void addMultiBlock(vtkMultiBlockDataSet* blocks, const std::string& base) {
        std::string index =
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
            "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <vtkMultiBlockDataSet>\n";
        for (unsigned b = 0; b < blocks->GetNumberOfBlocks(); ++b) {
            const char* label =
                blocks->HasMetaData(b) ? blocks->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()) : nullptr;
            const std::string name = xmlEscaped(label ? label : "block_" + std::to_string(b));
            index += "    <DataSet index=\"" + std::to_string(b) + "\" name=\"" + name + "\"";
            if (vtkDataObject* block = blocks->GetBlock(b)) {
                const std::string piece = base + "/" + base + "_" + std::to_string(b) + ".vtp";
                vtkNew<vtkXMLPolyDataWriter> w;
                addXml(w, block, piece);
                index += " file=\"" + piece + "\"";
            }
            index += "/>\n";
        }
        index += "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
        add(base + ".vtm", index);
    }
    void commit(const fs::path& dir) {
        io::writeFolderAtomically(dir, files_);
        for (const auto& f : files_) std::printf("wrote %s\n", (dir / f.first).string().c_str());
    }

private:
    double maxBytes_;
    std::function<void(double)> progress_;
    int expected_;
    double bytes_ = 0;
    std::vector<std::pair<std::string, std::string>> files_;
};

// The export's fan (in the observer's horizontal plane) or cone (60 degrees) of rays.
void configureExportRays(vtkLightconeNullGeodesicSource* geo, int rays, bool fan) {
    geo->SetNumberOfRays(rays);
    if (fan) {
        geo->SetDirectionModeToFan();
    } else {
        geo->SetDirectionModeToCone();
        geo->SetConeAngle(60);
    }
}

// The light paths' size before they are traced: a fan and a cone drawn over eight loops of the
// axis (Goedel, 2 pi a of affine length each) measured, scaled to the loops the scene's windings
// draw (within 15 % at 100 windings). Other metrics draw a fixed length: no estimate needed.
void refuseLightPathsOverTheLimit(const Scene& scene, int rays, double maxBytes) {
    const double a = views::sceneGodelA(scene);
    if (!(maxBytes > 0) || !(a > 0)) return;
    // Eight loops: a ray's later loops take more bytes than its first (its points compress less).
    const double trialLength = 8 * 2 * kPi * a;
    double trialBytes = 0, full = 0;  // of the fan and the cone drawn over the trial length
    for (const bool fan : {true, false}) {
        vtkNew<vtkLightconeNullGeodesicSource> trial;
        views::configureNullGeodesics(trial, scene);
        configureExportRays(trial, rays, fan);
        full = trial->GetMaxAffine();
        if (full <= 2 * trialLength) return;
        trial->SetMaxAffine(trialLength);
        trial->Update();
        vtkNew<vtkXMLPolyDataWriter> w;
        trialBytes += static_cast<double>(vtkXmlBytes(w, trial->GetOutput(), "the trial light paths").size());
    }
    const double estimate = trialBytes * full / trialLength;
    if (estimate > maxBytes)
        throw std::runtime_error(
            "the export would write about " + ExportFiles::megabytes(estimate) + " of light paths alone (" +
            ExportFiles::megabytes(trialBytes / 8) + " a loop of the axis for the fan and the cone, " +
            std::to_string(scene.settings.windings + 1) + " loops for the scene's windings), over --max-size " +
            ExportFiles::megabytes(maxBytes) +
            "; nothing was traced or written: fewer --rays, fewer windings "
            "(render.windings), or a larger --max-size (0: no limit)");
}

}  // namespace

void exportScene(const Scene& scene, const std::string& directory, int rays, const ExportLimits& limits) {
    io::checkOutputFolder(directory, "-o");
    const fs::path dir = directory;
    const bool godel = views::sceneGodelA(scene) > 0;
    refuseLightPathsOverTheLimit(scene, rays, limits.maxBytes);
    const int objects = static_cast<int>(scene.spheres.size() + scene.meshes.size());
    ExportFiles files(limits.maxBytes, limits.progress,
                      2 + (scene.spacetime->kerrNewmanParameters() ? 1 : 0) + (godel ? 4 : 0) + 2 * objects);

    // Null geodesics from the observer: a fan in the observer's horizontal plane and a cone.
    for (const char* mode : {"fan", "cone"}) {
        vtkNew<vtkLightconeNullGeodesicSource> geo;
        views::configureNullGeodesics(geo, scene);
        configureExportRays(geo, rays, std::string(mode) == "fan");
        files.addPolyData(geo, 0, std::string("geodesics_") + mode + ".vtp");
    }

    if (const auto hole = scene.spacetime->kerrNewmanParameters()) {
        // A black hole's horizons and ergosurfaces, inner ones too, in the tracer's chart.
        vtkNew<vtkLightconeKerrHorizonSource> horizon;
        horizon->SetMass(hole->mass);
        horizon->SetSpin(hole->spin);
        horizon->SetCharge(hole->charge);
        horizon->GenerateInnerSurfacesOn();
        files.addPolyData(horizon, 0, "horizon.vtp");
    }
    if (godel) {
        vtkNew<vtkLightconeGodelHorizonSource> horizon;
        views::configureHorizon(horizon, scene);
        files.addPolyData(horizon, 0, "horizon.vtp");
        files.addPolyData(horizon, 1, "light_cone.vtp");

        vtkNew<vtkLightconeKillingFieldSource> killing;
        views::configureKillingFields(killing, scene);
        killing->Update();
        vtkNew<vtkXMLImageDataWriter> kw;
        files.addXml(kw, killing->GetOutputDataObject(0), "killing_fields.vti");

        vtkNew<vtkLightconeIsometryOrbitSource> orbits;
        views::configureOrbits(orbits, scene);
        orbits->SetCoefficients(0, 0, 0, 1, 0);  // xi_4: radial through the axis at phi = pi/2
        files.addPolyData(orbits, 0, "orbits_xi4.vtp");
    }

    // Objects: photo-objects (Goedel: every image layer; flat: the apparent shape) and world lines.
    std::size_t index = 0;
    auto exportObject = [&](const std::string& name, const Vec4& centre, const Motion& motion, vtkPolyData* mesh) {
        const std::string base = std::to_string(index++) + "_" + io::sanitizeFileName(name);
        vtkNew<vtkLightconePhotoObjectFilter> photo;
        if (views::configurePhotoObject(photo, scene, centre, motion)) {
            photo->SetInputData(mesh);
            photo->Update();
            files.addMultiBlock(photo->GetOutput(), "photo_" + base);
        }
        vtkNew<vtkLightconeWorldLineSource> line;
        if (views::configureWorldLine(line, scene, centre, motion))
            files.addPolyData(line, 0, "world_line_" + base + ".vtp");
    };
    for (const auto& s : scene.spheres) {
        vtkNew<vtkSphereSource> sphere;
        views::configureSphereMesh(sphere, s.radius);
        sphere->Update();
        exportObject(s.name, s.centre, s.motion, sphere->GetOutput());
    }
    for (const auto& m : scene.meshes) {
        vtkNew<vtkPolyData> pd;
        io::meshToPolyData(m, pd);
        exportObject(m.name, m.centre, m.motion, pd);
    }
    if (limits.progress) limits.progress(1);
    files.commit(dir);
}

int runExport(const std::vector<std::string>& argv) {
    const ExportOptions o = parseExportOptions(argv);
    io::checkOutputFolder(o.directory, "-o");
    ProgressBar bar(!o.quiet, "files ");
    ExportLimits limits;
    limits.maxBytes = o.maxMegabytes * 1e6;
    limits.progress = [&bar](double f) { bar(f); };
    exportScene(io::readScene(o.scene, sceneReadOptions()), o.directory, o.rays, limits);
    return 0;
}

}  // namespace lc::cli
