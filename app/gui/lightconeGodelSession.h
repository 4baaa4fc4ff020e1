#ifndef lightconeGodelSession_h
#define lightconeGodelSession_h
// The state behind the linked views, without any widget: a Goedel scene, the camera yaw and
// the windings, the closed-form render (kept for picking), and the light path of a pixel.
#include "core/render.hpp"
#include "core/scene.hpp"

#include <string>
#include <vector>

namespace lcgui {

class GodelSession {
public:
    // Throws std::invalid_argument unless the scene uses the 'godel' metric with spheres at rest.
    explicit GodelSession(lc::Scene scene);

    const lc::Scene& scene() const { return scene_; }
    double a() const { return a_; }

    // Yaw of the camera about its up vector, in degrees, from the scene file's forward vector.
    void setYawDegrees(double yaw);
    double yawDegrees() const { return yaw_; }
    // Windings followed by the rays; the maximal affine length follows ((N + 1) 2 pi a).
    void setWindings(int windings);
    int windings() const { return scene_.settings.windings; }

    // Renders with lc::renderGodelClosedForm and shades with lc::shadePixels.
    void render();
    const lc::RenderResult& result() const { return result_; }
    const std::vector<float>& colours() const { return colours_; }  // linear RGB, row 0 on top
    // Throws std::out_of_range outside the image.
    const lc::PixelRecord& pixel(int i, int j) const;

    // The light path of pixel (i, j): the past-directed ray from the observer through the
    // pixel's direction, sampled in closed form on [0, affine] (samples + 1 events), in the
    // observer's chart (observer at the origin, as in the r-phi diagram).
    std::vector<lc::Vec4> lightPath(int i, int j, double affine, int samples = 400) const;
    // Observer's chart -> world chart of the scene.
    lc::Vec4 toWorld(const lc::Vec4& observerChartEvent) const;

    // One line for the status bar: object, emission time, affine depth, frequency ratio.
    std::string describe(int i, int j) const;

private:
    lc::Scene scene_;
    lc::Vec3 forward0_;
    double a_ = 1;
    double yaw_ = 0;
    lc::RenderResult result_;
    std::vector<float> colours_;
};

}  // namespace lcgui

#endif
