// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeOffscreenRenderer_h
#define vtkLightconeOffscreenRenderer_h
// The base of Lightcone's shader renderers: it owns the offscreen window and its renderer, the
// build timestamp (rebuild when what the build depends on changed) and the 8-bit read-back of
// the colour and id passes, timed. A renderer implements Build(), creating its window with
// CreateWindow() and ending with MarkBuilt().
#include <vtkObject.h>
#include <vtkSmartPointer.h>
#include <vtkTimeStamp.h>

#include <vector>

class vtkRenderWindow;
class vtkRenderer;

class vtkLightconeOffscreenRenderer : public vtkObject {
public:
    vtkTypeMacro(vtkLightconeOffscreenRenderer, vtkObject)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // Builds the VTK pipeline (every Render* call does it when needed).
    virtual void Build() = 0;
    // The offscreen window, built when needed.
    vtkRenderWindow* GetRenderWindow();
    // Wall time of the last read-back (draw + read-back), seconds.
    double GetLastRenderSeconds() const { return this->LastRenderSeconds; }

protected:
    vtkLightconeOffscreenRenderer();
    ~vtkLightconeOffscreenRenderer() override;

    // When what the last Build() depends on last changed (default: any Modified()).
    virtual vtkMTimeType GetBuildDependencyTime() { return this->GetMTime(); }
    bool NeedsBuild();
    void BuildIfNeeded();
    void MarkBuilt();
    void Invalidate() { this->Built = false; }
    // A new offscreen window of width x height with one renderer (offscreen_parts).
    void CreateWindow(int width, int height);
    // Draws and reads back 8-bit RGB, 3 bytes per pixel, row 0 at the top.
    std::vector<unsigned char> DrawAndReadBack(int width, int height);

    vtkSmartPointer<vtkRenderWindow> Window;
    vtkSmartPointer<vtkRenderer> Renderer;

private:
    vtkLightconeOffscreenRenderer(const vtkLightconeOffscreenRenderer&) = delete;
    void operator=(const vtkLightconeOffscreenRenderer&) = delete;

    bool Built = false;
    vtkTimeStamp BuildTime;
    double LastRenderSeconds = 0;
};

#endif
