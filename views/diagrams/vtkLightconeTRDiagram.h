// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeTRDiagram_h
#define vtkLightconeTRDiagram_h
// The t-r spacetime diagram of a Goedel scene: distance r from the observer (its own chart, the
// observer on the axis r = 0) across, coordinate time t up. It draws the observer's past light
// cone projected onto t-r (one closed-form null geodesic per elevation of the fan; rays never
// pass r = 2a), the horizon r = 2a and beyond it the band where the circles of constant t and r
// are closed timelike curves, the world line of each sphere (static: r constant; free fall or a
// given world line: lc::movingCentre), the light path of every image and its emission event,
// where `lightcone images` puts it. Time is the observer's chart's, shifted so that the observer
// sits at its own t: for an observer on the scene's z axis it is the scene's t. Exported to SVG,
// PDF or PNG (vtkLightconeGodelDiagram: settings, legend, export).
#include "vtkLightconeGodelDiagram.h"

class vtkLightconeTRDiagram : public vtkLightconeGodelDiagram {
public:
    static vtkLightconeTRDiagram* New();
    vtkTypeMacro(vtkLightconeTRDiagram, vtkLightconeGodelDiagram)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The number of emission events drawn (one per image path).
    int GetNumberOfEmissionEvents() const { return this->EmissionEvents; }

protected:
    vtkLightconeTRDiagram();
    ~vtkLightconeTRDiagram() override;

    std::string DiagramName() const override { return "t-r"; }
    void Draw(lc::views::DiagramChart& chart, double a, const lc::godel::ObserverView& view) override;

private:
    vtkLightconeTRDiagram(const vtkLightconeTRDiagram&) = delete;
    void operator=(const vtkLightconeTRDiagram&) = delete;

    // A curve in (r, t) of the observer's chart; t shifted by the observer's own time.
    struct Curve {
        std::vector<double> r, t;
        void add(const lc::Vec4& event, double tObserver);
    };
    std::vector<Curve> LightCone(double a) const;
    // maxSamples > 0: at most that many segments (a sketch, for the objects drawn together).
    Curve WorldLine(const lc::SphereObject& sphere, const lc::godel::ObserverView& view, double t0, double t1,
                    int maxSamples = 0) const;

    int EmissionEvents = 0;
};

#endif
