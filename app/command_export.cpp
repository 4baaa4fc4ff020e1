// `lightcone export`: the VTK filter outputs of a scene as files ParaView opens
// (.vtp polylines and surfaces, .vti Killing fields, .vtm photo-objects).
#include "app/commands.hpp"
#include "app/xml_text.hpp"
#include "readers/io/atomic_output.hpp"
#include "core/metrics/godel.hpp"
#include "vtkLightconeGodelHorizonSource.h"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconeMeshLoader.h"
#include "vtkLightconeNullGeodesicSource.h"
#include "vtkLightconePhotoObjectFilter.h"
#include "vtkLightconeWorldLineSource.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkPoints.h>
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
    void add(const std::string& name, std::string bytes) { files_.emplace_back(name, std::move(bytes)); }
    // VTK's XML writers, to a string.
    void addXml(vtkXMLWriter* writer, vtkDataObject* data, const std::string& name) {
        writer->SetInputData(data);
        writer->SetDataModeToBinary();
        writer->WriteToOutputStringOn();
        if (writer->Write() != 1) throw std::runtime_error("cannot encode '" + name + "' (VTK writer error)");
        add(name, writer->GetOutputString());
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
    std::vector<std::pair<std::string, std::string>> files_;
};

}  // namespace

void exportScene(const Scene& scene, const std::string& directory, int rays) {
    io::checkOutputFolder(directory, "-o");
    const fs::path dir = directory;
    ExportFiles files;
    const Vec4& obs = scene.observer;
    const auto* godel = dynamic_cast<const GodelCartesian*>(scene.spacetime.get());

    // Null geodesics from the observer: a fan in the observer's horizontal plane and a cone.
    for (const char* mode : {"fan", "cone"}) {
        vtkNew<vtkLightconeNullGeodesicSource> geo;
        geo->SetSpacetime(scene.spacetime);
        geo->SetObserver(obs(0), obs(1), obs(2), obs(3));
        geo->SetNumberOfRays(rays);
        if (std::string(mode) == "fan")
            geo->SetDirectionModeToFan();
        else {
            geo->SetDirectionModeToCone();
            geo->SetConeAngle(60);
        }
        geo->SetStepper("dopri5");
        geo->SetTolerance(1e-10);
        geo->SetMaxAffine(godel ? (scene.settings.windings + 1) * 2 * kPi * godel->a() : 60.0);
        files.addPolyData(geo, 0, std::string("geodesics_") + mode + ".vtp");
    }

    if (godel) {
        const double a = godel->a();
        vtkNew<vtkLightconeGodelHorizonSource> horizon;
        horizon->SetGodelA(a);
        horizon->SetObserver(obs(0), obs(1), obs(2), obs(3));
        horizon->SetZRange(obs(3) - 2 * a, obs(3) + 2 * a);
        horizon->GenerateLightConeOn();
        horizon->SetLightConeAffineLength(2 * kPi * a);
        files.addPolyData(horizon, 0, "horizon.vtp");
        files.addPolyData(horizon, 1, "light_cone.vtp");

        vtkNew<vtkLightconeKillingFieldSource> killing;
        killing->SetGodelA(a);
        killing->SetTime(obs(0));
        killing->SetDimensions(25, 25, 5);
        killing->SetOrigin(obs(1) - 3 * a, obs(2) - 3 * a, obs(3) - a);
        killing->SetSpacing(0.25 * a, 0.25 * a, 0.5 * a);
        killing->Update();
        vtkNew<vtkXMLImageDataWriter> kw;
        files.addXml(kw, killing->GetOutputDataObject(0), "killing_fields.vti");

        vtkNew<vtkLightconeIsometryOrbitSource> orbits;
        orbits->SetGodelA(a);
        orbits->SetCoefficients(0, 0, 0, 1, 0);  // xi_4: radial through the axis at phi = pi/2
        vtkNew<vtkPoints> seeds;
        for (int k = -4; k <= 4; ++k) seeds->InsertNextPoint(0.4 * a * k, 0, 0);
        orbits->SetSeeds(seeds);
        orbits->SetSeedTime(obs(0));
        orbits->SetFlowRange(-1.5, 1.5);
        files.addPolyData(orbits, 0, "orbits_xi4.vtp");
    }

    // Objects: photo-objects (Goedel: every image layer; flat: the apparent shape) and world lines.
    std::size_t index = 0;
    auto exportObject = [&](const std::string& name, const Vec4& centre, const Motion& motion, vtkPolyData* mesh) {
        const std::string base = std::to_string(index++) + "_" + io::sanitizeFileName(name);
        if (godel && motion.kind == Motion::Kind::Rest) {
            vtkNew<vtkLightconePhotoObjectFilter> photo;
            photo->SetInputData(mesh);
            photo->SetModeToGodel();
            photo->SetGodelA(godel->a());
            photo->SetObserver(obs(0), obs(1), obs(2), obs(3));
            photo->SetCentreEvent(centre(0), centre(1), centre(2), centre(3));
            photo->SetMaxWinding(scene.settings.windings);
            photo->Update();
            files.addMultiBlock(photo->GetOutput(), "photo_" + base);
        } else if (!godel && scene.spacetime->name() == "minkowski") {
            vtkNew<vtkLightconePhotoObjectFilter> photo;
            photo->SetInputData(mesh);
            photo->SetModeToSpecialRelativity();
            photo->SetObserver(obs(0), obs(1), obs(2), obs(3));
            photo->SetBeta(motion.beta.data());
            photo->SetObjectOrigin(centre(0), centre(1), centre(2), centre(3));
            photo->Update();
            files.addMultiBlock(photo->GetOutput(), "photo_" + base);
        }
        if (motion.moving()) {
            vtkNew<vtkLightconeWorldLineSource> line;
            line->SetStartEvent(centre(0), centre(1), centre(2), centre(3));
            if (godel && motion.kind == Motion::Kind::FreeFall) {
                line->SetModeToGodelFreeFall();
                line->SetGodelA(godel->a());
                line->SetEnergy(motion.k0);
                line->SetK3(motion.k3);
                line->SetAzimuth(motion.phi0 * 180 / kPi);
            } else if (motion.kind == Motion::Kind::ConstantVelocity) {
                line->SetModeToMinkowski();
                line->SetBeta(motion.beta.data());
            } else {
                return;
            }
            line->SetProperTimeRange(-10, 2);
            files.addPolyData(line, 0, "world_line_" + base + ".vtp");
        }
    };
    for (const auto& s : scene.spheres) {
        vtkNew<vtkSphereSource> sphere;
        sphere->SetRadius(s.radius);
        sphere->SetThetaResolution(48);
        sphere->SetPhiResolution(24);
        sphere->Update();
        exportObject(s.name, s.centre, s.motion, sphere->GetOutput());
    }
    for (const auto& m : scene.meshes) {
        vtkNew<vtkPolyData> pd;
        io::meshToPolyData(m, pd);
        exportObject(m.name, m.centre, m.motion, pd);
    }
    files.commit(dir);
}

int runExport(const std::vector<std::string>& argv) {
    const ExportOptions o = parseExportOptions(argv);
    io::checkOutputFolder(o.directory, "-o");
    exportScene(io::readScene(o.scene, sceneReadOptions()), o.directory, o.rays);
    return 0;
}

}  // namespace lc::cli
