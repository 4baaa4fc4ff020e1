// `lightcone export`: the VTK filter outputs of a scene as files ParaView opens
// (.vtp polylines and surfaces, .vti Killing fields, .vtm photo-objects).
#include "app/commands.hpp"
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
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLWriter.h>

#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace lc::cli {
namespace {
namespace fs = std::filesystem;

// Writes through a temporary name and renames, so a failed export leaves old files intact.
void writeAtomically(vtkXMLWriter* writer, vtkDataObject* data, const fs::path& target) {
    const fs::path tmp = target.parent_path() / (".tmp-" + std::to_string(::getpid()) + "-" + target.filename().string());
    writer->SetInputData(data);
    writer->SetFileName(tmp.string().c_str());
    writer->SetDataModeToBinary();
    if (writer->Write() != 1 || !fs::exists(tmp)) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write '" + target.string() + "' (hint: is the folder writable?)");
    }
    fs::rename(tmp, target);
    std::printf("wrote %s\n", target.string().c_str());
}

void writePolyData(vtkAlgorithm* source, int port, const fs::path& target) {
    source->Update();
    vtkNew<vtkXMLPolyDataWriter> w;
    writeAtomically(w, source->GetOutputDataObject(port), target);
}

}  // namespace

int runExport(const Args& args) {
    args.allow({"-o", "--output", "--rays"});
    if (args.positional().size() != 1) throw std::invalid_argument("export expects one scene file");
    const Scene scene = io::readScene(args.positional()[0], sceneReadOptions());
    const fs::path dir = args.get("-o", args.get("--output", "lightcone-export"));
    fs::create_directories(dir);
    const Vec4& obs = scene.observer;
    const int rays = static_cast<int>(args.number("--rays", 24));
    const auto* godel = dynamic_cast<const GodelCartesian*>(scene.spacetime.get());

    // Null geodesics from the observer: a fan in the observer's horizontal plane and a cone.
    for (const char* mode : {"fan", "cone"}) {
        vtkNew<vtkLightconeNullGeodesicSource> geo;
        geo->SetSpacetime(scene.spacetime);
        geo->SetObserver(obs(0), obs(1), obs(2), obs(3));
        geo->SetNumberOfRays(rays);
        if (std::string(mode) == "fan") geo->SetDirectionModeToFan();
        else {
            geo->SetDirectionModeToCone();
            geo->SetConeAngle(60);
        }
        geo->SetStepper("dopri5");
        geo->SetTolerance(1e-10);
        geo->SetMaxAffine(godel ? (scene.settings.windings + 1) * 2 * kPi * godel->a() : 60.0);
        writePolyData(geo, 0, dir / (std::string("geodesics_") + mode + ".vtp"));
    }

    if (godel) {
        const double a = godel->a();
        vtkNew<vtkLightconeGodelHorizonSource> horizon;
        horizon->SetGodelA(a);
        horizon->SetObserver(obs(0), obs(1), obs(2), obs(3));
        horizon->SetZRange(obs(3) - 2 * a, obs(3) + 2 * a);
        horizon->GenerateLightConeOn();
        horizon->SetLightConeAffineLength(2 * kPi * a);
        writePolyData(horizon, 0, dir / "horizon.vtp");
        writePolyData(horizon, 1, dir / "light_cone.vtp");

        vtkNew<vtkLightconeKillingFieldSource> killing;
        killing->SetGodelA(a);
        killing->SetTime(obs(0));
        killing->SetDimensions(25, 25, 5);
        killing->SetOrigin(obs(1) - 3 * a, obs(2) - 3 * a, obs(3) - a);
        killing->SetSpacing(0.25 * a, 0.25 * a, 0.5 * a);
        killing->Update();
        vtkNew<vtkXMLImageDataWriter> kw;
        writeAtomically(kw, killing->GetOutputDataObject(0), dir / "killing_fields.vti");

        vtkNew<vtkLightconeIsometryOrbitSource> orbits;
        orbits->SetGodelA(a);
        orbits->SetCoefficients(0, 0, 0, 1, 0);  // xi_4: radial through the axis at phi = pi/2
        vtkNew<vtkPoints> seeds;
        for (int k = -4; k <= 4; ++k) seeds->InsertNextPoint(0.4 * a * k, 0, 0);
        orbits->SetSeeds(seeds);
        orbits->SetSeedTime(obs(0));
        orbits->SetFlowRange(-1.5, 1.5);
        writePolyData(orbits, 0, dir / "orbits_xi4.vtp");
    }

    // Objects: photo-objects (Goedel: every image layer; flat: the apparent shape) and world lines.
    std::size_t index = 0;
    auto exportObject = [&](const std::string& name, const Vec4& centre, const Motion& motion, vtkPolyData* mesh) {
        const std::string base = std::to_string(index++) + "_" + name;
        if (godel && motion.kind == Motion::Kind::Rest) {
            vtkNew<vtkLightconePhotoObjectFilter> photo;
            photo->SetInputData(mesh);
            photo->SetModeToGodel();
            photo->SetGodelA(godel->a());
            photo->SetObserverEvent(obs(0), obs(1), obs(2), obs(3));
            photo->SetCentreEvent(centre(0), centre(1), centre(2), centre(3));
            photo->SetMaxWinding(scene.settings.windings);
            photo->Update();
            vtkNew<vtkXMLMultiBlockDataWriter> w;
            writeAtomically(w, photo->GetOutputDataObject(0), dir / ("photo_" + base + ".vtm"));
        } else if (!godel && scene.spacetime->name() == "minkowski") {
            vtkNew<vtkLightconePhotoObjectFilter> photo;
            photo->SetInputData(mesh);
            photo->SetModeToSpecialRelativity();
            photo->SetObserverEvent(obs(0), obs(1), obs(2), obs(3));
            photo->SetBeta(motion.beta.data());
            photo->SetObjectOrigin(centre(0), centre(1), centre(2), centre(3));
            photo->Update();
            vtkNew<vtkXMLMultiBlockDataWriter> w;
            writeAtomically(w, photo->GetOutputDataObject(0), dir / ("photo_" + base + ".vtm"));
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
            writePolyData(line, 0, dir / ("world_line_" + base + ".vtp"));
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
    return 0;
}

}  // namespace lc::cli
