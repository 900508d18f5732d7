// The VTK filters of filters/ on lattices of particles with analytic fields: interpolation
// onto grids (vtkMPSKernel, vtkMPSParticlesToGrid) and speed and vorticity
// (vtkMPSSpeedVorticity).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <vector>

#include <vtkCharArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMPSFreeSurface.h>
#include <vtkMPSKernel.h>
#include <vtkMPSParticlesToGrid.h>
#include <vtkMPSPolylineProbe.h>
#include <vtkMPSSectionAverages.h>
#include <vtkMPSSections.h>
#include <vtkMPSSpeedVorticity.h>
#include <vtkNew.h>
#include <vtkPVDReader.h>
#include <vtkPointData.h>
#include <vtkPointInterpolator.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticPointLocator.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include "operators/LatticeConstants.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "simulation/WaveGauges.h"
#include "support/TestSupport.h"

namespace {

constexpr double kDl = 0.005;
constexpr double kRe = 3.5 * kDl;

using Field2 = std::function<std::array<double, 2>(double, double)>;
using Field1 = std::function<double(double, double)>;

void add_value(vtkFieldData* fd, const char* name, double v) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(v);
  fd->AddArray(a);
}

/// A frame as `wcmps run` writes it: fluid particles on the square lattice of [0, nx DL] x
/// [0, ny DL] (centres at (i + 1/2) DL), "velocity" from vel, "pressure" from p, and "kind";
/// with walls, one row of wall particles under the bottom at rest.
vtkSmartPointer<vtkPolyData> lattice_frame(int nx, int ny, const Field2& vel, const Field1& p,
                                           bool with_wall = false) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("pressure");
  vtkNew<vtkUnsignedCharArray> kind;
  kind->SetName("kind");
  for (int j = with_wall ? -1 : 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double x = (i + 0.5) * kDl, y = (j + 0.5) * kDl;
      points->InsertNextPoint(x, y, 0.0);
      const auto v = j < 0 ? std::array<double, 2>{0.0, 0.0} : vel(x, y);
      velocity->InsertNextTuple3(v[0], v[1], 0.0);
      pressure->InsertNextValue(p(x, y));
      kind->InsertNextValue(j < 0 ? 1 : 0);
    }
  }
  auto frame = vtkSmartPointer<vtkPolyData>::New();
  frame->SetPoints(points);
  frame->GetPointData()->AddArray(velocity);
  frame->GetPointData()->AddArray(pressure);
  frame->GetPointData()->AddArray(kind);
  add_value(frame->GetFieldData(), "DL", kDl);
  add_value(frame->GetFieldData(), "re", kRe);
  add_value(frame->GetFieldData(), "n0", wcmps::square_lattice_constants(kDl, kRe).n0);
  return frame;
}

std::array<double, 2> at_rest(double, double) {
  return {0.0, 0.0};
}
double linear_p(double x, double y) {
  return 1000.0 + 2.0e4 * x - 9.81e3 * y;
}

/// Distance of (x, y) from the edge of the water [0, w] x [0, h].
double inside_by(double x, double y, double w, double h) {
  return std::min({x, w - x, y, h - y});
}

vtkImageData* grid_of(vtkMPSParticlesToGrid* f, vtkPolyData* frame) {
  f->SetInputData(frame);
  f->Update();
  return f->GetOutput();
}

TEST(ParticlesToGrid, ReproducesALinearFieldInsideAndAConstantWhereCovered) {
  const int nx = 30, ny = 20;
  const double w = nx * kDl, h = ny * kDl;
  auto frame = lattice_frame(nx, ny, at_rest, linear_p);
  // A constant in the velocity: u = 0.3, v = -0.1 everywhere.
  auto* vel = vtkDoubleArray::SafeDownCast(frame->GetPointData()->GetArray("velocity"));
  for (vtkIdType i = 0; i < vel->GetNumberOfTuples(); ++i) vel->SetTuple3(i, 0.3, -0.1, 0.0);

  vtkNew<vtkMPSParticlesToGrid> f;
  f->SetSpacing(0.37 * kDl);  // off the lattice: grid points fall anywhere in the cells
  f->SetSamplingBounds(-5 * kDl, w + 5 * kDl, -5 * kDl, h + 5 * kDl, 0, 0);
  vtkImageData* g = grid_of(f, frame);
  auto* p = g->GetPointData()->GetArray("pressure");
  auto* u = g->GetPointData()->GetArray("velocity");
  auto* mask = g->GetPointData()->GetArray("vtkValidPointMask");
  auto* coverage = g->GetPointData()->GetArray("coverage");
  ASSERT_NE(p, nullptr);
  ASSERT_NE(u, nullptr);
  ASSERT_NE(mask, nullptr);
  ASSERT_NE(coverage, nullptr);
  int interior = 0, valid = 0, masked = 0;
  for (vtkIdType i = 0; i < g->GetNumberOfPoints(); ++i) {
    double x[3];
    g->GetPoint(i, x);
    const double d = inside_by(x[0], x[1], w, h);
    if (mask->GetComponent(i, 0) != 0.0) {
      ++valid;
      // The linear correction reproduces constants to round-off everywhere it is used, and
      // Shepard (its fallback) does too.
      EXPECT_NEAR(u->GetComponent(i, 0), 0.3, 1e-12);
      EXPECT_NEAR(u->GetComponent(i, 1), -0.1, 1e-12);
    } else {
      ++masked;
      EXPECT_TRUE(std::isnan(p->GetComponent(i, 0))) << "masked points hold the null value";
    }
    if (d > kRe) {
      // Full neighbourhoods: the linear field to round-off (its values are ~1e3 Pa).
      ++interior;
      EXPECT_EQ(mask->GetComponent(i, 0), 1.0);
      EXPECT_NEAR(p->GetComponent(i, 0), linear_p(x[0], x[1]), 1e-9);
      // The bulk coverage is 1 on average; it ripples with the position in the lattice
      // cell (1.05 on a particle, 0.99 between four): 0.1 covers the ripple.
      EXPECT_NEAR(coverage->GetComponent(i, 0), 1.0, 0.1);
    }
    if (d < -kRe) {
      EXPECT_EQ(coverage->GetComponent(i, 0), 0.0);
      EXPECT_EQ(mask->GetComponent(i, 0), 0.0);
    }
  }
  EXPECT_GT(interior, 1000);
  EXPECT_GT(masked, 1000);
  EXPECT_GT(valid, interior);
}

TEST(ParticlesToGrid, CoverageIsOneHalfOnTheEdgeOfTheWater) {
  const int nx = 40, ny = 40;
  auto frame = lattice_frame(nx, ny, at_rest, linear_p);
  vtkNew<vtkMPSParticlesToGrid> f;
  f->SetSpacing(0.25 * kDl);
  vtkImageData* g = grid_of(f, frame);
  // Default bounds: the fluid's grown by DL/2, i.e. the water [0, 40 DL]^2 exactly.
  double b[6];
  g->GetBounds(b);
  EXPECT_NEAR(b[0], 0.0, 1e-12);
  EXPECT_NEAR(b[1], nx * kDl, 1e-12);
  EXPECT_NEAR(b[2], 0.0, 1e-12);
  EXPECT_NEAR(b[3], ny * kDl, 1e-12);
  // Along the top edge, away from the corners: the continuum value is 1/2; the lattice
  // ripple (as above, halved) allows 0.05.
  auto* coverage = g->GetPointData()->GetArray("coverage");
  int checked = 0;
  for (vtkIdType i = 0; i < g->GetNumberOfPoints(); ++i) {
    double x[3];
    g->GetPoint(i, x);
    if (std::abs(x[1] - ny * kDl) < 1e-12 && x[0] > 2 * kRe && x[0] < nx * kDl - 2 * kRe) {
      EXPECT_NEAR(coverage->GetComponent(i, 0), 0.5, 0.05) << "x = " << x[0];
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(ParticlesToGrid, DefaultGridFollowsTheFrameAndSurvivesTheXmlWriter) {
  auto frame = lattice_frame(12, 8, at_rest, linear_p);
  vtkNew<vtkMPSParticlesToGrid> f;
  f->SetInputData(frame);
  const auto dir = wcmps::test::scratch_dir("filters_grid_writer");
  const std::string file = (dir / "grid.vti").string();
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputConnection(f->GetOutputPort());
  writer->SetFileName(file.c_str());
  ASSERT_EQ(writer->Write(), 1);
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  // Spacing DL over [0, 12 DL] x [0, 8 DL]: 13 x 9 points.
  EXPECT_EQ(dims[0], 13);
  EXPECT_EQ(dims[1], 9);
  EXPECT_EQ(dims[2], 1);
  EXPECT_NEAR(reader->GetOutput()->GetSpacing()[0], kDl, 1e-15);
  EXPECT_NE(reader->GetOutput()->GetPointData()->GetArray("coverage"), nullptr);
  EXPECT_NE(reader->GetOutput()->GetFieldData()->GetArray("DL"), nullptr);
}

/// The pressure at the points of g by the stock vtkPointInterpolator, fed the frame and
/// vtkMPSKernel (so VTK's own locator finds the neighbours).
vtkSmartPointer<vtkDataArray> stock_pressure(vtkImageData* g, vtkPolyData* frame, double radius,
                                             int correction) {
  vtkNew<vtkImageData> probe;
  probe->DeepCopy(g);
  probe->GetPointData()->Initialize();
  vtkNew<vtkMPSKernel> kernel;
  kernel->SetRadius(radius);
  kernel->SetCorrection(correction);
  vtkNew<vtkPointInterpolator> stock;
  stock->SetInputData(probe);
  stock->SetSourceData(frame);
  stock->SetKernel(kernel);
  stock->AddExcludedArray("kind");
  stock->Update();
  return stock->GetOutput()->GetPointData()->GetArray("pressure");
}

TEST(ParticlesToGrid, AgreesWithVtkPointInterpolatorGivenTheSameKernel) {
  auto frame = lattice_frame(
      20, 20, at_rest, [](double x, double y) { return std::sin(40 * x) * std::cos(25 * y); });
  vtkNew<vtkMPSParticlesToGrid> f;
  f->SetSpacing(0.6 * kDl);
  f->SetMinimumCoverage(0.0);
  f->SetSamplingBounds(0, 20 * kDl, 0, 20 * kDl, 0, 0);
  vtkImageData* g = grid_of(f, frame);

  auto* ours = g->GetPointData()->GetArray("pressure");
  const auto theirs = stock_pressure(g, frame, kRe, vtkMPSKernel::LINEAR);
  ASSERT_NE(theirs, nullptr);
  for (vtkIdType i = 0; i < g->GetNumberOfPoints(); ++i) {
    if (g->GetPointData()->GetArray("vtkValidPointMask")->GetComponent(i, 0) == 0.0) continue;
    EXPECT_NEAR(ours->GetComponent(i, 0), theirs->GetComponent(i, 0), 1e-12);
  }
}

// The probe bins the particles itself (MPSProbe.cxx); a scattered cloud, points outside it,
// both corrections and a radius so small that the bins are enlarged must all give what the
// stock interpolator gives with VTK's locator. 1e-12: the sums differ only in their order.
TEST(ParticlesToGrid, OwnBinsFindWhatVtksLocatorFinds) {
  auto frame = lattice_frame(
      24, 16, at_rest, [](double x, double y) { return std::sin(40 * x) * std::cos(25 * y); });
  // Scatter the particles by up to 0.45 DL (a fixed sequence, no seed to vary).
  vtkPoints* pts = frame->GetPoints();
  for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i) {
    double x[3];
    pts->GetPoint(i, x);
    x[0] += 0.45 * kDl * std::sin(12.9898 * i);
    x[1] += 0.45 * kDl * std::cos(78.233 * i);
    pts->SetPoint(i, x);
  }
  for (const double radius : {kRe, 0.3 * kDl}) {
    for (const int correction : {vtkMPSKernel::SHEPARD, vtkMPSKernel::LINEAR}) {
      SCOPED_TRACE("radius " + std::to_string(radius) + ", correction " +
                   std::to_string(correction));
      vtkNew<vtkMPSParticlesToGrid> f;
      f->SetSpacing(0.43 * kDl);
      f->SetRadius(radius);
      f->SetCorrection(correction);
      f->SetMinimumCoverage(0.0);
      f->SetSamplingBounds(-6 * kDl, 30 * kDl, -6 * kDl, 22 * kDl, 0, 0);
      vtkImageData* g = grid_of(f, frame);
      auto* ours = g->GetPointData()->GetArray("pressure");
      auto* mask = g->GetPointData()->GetArray("vtkValidPointMask");
      const auto theirs = stock_pressure(g, frame, radius, correction);
      ASSERT_NE(theirs, nullptr);
      int valid = 0, empty = 0;
      for (vtkIdType i = 0; i < g->GetNumberOfPoints(); ++i) {
        double x[3];
        g->GetPoint(i, x);
        int near = 0;  // brute force: particles strictly inside the kernel (W > 0)
        for (vtkIdType j = 0; j < pts->GetNumberOfPoints(); ++j) {
          double q[3];
          pts->GetPoint(j, q);
          near += std::hypot(q[0] - x[0], q[1] - x[1]) < radius;
        }
        EXPECT_EQ(mask->GetComponent(i, 0) != 0.0, near > 0) << "at " << x[0] << ", " << x[1];
        if (near == 0) {
          ++empty;
          continue;
        }
        ++valid;
        EXPECT_NEAR(ours->GetComponent(i, 0), theirs->GetComponent(i, 0), 1e-12);
      }
      EXPECT_GT(valid, 300);  // both kinds of point were met
      EXPECT_GT(empty, 300);
    }
  }
}

TEST(MPSKernel, ShepardReproducesAConstantButNotALinearFieldOffTheLattice) {
  auto frame = lattice_frame(20, 20, at_rest, linear_p);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(frame);
  locator->BuildLocator();
  vtkNew<vtkMPSKernel> kernel;
  kernel->SetRadius(kRe);
  kernel->SetCorrectionToShepard();
  kernel->Initialize(locator, frame, frame->GetPointData());
  double x[3] = {10.3 * kDl, 7.8 * kDl, 0.0};
  vtkNew<vtkIdList> ids;
  vtkNew<vtkDoubleArray> weights;
  kernel->ComputeBasis(x, ids);
  ASSERT_GT(kernel->ComputeWeights(x, ids, weights), 0);
  double sum = 0.0, value = 0.0, p[3];
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
    frame->GetPoint(ids->GetId(k), p);
    sum += weights->GetValue(k);
    value += weights->GetValue(k) * linear_p(p[0], p[1]);
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  // The point is off the lattice's symmetry points: Shepard's error is of order the
  // gradient times the offset of the weighted centroid (here above 0.01 Pa).
  EXPECT_GT(std::abs(value - linear_p(x[0], x[1])), 1e-2);
  kernel->SetCorrectionToLinear();
  kernel->ComputeWeights(x, ids, weights);
  value = 0.0;
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
    frame->GetPoint(ids->GetId(k), p);
    value += weights->GetValue(k) * linear_p(p[0], p[1]);
  }
  EXPECT_NEAR(value, linear_p(x[0], x[1]), 1e-9);
}

vtkPolyData* vorticity_of(vtkMPSSpeedVorticity* f, vtkPolyData* frame) {
  f->SetInputData(frame);
  f->Update();
  return f->GetOutput();
}

/// Checks omega at the fluid particles more than re from the water's edge (interior) or all.
void expect_vorticity(vtkPolyData* out, double w, double h, double expected, bool interior,
                      double tol) {
  auto* omega = out->GetPointData()->GetArray("vorticity");
  auto* kind = out->GetPointData()->GetArray("kind");
  ASSERT_NE(omega, nullptr);
  int checked = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double x[3];
    out->GetPoint(i, x);
    if (kind->GetComponent(i, 0) != 0.0) {
      EXPECT_TRUE(std::isnan(omega->GetComponent(i, 0)));
      continue;
    }
    if (interior && inside_by(x[0], x[1], w, h) <= kRe) continue;
    EXPECT_NEAR(omega->GetComponent(i, 0), expected, tol) << "at " << x[0] << ", " << x[1];
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(SpeedVorticity, SolidBodyRotationHasTwiceItsRate) {
  const double omega = 3.0;  // rad/s, anticlockwise
  const int n = 24;
  const double c = 0.5 * n * kDl;
  auto frame = lattice_frame(
      n, n,
      [&](double x, double y) {
        return std::array<double, 2>{-omega * (y - c), omega * (x - c)};
      },
      linear_p);
  for (int gradient : {vtkMPSSpeedVorticity::MPS, vtkMPSSpeedVorticity::CORRECTED}) {
    vtkNew<vtkMPSSpeedVorticity> f;
    f->SetGradient(gradient);
    vtkPolyData* out = vorticity_of(f, frame);
    // Inside the lattice both operators are exact for a linear field (the MPS one because
    // the lattice's second moment is isotropic): round-off only.
    expect_vorticity(out, n * kDl, n * kDl, 2.0 * omega, true, 1e-9);
    // Speed: |omega| r at every particle.
    auto* speed = out->GetPointData()->GetArray("speed");
    double x[3];
    out->GetPoint(0, x);
    EXPECT_NEAR(speed->GetComponent(0, 0), omega * std::hypot(x[0] - c, x[1] - c), 1e-12);
  }
}

TEST(SpeedVorticity, UniformFlowHasNoneAndShearHasMinusItsRate) {
  const int n = 20;
  auto uniform = lattice_frame(
      n, n,
      [](double, double) {
        return std::array<double, 2>{0.7, -0.2};
      },
      linear_p);
  vtkNew<vtkMPSSpeedVorticity> f;
  // Every difference phi_j - phi_i is zero: exactly zero, edges included.
  expect_vorticity(vorticity_of(f, uniform), n * kDl, n * kDl, 0.0, false, 0.0);

  const double k = 5.0;  // 1/s
  auto shear = lattice_frame(
      n, n,
      [&](double, double y) {
        return std::array<double, 2>{k * y, 0.0};
      },
      linear_p);
  expect_vorticity(vorticity_of(f, shear), n * kDl, n * kDl, -k, true, 1e-9);
  // At the free surface the MPS gradient misses the neighbours above: it is not exact there,
  // and the corrected one is (to round-off).
  vtkNew<vtkMPSSpeedVorticity> corrected;
  corrected->SetGradientToCorrected();
  expect_vorticity(vorticity_of(corrected, shear), n * kDl, n * kDl, -k, false, 1e-9);
  vtkPolyData* mps = vorticity_of(f, shear);
  auto* om = mps->GetPointData()->GetArray("vorticity");
  double worst = 0.0;
  for (vtkIdType i = 0; i < mps->GetNumberOfPoints(); ++i) {
    worst = std::max(worst, std::abs(om->GetComponent(i, 0) + k));
  }
  EXPECT_GT(worst, 0.1 * k);
}

TEST(SpeedVorticity, WallsAtRestMakeTheNoSlipShear) {
  // Water moving at u = 0.1 over a row of wall particles at rest: u grows upwards across the
  // wall, du/dy > 0, so omega = -du/dy < 0 in the water within re of the wall; further up
  // the flow is uniform and omega is exactly 0.
  const int n = 16;
  auto frame = lattice_frame(
      n, n,
      [](double, double) {
        return std::array<double, 2>{0.1, 0.0};
      },
      linear_p, true);
  vtkNew<vtkMPSSpeedVorticity> f;
  vtkPolyData* out = vorticity_of(f, frame);
  auto* om = out->GetPointData()->GetArray("vorticity");
  auto* kind = out->GetPointData()->GetArray("kind");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double x[3];
    out->GetPoint(i, x);
    if (kind->GetComponent(i, 0) != 0.0) continue;
    if (x[1] < kDl && x[0] > kRe && x[0] < n * kDl - kRe) {
      EXPECT_LT(om->GetComponent(i, 0), 0.0);
    }
    if (x[1] > 1.1 * kRe && x[1] < n * kDl - kRe) {
      EXPECT_NEAR(om->GetComponent(i, 0), 0.0, 1e-12);
    }
  }
}

// Sections, averages, free surface and polylines on a box of water [0, 40 DL] x [0, 30 DL]
// with the linear fields u = 2 y + 0.5 x, v = -x + 0.3 y + 0.1 and the linear pressure.
constexpr int kBoxX = 40, kBoxY = 30;
std::array<double, 2> linear_u(double x, double y) {
  return {2 * y + 0.5 * x, -x + 0.3 * y + 0.1};
}

// The edge of the water found from the coverage sits within a tenth of DL of the continuum
// edge: the coverage there ripples by +-0.005 along the lattice and falls by ~0.15 per DL.
constexpr double kEdgeTolerance = 0.1 * kDl;

TEST(Sections, ProfilesInTheBedFrameFromBedToSurface) {
  auto frame = lattice_frame(kBoxX, kBoxY, linear_u, linear_p);
  const double pi = std::acos(-1.0);
  const double theta = 40.0 * pi / 180.0;
  vtkNew<vtkMPSSections> f;
  f->AddSection("V", 20 * kDl, 0.0, 0.0, 1.0);  // vertical: bottom to surface
  f->AddSection("T", 10 * kDl, 0.0, std::sin(theta), std::cos(theta));  // 40 deg from vertical
  f->AddSection("dry", -1.0, 0.0, 0.0, 1.0);                            // misses the water
  f->SetInputData(frame);
  f->Update();
  vtkPolyData* prof = f->GetOutput();
  vtkTable* sum = f->GetSummary();
  ASSERT_EQ(sum->GetNumberOfRows(), 3);
  EXPECT_EQ(prof->GetNumberOfPoints(), 2 * 51);
  EXPECT_EQ(prof->GetNumberOfLines(), 2);
  // The vertical section spans the whole depth 30 DL.
  EXPECT_NEAR(sum->GetValueByName(0, "H").ToDouble(), kBoxY * kDl, kEdgeTolerance);
  EXPECT_NEAR(sum->GetValueByName(0, "y0").ToDouble(), 0.0, kEdgeTolerance);
  // The tilted one leaves through the side x = 40 DL: H = 30 DL / cos(theta) is past it, so
  // H = (40 - 10) DL / sin(theta) or 30 DL / cos(theta), whichever is shorter.
  const double h_t = std::min(30 * kDl / std::sin(theta), 30 * kDl / std::cos(theta));
  EXPECT_NEAR(sum->GetValueByName(1, "H").ToDouble(), h_t, kEdgeTolerance / std::sin(theta));
  EXPECT_EQ(sum->GetValueByName(2, "H").ToDouble(), 0.0);
  EXPECT_TRUE(std::isnan(sum->GetValueByName(2, "mean_u_along").ToDouble()));

  auto* y = prof->GetPointData()->GetArray("Y");
  auto* h = prof->GetPointData()->GetArray("h");
  auto* sec = prof->GetPointData()->GetArray("section");
  auto* ua = prof->GetPointData()->GetArray("u_along");
  auto* un = prof->GetPointData()->GetArray("u_normal");
  auto* p = prof->GetPointData()->GetArray("pressure");
  for (vtkIdType i = 0; i < prof->GetNumberOfPoints(); ++i) {
    double x[3];
    prof->GetPoint(i, x);
    const int k = static_cast<int>(sec->GetComponent(i, 0));
    const double n[2] = {k == 0 ? 0.0 : std::sin(theta), k == 0 ? 1.0 : std::cos(theta)};
    const double t[2] = {n[1], -n[0]};
    const double height = sum->GetValueByName(k, "H").ToDouble();
    EXPECT_NEAR(h->GetComponent(i, 0), y->GetComponent(i, 0) * height, 1e-12);
    const auto u = linear_u(x[0], x[1]);
    // The bed-frame components are (u, v) turned by the section's angle; linear fields are
    // reproduced to round-off, ends included (the linear correction holds on the edge).
    EXPECT_NEAR(ua->GetComponent(i, 0), u[0] * t[0] + u[1] * t[1], 1e-9);
    EXPECT_NEAR(un->GetComponent(i, 0), u[0] * n[0] + u[1] * n[1], 1e-9);
    EXPECT_NEAR(p->GetComponent(i, 0), linear_p(x[0], x[1]), 1e-8);
  }
  // Depth averages of linear profiles: the value at mid-depth, exactly.
  for (int k = 0; k < 2; ++k) {
    const double xm =
        0.5 * (sum->GetValueByName(k, "x0").ToDouble() + sum->GetValueByName(k, "x1").ToDouble());
    const double ym =
        0.5 * (sum->GetValueByName(k, "y0").ToDouble() + sum->GetValueByName(k, "y1").ToDouble());
    const double n[2] = {k == 0 ? 0.0 : std::sin(theta), k == 0 ? 1.0 : std::cos(theta)};
    const auto u = linear_u(xm, ym);
    EXPECT_NEAR(sum->GetValueByName(k, "mean_u_along").ToDouble(), u[0] * n[1] - u[1] * n[0], 1e-9);
    EXPECT_NEAR(sum->GetValueByName(k, "mean_pressure").ToDouble(), linear_p(xm, ym), 1e-8);
  }
}

// With no sections added, the filter takes the frame's own (the case's [[section]]s, which
// `wcmps run` writes as SectionNames and SectionLines) and gives what adding them gives.
TEST(Sections, TheFramesOwnSectionsByDefault) {
  auto frame = lattice_frame(kBoxX, kBoxY, linear_u, linear_p);
  vtkNew<vtkStringArray> names;
  names->SetName("SectionNames");
  names->InsertNextValue("V");
  names->InsertNextValue("T");
  vtkNew<vtkDoubleArray> lines;
  lines->SetName("SectionLines");
  lines->SetNumberOfComponents(4);
  lines->InsertNextTuple4(20 * kDl, 0.0, 0.0, 1.0);
  lines->InsertNextTuple4(10 * kDl, 0.0, 0.6, 0.8);
  frame->GetFieldData()->AddArray(names);
  frame->GetFieldData()->AddArray(lines);

  vtkNew<vtkMPSSections> given;
  given->AddSection("V", 20 * kDl, 0.0, 0.0, 1.0);
  given->AddSection("T", 10 * kDl, 0.0, 0.6, 0.8);
  given->SetInputData(frame);
  given->Update();
  vtkNew<vtkMPSSections> own;
  own->SetInputData(frame);
  own->Update();
  ASSERT_EQ(own->GetSummary()->GetNumberOfRows(), 2);
  EXPECT_EQ(own->GetSummary()->GetValueByName(1, "section").ToString(), "T");
  ASSERT_EQ(own->GetOutput()->GetNumberOfPoints(), given->GetOutput()->GetNumberOfPoints());
  auto* a = own->GetOutput()->GetPointData()->GetArray("u_along");
  auto* b = given->GetOutput()->GetPointData()->GetArray("u_along");
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
    EXPECT_EQ(a->GetComponent(i, 0), b->GetComponent(i, 0));
  }

  // A frame with neither: an error, no output.
  auto bare = lattice_frame(kBoxX, kBoxY, linear_u, linear_p);
  vtkNew<vtkMPSSections> none;
  none->SetInputData(bare);
  none->Update();
  EXPECT_EQ(none->GetOutput()->GetNumberOfPoints(), 0);
}

void add_block_outline(vtkPolyData* frame, const double c[2], const double a[2],
                       const double g[2]) {
  vtkNew<vtkDoubleArray> outline;
  outline->SetName("BlockOutline");
  outline->SetNumberOfComponents(3);
  outline->InsertNextTuple3(c[0], c[1], 0.0);
  outline->InsertNextTuple3(a[0], a[1], 0.0);
  outline->InsertNextTuple3(g[0], g[1], 0.0);
  frame->GetFieldData()->AddArray(outline);
}

TEST(SectionAverages, StationsAlongTheTopEdgeInTheBedNormal) {
  auto frame = lattice_frame(kBoxX, kBoxY, linear_u, linear_p);
  // A block (not made of particles here) with C, A on a horizontal top edge of length 5 DL
  // and its face CG at 45 degrees down to the right: sections point up and to the right.
  const double c[2] = {5 * kDl, 10 * kDl}, a[2] = {10 * kDl, 10 * kDl}, g[2] = {10 * kDl, 5 * kDl};
  add_block_outline(frame, c, a, g);
  vtkNew<vtkMPSSectionAverages> f;
  f->SetMaximumXOverL(2.0);
  f->SetNumberOfStations(5);
  f->SetInputData(frame);
  f->Update();
  vtkTable* t = f->GetOutput();
  ASSERT_EQ(t->GetNumberOfRows(), 5);
  const double n = std::sqrt(0.5);
  for (vtkIdType r = 0; r < 5; ++r) {
    EXPECT_NEAR(t->GetValueByName(r, "X_over_L").ToDouble(), 0.5 * r, 1e-12);
    EXPECT_NEAR(t->GetValueByName(r, "X").ToDouble(), 0.5 * r * 5 * kDl, 1e-12);
    // The section passes through its station, in the direction (n, n).
    const double sx = c[0] + 0.5 * r * 5 * kDl, sy = c[1];
    const double x0 = t->GetValueByName(r, "x0").ToDouble(),
                 y0 = t->GetValueByName(r, "y0").ToDouble();
    EXPECT_NEAR((x0 - sx) * n - (y0 - sy) * n, 0.0, 1e-12);
    const double xm = 0.5 * (x0 + t->GetValueByName(r, "x1").ToDouble());
    const double ym = 0.5 * (y0 + t->GetValueByName(r, "y1").ToDouble());
    const auto u = linear_u(xm, ym);
    EXPECT_NEAR(t->GetValueByName(r, "mean_u_along").ToDouble(), (u[0] - u[1]) * n, 1e-9);
    EXPECT_NEAR(t->GetValueByName(r, "mean_u_normal").ToDouble(), (u[0] + u[1]) * n, 1e-9);
  }
}

double eta_at(vtkPolyData* s, double x) {
  auto* xs = s->GetPointData()->GetArray("x");
  auto* eta = s->GetPointData()->GetArray("eta");
  for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i) {
    if (std::abs(xs->GetComponent(i, 0) - x) < 1e-12) return eta->GetComponent(i, 0);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(FreeSurface, StillTankIsFlatAndSplashIsIgnored) {
  auto frame = lattice_frame(kBoxX, kBoxY, at_rest, linear_p);
  // A lone droplet and a clump of four particles above the surface.
  auto* pts = frame->GetPoints();
  auto* vel = frame->GetPointData()->GetArray("velocity");
  auto* pr = frame->GetPointData()->GetArray("pressure");
  auto* kind = vtkUnsignedCharArray::SafeDownCast(frame->GetPointData()->GetArray("kind"));
  const double extra[5][2] = {{10.5, 40.5}, {25.5, 36.5}, {26.5, 36.5}, {25.5, 37.5}, {26.5, 37.5}};
  for (const auto& e : extra) {
    pts->InsertNextPoint(e[0] * kDl, e[1] * kDl, 0.0);
    vel->InsertNextTuple3(0.0, 0.0, 0.0);
    pr->InsertNextTuple1(0.0);
    kind->InsertNextValue(0);
  }
  vtkNew<vtkMPSFreeSurface> f;
  f->SetInputData(frame);
  f->Update();
  vtkPolyData* s = f->GetOutput();
  // Every DL from the leftmost particle to the rightmost.
  EXPECT_EQ(s->GetNumberOfPoints(), kBoxX);
  auto* eta = s->GetPointData()->GetArray("eta");
  for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i) {
    double x[3];
    s->GetPoint(i, x);
    // Within re of a side of the water (a wall, here a corner of it) the fluid's coverage
    // misses that side too: the surface reads low there, by 0.34 DL on the last column.
    const bool side = std::min(x[0], kBoxX * kDl - x[0]) < kRe;
    EXPECT_NEAR(eta->GetComponent(i, 0), kBoxY * kDl, side ? 0.4 * kDl : kEdgeTolerance)
        << "station " << i;
  }
  // Gauges: only the stations asked for.
  vtkNew<vtkMPSFreeSurface> g;
  g->AddGauge(10.5 * kDl);
  g->AddGauge(26 * kDl);
  g->SetInputData(frame);
  g->Update();
  ASSERT_EQ(g->GetOutput()->GetNumberOfPoints(), 2);
  EXPECT_NEAR(eta_at(g->GetOutput(), 26 * kDl), kBoxY * kDl, kEdgeTolerance);
}

TEST(FreeSurface, TiltedSurfaceHasItsSlope) {
  // Particles of the box below the line y = 20 DL + 0.25 x.
  const double slope = 0.25;
  auto frame = lattice_frame(kBoxX, kBoxY, at_rest, linear_p);
  vtkNew<vtkPolyData> cut;
  {
    vtkNew<vtkPoints> pts;
    vtkNew<vtkUnsignedCharArray> kind;
    kind->SetName("kind");
    for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i) {
      double x[3];
      frame->GetPoint(i, x);
      if (x[1] < 20 * kDl + slope * x[0]) {
        pts->InsertNextPoint(x);
        kind->InsertNextValue(0);
      }
    }
    cut->SetPoints(pts);
    cut->GetPointData()->AddArray(kind);
    cut->GetFieldData()->ShallowCopy(frame->GetFieldData());
  }
  vtkNew<vtkMPSFreeSurface> f;
  f->SetInputData(cut);
  f->Update();
  vtkPolyData* s = f->GetOutput();
  // Least-squares line through eta(x) away from the side walls (2 re).
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i) {
    double x[3];
    s->GetPoint(i, x);
    if (x[0] < 2 * kRe || x[0] > kBoxX * kDl - 2 * kRe) continue;
    sx += x[0], sy += x[1], sxx += x[0] * x[0], sxy += x[0] * x[1], n += 1;
  }
  const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double a0 = (sy - b * sx) / n;
  // The particles are a staircase of the line (steps of DL every 4 DL): the fit's slope is
  // within 2 % of it and its height within a quarter DL.
  EXPECT_NEAR(b, slope, 0.02 * slope);
  EXPECT_NEAR(a0, 20 * kDl, 0.25 * kDl);
}

TEST(PolylineProbe, LinearPressureAlongTheBlockTop) {
  auto frame = lattice_frame(kBoxX, kBoxY, at_rest, linear_p);
  const double c[2] = {5 * kDl, 10 * kDl}, a[2] = {15 * kDl, 12 * kDl}, g[2] = {15 * kDl, 5 * kDl};
  add_block_outline(frame, c, a, g);
  vtkNew<vtkMPSPolylineProbe> f;
  f->SetNumberOfSamples(11);
  f->SetInputData(frame);
  f->Update();
  vtkPolyData* out = f->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 11);
  auto* p = out->GetPointData()->GetArray("pressure");
  auto* arc = out->GetPointData()->GetArray("arc_length");
  const double len = std::hypot(a[0] - c[0], a[1] - c[1]);
  for (vtkIdType i = 0; i < 11; ++i) {
    double x[3];
    out->GetPoint(i, x);
    EXPECT_NEAR(arc->GetComponent(i, 0), 0.1 * i * len, 1e-12);
    EXPECT_NEAR(x[0], c[0] + 0.1 * i * (a[0] - c[0]), 1e-12);
    EXPECT_NEAR(p->GetComponent(i, 0), linear_p(x[0], x[1]), 1e-8);
  }
}

TEST(WaveGauges, TheSolversGaugesEqualTheFiltersOnTheSameParticles) {
  using namespace wcmps;
  const CaseSpec spec = parse_case_text(
      test::minimal_case_text() + "\n[gauges]\nx = [0.05, 0.1, 0.15, 0.5]\ninterval = 0.002\n",
      "gauges.toml");
  Scene scene = build_scene(spec);
  const Vec2 lo = scene.domain_lo, hi = scene.domain_hi;
  const Simulation sim(spec, std::move(scene));
  WaveGauges gauges(spec, lo, hi);
  ASSERT_TRUE(gauges.due(0.0));
  gauges.sample(sim);
  EXPECT_FALSE(gauges.due(0.0019));
  EXPECT_TRUE(gauges.due(0.002));
  ASSERT_EQ(gauges.sample_count(), 1u);
  const std::vector<double> row(gauges.sample_values(0), gauges.sample_values(0) + 5);
  ASSERT_EQ(row.size(), 5u);

  // The same fluid particles as a frame, through vtkMPSFreeSurface with the same gauges.
  const ParticleSet& ps = sim.particles();
  vtkNew<vtkPolyData> frame;
  vtkNew<vtkPoints> pts;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    pts->InsertNextPoint(ps.now.x[i], ps.now.y[i], 0.0);
  }
  frame->SetPoints(pts);
  add_value(frame->GetFieldData(), "DL", spec.dl);
  add_value(frame->GetFieldData(), "re", spec.re());
  vtkNew<vtkMPSFreeSurface> f;
  for (const double x : spec.gauges.x) f->AddGauge(x);
  f->SetInputData(frame);
  f->Update();
  // The gauge at x = 0.5 is outside the tank: no water, NaN in the solver, no point here.
  ASSERT_EQ(f->GetOutput()->GetNumberOfPoints(), 3);
  EXPECT_TRUE(std::isnan(row[4]));
  for (int k = 0; k < 3; ++k) {
    // One algorithm: equal up to the bisection's resolution (DL/1000) where sums of W taken
    // in another order fall either side of the threshold.
    EXPECT_NEAR(row[static_cast<size_t>(k) + 1],
                eta_at(f->GetOutput(), spec.gauges.x[static_cast<size_t>(k)]), 2e-3 * spec.dl);
    // Water 0.1 m deep, the column compressed by the hydrostatic start by a fraction of DL.
    EXPECT_NEAR(row[static_cast<size_t>(k) + 1], 0.1, 0.2 * spec.dl);
  }
  EXPECT_EQ(gauges.csv().substr(0, gauges.csv().find('\n')),
            "time [s],eta at x = 0.05 m [m],eta at x = 0.1 m [m],eta at x = 0.15 m [m],"
            "eta at x = 0.5 m [m]");
}

TEST(Series, EveryFilterFollowsTheTimeRequestsOfAPvdReader) {
  // Three frames whose water is 20, 22 and 24 DL deep, as series.pvd at t = 0, 0.1, 0.2.
  const auto dir = wcmps::test::scratch_dir("filters_series");
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
      "<Collection>\n";
  for (int k = 0; k < 3; ++k) {
    auto frame = lattice_frame(kBoxX, 20 + 2 * k, linear_u, linear_p);
    const std::string name = "frame_" + std::to_string(k) + ".vtp";
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(frame);
    w->SetDataModeToBinary();  // as wcmps writes frames (docs/running.md: appended data breaks)
    w->SetFileName((dir / name).string().c_str());
    ASSERT_EQ(w->Write(), 1);
    pvd += "<DataSet timestep=\"" + std::to_string(0.1 * k) + "\" part=\"0\" file=\"" + name +
           "\"/>\n";
  }
  pvd += "</Collection>\n</VTKFile>\n";
  std::ofstream((dir / "series.pvd").string()) << pvd;

  vtkNew<vtkPVDReader> reader;
  reader->SetFileName((dir / "series.pvd").string().c_str());
  reader->UpdateInformation();
  vtkInformation* info = reader->GetOutputInformation(0);
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 3);

  vtkNew<vtkMPSSpeedVorticity> sv;
  sv->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkMPSParticlesToGrid> grid;
  grid->SetInputConnection(sv->GetOutputPort());
  vtkNew<vtkMPSSections> sections;
  sections->SetInputConnection(reader->GetOutputPort());
  sections->AddSection("V", 20 * kDl, 0.0, 0.0, 1.0);
  vtkNew<vtkMPSFreeSurface> surface;
  surface->SetInputConnection(reader->GetOutputPort());
  surface->AddGauge(20 * kDl);
  vtkNew<vtkMPSPolylineProbe> line;
  line->SetInputConnection(reader->GetOutputPort());
  line->AddPoint(5 * kDl, 5 * kDl);
  line->AddPoint(15 * kDl, 5 * kDl);
  for (int k = 0; k < 3; ++k) {
    const double t = 0.1 * k, depth = (20 + 2 * k) * kDl;
    grid->UpdateTimeStep(t);
    surface->UpdateTimeStep(t);
    sections->UpdateTimeStep(t);
    line->UpdateTimeStep(t);
    // Each output is the frame of its time: the grid's default box grows with the water,
    // the gauge and the section's depth follow it.
    int dims[3];
    grid->GetOutput()->GetDimensions(dims);
    EXPECT_EQ(dims[1], 20 + 2 * k + 1) << "t = " << t;
    EXPECT_NE(grid->GetOutput()->GetPointData()->GetArray("vorticity"), nullptr);
    EXPECT_NEAR(eta_at(surface->GetOutput(), 20 * kDl), depth, kEdgeTolerance) << "t = " << t;
    EXPECT_NEAR(sections->GetSummary()->GetValueByName(0, "H").ToDouble(), depth, kEdgeTolerance);
    EXPECT_EQ(line->GetOutput()->GetNumberOfPoints(), 101);
    EXPECT_DOUBLE_EQ(surface->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()),
                     t);
  }
}

}  // namespace
