#include "vtkLightconeGeodesicShaderRenderer.h"

#include "lightconeReadBack.h"

#include "core/frame.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCullerCollection.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkUniforms.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeGeodesicShaderRenderer);

namespace {

// Vertex shader: the quad's points are already clip-space positions.
const char* kVertexImpl = R"(//VTK::PositionVC::Impl
gl_Position = vec4(vertexMC.xy, 0.0, 1.0);
)";

// Fragment shader, global declarations (placed after all of VTK's declarations, custom
// uniforms included): dual numbers, the metric as code, Hamilton's equations, the stepper.
const char* kFragmentDec = R"(//VTK::ValuePass::Dec

// ---- forward-mode dual numbers: value and gradient with respect to (x^0, x^1, x^2, x^3) ----
struct dual4 { float v; vec4 d; };
dual4 dConst(float v) { return dual4(v, vec4(0.0)); }
dual4 dAdd(dual4 a, dual4 b) { return dual4(a.v + b.v, a.d + b.d); }
dual4 dSub(dual4 a, dual4 b) { return dual4(a.v - b.v, a.d - b.d); }
dual4 dMul(dual4 a, dual4 b) { return dual4(a.v * b.v, a.d * b.v + a.v * b.d); }
dual4 dDiv(dual4 a, dual4 b) { float q = a.v / b.v; return dual4(q, (a.d - q * b.d) / b.v); }
dual4 dSqrt(dual4 a) { float s = sqrt(a.v); return dual4(s, a.d * (0.5 / s)); }
dual4 dScale(dual4 a, float s) { return dual4(a.v * s, a.d * s); }
dual4 dAddC(dual4 a, float c) { return dual4(a.v + c, a.d); }
dual4 dNeg(dual4 a) { return dual4(-a.v, -a.d); }

// ---- the metric written as code (lc::KerrNewman::g, outgoing Kerr-Schild Cartesian) ----
//   g = eta - f l (x) l,  f = r^2 (2 M r - Q^2) / (r^4 + a^2 z^2),
//   l = (1, -(r x - a y)/(r^2+a^2), -(r y + a x)/(r^2+a^2), -z/r).
// The ten independent entries g_{mu nu} (mu <= nu) as dual numbers over x: value and exact
// gradient d g_{mu nu} / d x^k. Written without arrays or loops so that every index is a
// compile-time constant (dynamically indexed local arrays are very slow on llvmpipe).
#define LC_ENTRY(G, LA, LB, ETA) G = dMul(f, dMul(LA, LB)); G = dual4(ETA - G.v, -G.d);
void lcMetric(vec4 X, out dual4 g00, out dual4 g01, out dual4 g02, out dual4 g03, out dual4 g11,
              out dual4 g12, out dual4 g13, out dual4 g22, out dual4 g23, out dual4 g33)
{
  if (lcMetricKind == 0)
  {
    g00 = dConst(1.0); g11 = dConst(-1.0); g22 = dConst(-1.0); g33 = dConst(-1.0);
    g01 = dConst(0.0); g02 = dConst(0.0); g03 = dConst(0.0);
    g12 = dConst(0.0); g13 = dConst(0.0); g23 = dConst(0.0);
    return;
  }
  float a = lcSpin;
  dual4 x = dual4(X.y, vec4(0.0, 1.0, 0.0, 0.0));
  dual4 y = dual4(X.z, vec4(0.0, 0.0, 1.0, 0.0));
  dual4 z = dual4(X.w, vec4(0.0, 0.0, 0.0, 1.0));
  dual4 z2 = dMul(z, z);
  dual4 rho2 = dAddC(dAdd(dAdd(dMul(x, x), dMul(y, y)), z2), -a * a);
  dual4 r = dSqrt(dScale(dAdd(rho2, dSqrt(dAdd(dMul(rho2, rho2), dScale(z2, 4.0 * a * a)))), 0.5));
  dual4 r2 = dMul(r, r);
  dual4 f = dDiv(dMul(r2, dAddC(dScale(r, 2.0 * lcMass), -lcCharge * lcCharge)),
                 dAdd(dMul(r2, r2), dScale(z2, a * a)));
  dual4 den = dAddC(r2, a * a);
  dual4 l0 = dConst(1.0);
  dual4 l1 = dNeg(dDiv(dSub(dMul(r, x), dScale(y, a)), den));
  dual4 l2 = dNeg(dDiv(dAdd(dMul(r, y), dScale(x, a)), den));
  dual4 l3 = dNeg(dDiv(z, r));
  LC_ENTRY(g00, l0, l0, 1.0)
  LC_ENTRY(g01, l0, l1, 0.0)
  LC_ENTRY(g02, l0, l2, 0.0)
  LC_ENTRY(g03, l0, l3, 0.0)
  LC_ENTRY(g11, l1, l1, -1.0)
  LC_ENTRY(g12, l1, l2, 0.0)
  LC_ENTRY(g13, l1, l3, 0.0)
  LC_ENTRY(g22, l2, l2, -1.0)
  LC_ENTRY(g23, l2, l3, 0.0)
  LC_ENTRY(g33, l3, l3, -1.0)
}

// Boyer-Lindquist radius of a Cartesian Kerr-Schild point (lc::KerrNewman::radius).
float lcRadius(vec3 q)
{
  float a2 = lcSpin * lcSpin;
  float rho2 = dot(q, q) - a2;
  return sqrt(0.5 * (rho2 + sqrt(rho2 * rho2 + 4.0 * a2 * q.z * q.z)));
}

// Hamilton's equations for H = 1/2 g^{mu nu} p_mu p_nu (lc::Spacetime::flow):
//   dx/dl = v = g^{-1} p,  dp_k/dl = 1/2 v^T (d_k g) v.
void lcFlow(vec4 x, vec4 p, out vec4 dx, out vec4 dp)
{
  dual4 g00, g01, g02, g03, g11, g12, g13, g22, g23, g33;
  lcMetric(x, g00, g01, g02, g03, g11, g12, g13, g22, g23, g33);
  mat4 g = mat4(g00.v, g01.v, g02.v, g03.v,  g01.v, g11.v, g12.v, g13.v,
                g02.v, g12.v, g22.v, g23.v,  g03.v, g13.v, g23.v, g33.v);
  vec4 v = inverse(g) * p;
  dx = v;
  // 1/2 v^T (d_k g) v over the symmetric entries (off-diagonal ones twice).
  dp = 0.5 * (v.x * v.x * g00.d + v.y * v.y * g11.d + v.z * v.z * g22.d + v.w * v.w * g33.d)
     + v.x * v.y * g01.d + v.x * v.z * g02.d + v.x * v.w * g03.d
     + v.y * v.z * g12.d + v.y * v.w * g13.d + v.z * v.w * g23.d;
}

float lcMaxAbs(vec4 e, vec4 y0, vec4 y1)
{
  vec4 q = abs(e) / (lcTolerance * (vec4(1.0) + max(abs(y0), abs(y1))));
  return max(max(q.x, q.y), max(q.z, q.w));
}

// Traces the past-directed null ray seen along frame direction n. Returns 0 (escaped, dir =
// the spatial contravariant tangent at escape), 1 (horizon) or 2 (failed); steps = trial steps.
int lcTrace(vec3 n, out vec3 dir, out int steps)
{
  dir = vec3(0.0);
  steps = 0;
  // k = -e0 + n^i e_i, lowered with g(x0) (lc::LocalFrame::pastNullMomentum).
  vec4 k = -lcE0 + n.x * lcE1 + n.y * lcE2 + n.z * lcE3;
  vec4 p = vec4(dot(lcG0r0, k), dot(lcG0r1, k), dot(lcG0r2, k), dot(lcG0r3, k));
  vec4 x = lcObserver;
  vec4 k1x, k1p;
  lcFlow(x, p, k1x, k1p);
  float h = lcInitialStep;
  for (int it = 0; it < lcMaxSteps; ++it)
  {
    steps = it + 1;
    // Dormand-Prince 5(4), first-same-as-last.
    h = min(h, lcStepPerRadius * max(length(x.yzw), lcRadiusFloor));
    vec4 k2x, k2p, k3x, k3p, k4x, k4p, k5x, k5p, k6x, k6p, k7x, k7p;
    lcFlow(x + h * (0.2 * k1x), p + h * (0.2 * k1p), k2x, k2p);
    lcFlow(x + h * (3.0 / 40.0 * k1x + 9.0 / 40.0 * k2x), p + h * (3.0 / 40.0 * k1p + 9.0 / 40.0 * k2p), k3x, k3p);
    lcFlow(x + h * (44.0 / 45.0 * k1x - 56.0 / 15.0 * k2x + 32.0 / 9.0 * k3x),
           p + h * (44.0 / 45.0 * k1p - 56.0 / 15.0 * k2p + 32.0 / 9.0 * k3p), k4x, k4p);
    lcFlow(x + h * (19372.0 / 6561.0 * k1x - 25360.0 / 2187.0 * k2x + 64448.0 / 6561.0 * k3x - 212.0 / 729.0 * k4x),
           p + h * (19372.0 / 6561.0 * k1p - 25360.0 / 2187.0 * k2p + 64448.0 / 6561.0 * k3p - 212.0 / 729.0 * k4p),
           k5x, k5p);
    lcFlow(x + h * (9017.0 / 3168.0 * k1x - 355.0 / 33.0 * k2x + 46732.0 / 5247.0 * k3x + 49.0 / 176.0 * k4x - 5103.0 / 18656.0 * k5x),
           p + h * (9017.0 / 3168.0 * k1p - 355.0 / 33.0 * k2p + 46732.0 / 5247.0 * k3p + 49.0 / 176.0 * k4p - 5103.0 / 18656.0 * k5p),
           k6x, k6p);
    vec4 xn = x + h * (35.0 / 384.0 * k1x + 500.0 / 1113.0 * k3x + 125.0 / 192.0 * k4x - 2187.0 / 6784.0 * k5x + 11.0 / 84.0 * k6x);
    vec4 pn = p + h * (35.0 / 384.0 * k1p + 500.0 / 1113.0 * k3p + 125.0 / 192.0 * k4p - 2187.0 / 6784.0 * k5p + 11.0 / 84.0 * k6p);
    lcFlow(xn, pn, k7x, k7p);
    // Fifth minus fourth order solution.
    vec4 ex = h * (71.0 / 57600.0 * k1x - 71.0 / 16695.0 * k3x + 71.0 / 1920.0 * k4x - 17253.0 / 339200.0 * k5x + 22.0 / 525.0 * k6x - 1.0 / 40.0 * k7x);
    vec4 ep = h * (71.0 / 57600.0 * k1p - 71.0 / 16695.0 * k3p + 71.0 / 1920.0 * k4p - 17253.0 / 339200.0 * k5p + 22.0 / 525.0 * k6p - 1.0 / 40.0 * k7p);
    float err = max(lcMaxAbs(ex, x, xn), lcMaxAbs(ep, p, pn));
    if (!(err <= 1.0))  // rejected (NaN included)
    {
      h *= (err > 1.0 && err < 1e30) ? max(0.2, 0.9 * pow(err, -0.2)) : 0.2;
      if (h < 1e-7) return 2;
      continue;
    }
    x = xn;
    p = pn;
    k1x = k7x;
    k1p = k7p;
    h *= min(5.0, 0.9 * pow(max(err, 1e-10), -0.2));
    if (any(isnan(x)) || any(isinf(x)) || any(isnan(p)) || any(isinf(p))) return 2;
    // Null condition H = 1/2 p.v (v = g^{-1} p is the first stage of the next step, free):
    // a ray whose |H| grew past the tolerance fails, as ConstraintBlowUp on the CPU. In
    // single precision |H| is measured relative to 1/2 sum |p_mu v^mu| (1 at the observer,
    // where the observed frequency is 1), since the terms of p.v grow with the blueshift
    // towards the horizon and float round-off grows with them.
    if (abs(dot(p, k1x)) > lcConstraintTolerance * dot(abs(p), abs(k1x))) return 2;
    if (lcMetricKind != 0 && lcRadius(x.yzw) < lcHorizonStop) return 1;
    if (dot(x.yzw, x.yzw) > lcEscapeRadius * lcEscapeRadius && dot(x.yzw, k1x.yzw) > 0.0)
    {
      dir = normalize(k1x.yzw);
      return 0;
    }
  }
  return 2;
}
)";

// Fragment shader, body: the pixel's direction (lc::Camera::direction with gl_FragCoord =
// pixel centre, row 0 of the camera at the top), the trace, the colour or the pass output.
const char* kFragmentImpl = R"(//VTK::TCoord::Impl
{
  float lcSx = 2.0 * gl_FragCoord.x / lcWidth - 1.0;
  float lcSy = 2.0 * gl_FragCoord.y / lcHeight - 1.0;
  vec3 lcN;
  if (lcProjection == 0)
    lcN = normalize(lcForward + lcSx * lcTanHalfX * lcRight + lcSy * lcTanHalfY * lcUp);
  else
  {
    float lcAz = -lcSx * lcHalfX, lcEl = lcSy * lcHalfY;
    lcN = normalize(cos(lcEl) * (cos(lcAz) * lcForward - sin(lcAz) * lcRight) + sin(lcEl) * lcUp);
  }
  vec3 lcDir;
  int lcSteps;
  int lcClass = lcTrace(lcN, lcDir, lcSteps);
  if (lcMode == 1)
    gl_FragData[0] = vec4(float(lcClass) / 255.0, float(min(lcSteps / 8, 255)) / 255.0, 0.0, 1.0);
  else if (lcMode == 2)
    gl_FragData[0] = vec4(lcClass == 0 ? 0.5 * lcDir + vec3(0.5) : vec3(0.0), 1.0);
  else
  {
    vec3 lcC = vec3(1.0, 0.0, 1.0);
    if (lcClass == 1) lcC = vec3(0.0);
    else if (lcClass == 0)
    {
      // toSkyUv of core/render.cpp: u = 1/2 + atan2(y, x) / 2 pi, v = acos(z) / pi.
      float lcU = 0.5 + atan(lcDir.y, lcDir.x) / 6.28318530717958647;
      float lcV = acos(clamp(lcDir.z, -1.0, 1.0)) / 3.14159265358979323846;
      lcC = textureLod(actortexture, vec2(lcU, lcV), 0.0).rgb;
    }
    gl_FragData[0] = vec4(lcC, 1.0);
  }
}
)";

// The sky baked at texel centres: u across (wraps), v down the rows (v = 0 at the north pole);
// texel row j is texture coordinate t = v. Procedural skies are sampled nearest so checker
// edges stay sharp; image skies keep their texels and are filtered linearly (as
// lc::ImageTexture::sample).
vtkSmartPointer<vtkTexture> bakeSky(const lc::TexturePtr& tex, const lc::Vec3& fallback, int n) {
    const auto* image = dynamic_cast<const lc::ImageTexture*>(tex.get());
    const int w = image ? image->width() : 2 * n, h = image ? image->height() : n;
    vtkNew<vtkImageData> data;
    data->SetDimensions(w, h, 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* p = static_cast<unsigned char*>(data->GetScalarPointer());
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const lc::Vec3 c = tex ? tex->sample((i + 0.5) / w, (j + 0.5) / h) : fallback;
            for (int k = 0; k < 3; ++k)
                p[3 * (static_cast<std::size_t>(j) * w + i) + k] =
                    static_cast<unsigned char>(std::lround(255.0 * std::clamp(c(k), 0.0, 1.0)));
        }
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(data);
    texture->SetInterpolate(image != nullptr);
    texture->RepeatOn();
    texture->MipmapOff();
    return texture;
}

void set4(vtkUniforms* u, const char* name, const lc::Vec4& v) {
    const float f[4] = {static_cast<float>(v(0)), static_cast<float>(v(1)), static_cast<float>(v(2)),
                        static_cast<float>(v(3))};
    u->SetUniform4f(name, f);
}
void set3(vtkUniforms* u, const char* name, const lc::Vec3& v) {
    const float f[3] = {static_cast<float>(v(0)), static_cast<float>(v(1)), static_cast<float>(v(2))};
    u->SetUniform3f(name, f);
}

}  // namespace

vtkLightconeGeodesicShaderRenderer::vtkLightconeGeodesicShaderRenderer() = default;
vtkLightconeGeodesicShaderRenderer::~vtkLightconeGeodesicShaderRenderer() = default;

void vtkLightconeGeodesicShaderRenderer::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Metric: " << (this->HasScene ? this->Scene.spacetime->name() : std::string("(none)")) << "\n"
       << indent << "Tolerance: " << this->Tolerance << "\n"
       << indent << "MaxSteps: " << this->MaxSteps << "\n"
       << indent << "HorizonEpsilon: " << this->HorizonEpsilon << "\n"
       << indent << "ConstraintTolerance: " << this->ConstraintTolerance << "\n"
       << indent << "TextureSize: " << this->TextureSize << "\n"
       << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
}

void vtkLightconeGeodesicShaderRenderer::SetScene(const lc::Scene& scene) {
    const lc::Spacetime* st = scene.spacetime.get();
    if (!st) throw std::invalid_argument("the GPU geodesic renderer: the scene has no spacetime");
    if (const auto* kn = dynamic_cast<const lc::KerrNewman*>(st)) {
        this->MetricKind = 1;
        this->Mass = kn->mass();
        this->Spin = kn->spin();
        this->Charge = kn->charge();
        this->OuterHorizon = kn->outerHorizon();
    } else if (dynamic_cast<const lc::Minkowski*>(st)) {
        this->MetricKind = 0;
        this->Mass = this->Spin = this->Charge = this->OuterHorizon = 0;
    } else {
        throw std::invalid_argument("the GPU geodesic renderer draws minkowski, schwarzschild, kerr and kerr-newman "
                                    "scenes; metric '" + st->name() + "' is not supported (use the numeric renderer)");
    }
    scene.camera.validate();
    // Throws if the observer cannot be static / has a bad velocity here.
    (void)lc::LocalFrame::withVelocity(*st, scene.observer, scene.observerVelocity);
    this->Scene = scene;
    this->HasScene = true;
    this->Built = false;
    this->Modified();
}

vtkRenderWindow* vtkLightconeGeodesicShaderRenderer::GetRenderWindow() {
    if (this->NeedsBuild()) this->Build();
    return this->Window;
}

bool vtkLightconeGeodesicShaderRenderer::NeedsBuild() {
    return !this->Built || this->GetMTime() > this->BuildTime.GetMTime();
}

void vtkLightconeGeodesicShaderRenderer::Build() {
    if (!this->HasScene) throw std::logic_error("vtkLightconeGeodesicShaderRenderer: no scene");
    const lc::Camera& cam = this->Scene.camera;

    // Two triangles covering clip space; texture coordinates only so that the mapper declares
    // the actor's texture sampler.
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    const double corners[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("TCoords");
    tcoords->SetNumberOfComponents(2);
    for (const auto& c : corners) {
        points->InsertNextPoint(c);
        tcoords->InsertNextTuple2(0.5 * (c[0] + 1), 0.5 * (c[1] + 1));
    }
    vtkNew<vtkCellArray> cells;
    const vtkIdType t0[3] = {0, 1, 2}, t1[3] = {0, 2, 3};
    cells->InsertNextCell(3, t0);
    cells->InsertNextCell(3, t1);
    vtkNew<vtkPolyData> quad;
    quad->SetPoints(points);
    quad->SetPolys(cells);
    quad->GetPointData()->SetTCoords(tcoords);

    vtkNew<vtkOpenGLPolyDataMapper> mapper;
    mapper->SetInputData(quad);
    mapper->ScalarVisibilityOff();
    mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    this->Actor = vtkSmartPointer<vtkActor>::New();
    this->Actor->SetMapper(mapper);
    this->Actor->SetTexture(bakeSky(this->Scene.sky, this->Scene.background, this->TextureSize));
    this->Actor->GetProperty()->LightingOff();
    vtkShaderProperty* sp = this->Actor->GetShaderProperty();
    sp->AddVertexShaderReplacement("//VTK::PositionVC::Impl", true, kVertexImpl, false);
    sp->AddFragmentShaderReplacement("//VTK::ValuePass::Dec", true, kFragmentDec, false);
    sp->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, kFragmentImpl, false);

    this->Renderer = vtkSmartPointer<vtkRenderer>::New();
    this->Renderer->GetCullers()->RemoveAllItems();
    this->Renderer->SetUseDepthPeeling(false);
    this->Renderer->SetUseFXAA(false);
    this->Renderer->SetBackground(0, 0, 0);
    this->Renderer->AddActor(this->Actor);
    this->Window = vtkSmartPointer<vtkRenderWindow>::New();
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);  // one sample per pixel: one ray per pixel, exact ids
    this->Window->SetSize(cam.width, cam.height);
    this->Window->AddRenderer(this->Renderer);

    this->Built = true;
    this->BuildTime.Modified();
    this->UpdateUniforms(0);
}

void vtkLightconeGeodesicShaderRenderer::SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up) {
    this->Scene.camera.forward = forward;
    this->Scene.camera.up = up;
    this->Scene.camera.validate();
    if (!this->NeedsBuild()) this->UpdateUniforms(0);
}

void vtkLightconeGeodesicShaderRenderer::UpdateUniforms(int mode) {
    const lc::Scene& scene = this->Scene;
    const lc::Camera& cam = scene.camera;
    const lc::Spacetime& st = *scene.spacetime;
    const lc::LocalFrame frame = lc::LocalFrame::withVelocity(st, scene.observer, scene.observerVelocity);
    const lc::Mat4 g0 = st.metric(scene.observer);
    const lc::Vec3 f = cam.forward.normalized();
    const lc::Vec3 r = f.cross(cam.up).normalized();
    const lc::Vec3 u = r.cross(f);
    const double deg = lc::kPi / 180;
    const lc::TraceOptions& trace = scene.settings.trace;

    vtkUniforms* fs = this->Actor->GetShaderProperty()->GetFragmentCustomUniforms();
    fs->SetUniformi("lcMode", mode);
    fs->SetUniformi("lcMetricKind", this->MetricKind);
    fs->SetUniformf("lcMass", static_cast<float>(this->Mass));
    fs->SetUniformf("lcSpin", static_cast<float>(this->Spin));
    fs->SetUniformf("lcCharge", static_cast<float>(this->Charge));
    fs->SetUniformf("lcHorizonStop", static_cast<float>(this->OuterHorizon * (1.0 + this->HorizonEpsilon)));
    fs->SetUniformf("lcEscapeRadius", static_cast<float>(trace.escapeRadius));
    // A step may not exceed StepPerRadius x the distance from the origin (the CPU's
    // stepPerRadius); the floor (M, or 1 in flat space) keeps rays from the origin moving.
    fs->SetUniformf("lcStepPerRadius", static_cast<float>(trace.stepPerRadius > 0 ? trace.stepPerRadius : 1e30));
    fs->SetUniformf("lcRadiusFloor", static_cast<float>(this->MetricKind == 0 ? 1.0 : this->Mass));
    fs->SetUniformf("lcInitialStep", static_cast<float>(trace.initialStep > 0 ? trace.initialStep : 1e-2));
    fs->SetUniformf("lcTolerance", static_cast<float>(this->Tolerance));
    fs->SetUniformi("lcMaxSteps", this->MaxSteps);
    fs->SetUniformf("lcConstraintTolerance", static_cast<float>(this->ConstraintTolerance));
    set4(fs, "lcObserver", scene.observer);
    set4(fs, "lcE0", frame.e[0]);
    set4(fs, "lcE1", frame.e[1]);
    set4(fs, "lcE2", frame.e[2]);
    set4(fs, "lcE3", frame.e[3]);
    set4(fs, "lcG0r0", g0.row(0).transpose());
    set4(fs, "lcG0r1", g0.row(1).transpose());
    set4(fs, "lcG0r2", g0.row(2).transpose());
    set4(fs, "lcG0r3", g0.row(3).transpose());
    set3(fs, "lcForward", f);
    set3(fs, "lcRight", r);
    set3(fs, "lcUp", u);
    const int projection = cam.projection == lc::Camera::Projection::Pinhole ? 0 : 1;
    fs->SetUniformi("lcProjection", projection);
    fs->SetUniformf("lcTanHalfX", static_cast<float>(std::tan(0.5 * cam.fovXDeg * deg)));
    fs->SetUniformf("lcTanHalfY", static_cast<float>(projection == 0 ? std::tan(0.5 * cam.fovYDeg * deg) : 1.0));
    fs->SetUniformf("lcHalfX", static_cast<float>(0.5 * cam.fovXDeg * deg));
    fs->SetUniformf("lcHalfY", static_cast<float>(0.5 * cam.fovYDeg * deg));
    fs->SetUniformf("lcWidth", static_cast<float>(cam.width));
    fs->SetUniformf("lcHeight", static_cast<float>(cam.height));
}

void vtkLightconeGeodesicShaderRenderer::Render() {
    if (this->NeedsBuild()) this->Build();
    this->UpdateUniforms(0);
    this->Window->Render();
}

std::vector<unsigned char> vtkLightconeGeodesicShaderRenderer::ReadPixels(int mode) {
    if (this->NeedsBuild()) this->Build();
    const auto t0 = std::chrono::steady_clock::now();
    this->UpdateUniforms(mode);
    this->Window->Render();
    std::vector<unsigned char> rgb = lc::views::readBackRgb(this->Window, this->Scene.camera.width, this->Scene.camera.height, "vtkLightconeGeodesicShaderRenderer");
    this->LastRenderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (mode != 0) this->UpdateUniforms(0);
    return rgb;
}

std::vector<float> vtkLightconeGeodesicShaderRenderer::RenderColour() {
    const std::vector<unsigned char> rgb = this->ReadPixels(0);
    std::vector<float> out(rgb.size());
    for (std::size_t k = 0; k < rgb.size(); ++k) out[k] = rgb[k] / 255.0f;
    return out;
}

std::vector<int> vtkLightconeGeodesicShaderRenderer::RenderIds() {
    const std::vector<unsigned char> rgb = this->ReadPixels(1);
    std::vector<int> ids(rgb.size() / 3);
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(rgb[3 * k]);
    return ids;
}

std::vector<int> vtkLightconeGeodesicShaderRenderer::RenderStepCounts() {
    const std::vector<unsigned char> rgb = this->ReadPixels(1);
    std::vector<int> steps(rgb.size() / 3);
    for (std::size_t k = 0; k < steps.size(); ++k) steps[k] = 8 * static_cast<int>(rgb[3 * k + 1]);
    return steps;
}

std::vector<float> vtkLightconeGeodesicShaderRenderer::RenderEscapeDirections() {
    const std::vector<unsigned char> rgb = this->ReadPixels(2);
    std::vector<float> out(rgb.size());
    for (std::size_t k = 0; k < rgb.size(); ++k) out[k] = 2.0f * rgb[k] / 255.0f - 1.0f;
    return out;
}
