// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeOutputChart_h
#define vtkLightconeOutputChart_h
/**
 * @class vtkLightconeOutputChart
 * @brief The chart in which the Lightcone sources write their points, one meaning for all.
 *
 *   - EMBEDDING (default): (X, Y, z) — the spatial picture;
 *   - RPHIT: (r, phi, t), phi continuous along each curve — the r-phi diagram with time up;
 *   - XYT: (X, Y, t) — a spacetime diagram of the plane, time up.
 *
 * A source declares its OutputChart with vtkLightconeOutputChartMacro() and maps each event of
 * a curve with a vtkLightconeOutputChart::Curve (which keeps phi continuous). The Goedel
 * parameter of the Goedel sources is declared once too (vtkLightconeGodelAMacro()).
 */
#include "core/numerics/types.hpp"

#include <cmath>

class vtkLightconeOutputChart
{
public:
  enum Chart
  {
    EMBEDDING = 0,
    RPHIT = 1,
    XYT = 2
  };

  static const char* GetName(int chart)
  {
    return chart == RPHIT ? "RPhiT" : chart == XYT ? "XYT" : "Embedding";
  }

  // The points of one curve: events (t, X, Y, z) in order, phi unwrapped from one to the next.
  class Curve
  {
  public:
    explicit Curve(int chart)
      : ChartId(chart)
    {
    }
    void Map(const lc::Vec4& x, double point[3])
    {
      if (this->ChartId != RPHIT)
      {
        point[0] = x(1);
        point[1] = x(2);
        point[2] = this->ChartId == XYT ? x(0) : x(3);
        return;
      }
      const double r = std::hypot(x(1), x(2));
      double phi = std::atan2(x(2), x(1));
      if (this->HavePhi)
      {
        phi += 2.0 * lc::kPi * std::nearbyint((this->Phi - phi) / (2.0 * lc::kPi));
      }
      if (r > 0 || !this->HavePhi) // on the axis the azimuth is undefined: keep the last one
      {
        this->Phi = phi;
        this->HavePhi = true;
      }
      point[0] = r;
      point[1] = this->Phi;
      point[2] = x(0);
    }

  private:
    int ChartId;
    bool HavePhi = false;
    double Phi = 0.0;
  };
};

// OutputChart with its Set/Get methods, as every Lightcone source declares it.
#define vtkLightconeOutputChartMacro()                                                             \
  vtkSetClampMacro(                                                                                \
    OutputChart, int, vtkLightconeOutputChart::EMBEDDING, vtkLightconeOutputChart::XYT);           \
  vtkGetMacro(OutputChart, int);                                                                   \
  void SetOutputChartToEmbedding()                                                                 \
  {                                                                                                \
    this->SetOutputChart(vtkLightconeOutputChart::EMBEDDING);                                      \
  }                                                                                                \
  void SetOutputChartToRPhiT()                                                                     \
  {                                                                                                \
    this->SetOutputChart(vtkLightconeOutputChart::RPHIT);                                          \
  }                                                                                                \
  void SetOutputChartToXYT()                                                                       \
  {                                                                                                \
    this->SetOutputChart(vtkLightconeOutputChart::XYT);                                            \
  }

// The Goedel parameter a > 0 (default 1) of the Goedel sources and filters.
#define vtkLightconeGodelAMacro()                                                                  \
  vtkSetClampMacro(GodelA, double, 1e-12, VTK_DOUBLE_MAX);                                         \
  vtkGetMacro(GodelA, double)

#endif
