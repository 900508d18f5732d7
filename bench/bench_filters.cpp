// Google Benchmark of the grid interpolation: vtkMPSParticlesToGrid (its own loop: one
// neighbour search per grid point gives the weights and the coverage) against VTK's
// vtkPointInterpolator with the same kernel (vtkMPSKernel), which interpolates but gives no
// coverage, so the filter would need a second search per point for it.
//
// The particles: a square lattice of W x H particles (default 300 x 150 = 45,000, about case
// I's fluid) at DL = 5 mm, with velocity and pressure; the grid: spacing 2 mm over the water
// (the study's contour grid). Run:
//   build/bin/bench_filters [--benchmark_repetitions=5 --benchmark_report_aggregates_only]
// The smoke test (ctest -R bench) runs a tiny lattice once.

#include <benchmark/benchmark.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMPSKernel.h>
#include <vtkMPSParticlesToGrid.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointInterpolator.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace {

constexpr double kDl = 0.005;
int g_width = 300, g_height = 150;

vtkSmartPointer<vtkPolyData> lattice() {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> velocity, pressure;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  pressure->SetName("pressure");
  for (int j = 0; j < g_height; ++j) {
    for (int i = 0; i < g_width; ++i) {
      const double x = (i + 0.5) * kDl, y = (j + 0.5) * kDl;
      points->InsertNextPoint(x, y, 0.0);
      velocity->InsertNextTuple3(std::sin(10 * x), std::cos(7 * y), 0.0);
      pressure->InsertNextValue(9810.0 * (g_height * kDl - y));
    }
  }
  auto frame = vtkSmartPointer<vtkPolyData>::New();
  frame->SetPoints(points);
  frame->GetPointData()->AddArray(velocity);
  frame->GetPointData()->AddArray(pressure);
  for (const auto& [name, value] : {std::pair<const char*, double>{"DL", kDl}, {"re", 3.5 * kDl}}) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    frame->GetFieldData()->AddArray(a);
  }
  return frame;
}

void set_threads(const benchmark::State& state) {
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(static_cast<int>(state.range(0)));
}

void ParticlesToGrid(benchmark::State& state) {
  set_threads(state);
  auto frame = lattice();
  vtkNew<vtkMPSParticlesToGrid> f;
  f->SetInputData(frame);
  f->SetSpacing(0.002);
  vtkIdType points = 0;
  for (auto _ : state) {
    f->Modified();
    f->Update();
    points = f->GetOutput()->GetNumberOfPoints();
  }
  state.counters["grid_points"] = static_cast<double>(points);
  state.counters["points_per_s"] = benchmark::Counter(
      static_cast<double>(points), benchmark::Counter::kIsIterationInvariantRate);
}

void StockPointInterpolator(benchmark::State& state) {
  set_threads(state);
  auto frame = lattice();
  vtkNew<vtkMPSParticlesToGrid> shape;  // the same grid, to probe
  shape->SetInputData(frame);
  shape->SetSpacing(0.002);
  shape->Update();
  vtkNew<vtkImageData> grid;
  grid->CopyStructure(shape->GetOutput());
  vtkNew<vtkMPSKernel> kernel;
  kernel->SetRadius(3.5 * kDl);
  vtkNew<vtkPointInterpolator> stock;
  stock->SetInputData(grid);
  stock->SetSourceData(frame);
  stock->SetKernel(kernel);
  for (auto _ : state) {
    stock->Modified();
    stock->Update();
  }
  state.counters["grid_points"] = static_cast<double>(grid->GetNumberOfPoints());
  state.counters["points_per_s"] =
      benchmark::Counter(static_cast<double>(grid->GetNumberOfPoints()),
                         benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(ParticlesToGrid)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(StockPointInterpolator)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  // --lattice=WxH before Google Benchmark's own flags.
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a.rfind("--lattice=", 0) == 0) {
      g_width = std::atoi(a.c_str() + 10);
      const auto x = a.find('x');
      g_height = x == std::string::npos ? g_width : std::atoi(a.c_str() + x + 1);
      for (int m = k; m + 1 < argc; ++m) argv[m] = argv[m + 1];
      --argc;
      --k;
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
