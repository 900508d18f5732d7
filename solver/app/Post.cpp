#include "app/Post.h"

#include <vtkImageData.h>
#include <vtkMPSFreeSurface.h>
#include <vtkMPSParticlesToGrid.h>
#include <vtkMPSPolylineProbe.h>
#include <vtkMPSSectionAverages.h>
#include <vtkMPSSections.h>
#include <vtkMPSSpeedVorticity.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "core/Error.h"
#include "core/ExitCodes.h"
#include "core/TerminalProgress.h"
#include "core/Version.h"
#include "io/AtomicFile.h"
#include "io/FrameReader.h"
#include "io/RunDirectory.h"
#include "io/RunLock.h"
#include "io/SeriesIndex.h"
#include "io/VtkXmlFile.h"
#include "scene/CaseParser.h"
#include "simulation/WaterCavity.h"

namespace fs = std::filesystem;

namespace wcmps {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

/// A CSV table built row by row and written atomically at the end.
struct Csv {
  std::string text;
  explicit Csv(const std::string& header) : text(header + "\n") {}
  void row(const std::vector<std::string>& cells) {
    for (size_t k = 0; k < cells.size(); ++k) text += (k ? "," : "") + cells[k];
    text += "\n";
  }
};

double column(vtkTable* t, vtkIdType r, const char* name) {
  return t->GetValueByName(r, name).ToDouble();
}

double component(vtkPolyData* p, const char* name, vtkIdType i, int c = 0) {
  vtkDataArray* a = p->GetPointData()->GetArray(name);
  return a ? a->GetComponent(i, c) : std::nan("");
}

/// A point of the block by name (C, A, G, or the midpoints B of CA and F of AG), from the
/// frame's BlockOutline.
bool block_point(vtkPolyData* frame, const std::string& name, double out[2]) {
  vtkDataArray* o = frame->GetFieldData()->GetArray("BlockOutline");
  if (!o || o->GetNumberOfTuples() < 3) return false;
  const auto corner = [&](int k, int c) { return o->GetComponent(k, c); };
  for (int c = 0; c < 2; ++c) {
    if (name == "C") out[c] = corner(0, c);
    if (name == "A") out[c] = corner(1, c);
    if (name == "G") out[c] = corner(2, c);
    if (name == "B") out[c] = 0.5 * (corner(0, c) + corner(1, c));
    if (name == "F") out[c] = 0.5 * (corner(1, c) + corner(2, c));
  }
  return true;
}

/// The water cavity (simulation/WaterCavity.h) of a frame: its particles by kind and the block
/// where it is now.
CavityMeasure measure_cavity(const WaterCavity& cavity, vtkPolyData* frame, const fs::path& file) {
  vtkDataArray* kinds = frame->GetPointData()->GetArray("kind");
  if (!kinds) {
    throw IoError(file.string() +
                  ": the cavity needs the particles' kind in the frames "
                  "([output] fields)");
  }
  const vtkIdType n = frame->GetNumberOfPoints();
  std::vector<double> x(n), y(n);
  std::vector<ParticleKind> kind(n);
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    frame->GetPoint(i, p);
    x[i] = p[0];
    y[i] = p[1];
    kind[i] = static_cast<ParticleKind>(static_cast<int>(kinds->GetComponent(i, 0)));
  }
  std::vector<Vec2> outline;
  if (vtkDataArray* o = frame->GetFieldData()->GetArray("BlockOutline")) {
    for (vtkIdType k = 0; k < o->GetNumberOfTuples(); ++k) {
      outline.push_back({o->GetComponent(k, 0), o->GetComponent(k, 1)});
    }
  }
  return cavity.measure(x.data(), y.data(), kind.data(), n, outline);
}

class Stopwatch {
 public:
  void start() { t0_ = std::chrono::steady_clock::now(); }
  double stop(const std::string& product) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    seconds[product].push_back(s);
    return s;
  }
  std::map<std::string, std::vector<double>> seconds;

 private:
  std::chrono::steady_clock::time_point t0_;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int post_command(const PostOptions& o) {
  const fs::path run(o.run_dir);
  const fs::path pvd = run / RunFiles::kSeries, case_copy = run / RunFiles::kCase;
  std::error_code ec;
  if (const std::string problem = run_directory_problem(run); !problem.empty()) {
    std::cerr << "wcmps: error: " << problem << '\n';
    return exit_code::kUsage;
  }
  CaseSpec spec;
  std::vector<SeriesEntry> series;
  try {
    // Another case file may ask for other products of the same run (its scene is not rebuilt:
    // the frames are the run's).
    spec = parse_case_file(o.case_file.empty() ? case_copy.string() : o.case_file);
    series = read_series(pvd);
  } catch (const CaseError& e) {
    std::cerr << "wcmps: error: " << e.what() << '\n';
    return exit_code::kBadCase;
  } catch (const IoError& e) {
    std::cerr << "wcmps: error: " << e.what() << '\n';
    return exit_code::kIo;
  }
  const PostSpec& post = spec.post;
  if (post.products.empty()) {
    std::cout << "The case asks for no post-processing products: nothing to do (add a [post] "
                 "table, docs/case-format.md).\n";
    return exit_code::kOk;
  }
  std::vector<double> times =
      o.times ? *o.times : (!post.times.empty() ? post.times : spec.output_times);
  if (times.empty()) {
    for (const auto& e : series) times.push_back(e.time);
  }
  std::vector<const SeriesEntry*> frames;
  for (const double t : times) {
    const SeriesEntry* e = frame_at(series, t);
    if (!e) {
      std::cerr << "wcmps: error: " << pvd.string() << " has no frame at t = " << t
                << " s (frames from " << (series.empty() ? 0.0 : series.front().time) << " to "
                << (series.empty() ? 0.0 : series.back().time) << " s)\n";
      return exit_code::kUsage;
    }
    frames.push_back(e);
  }

  const int threads =
      o.threads ? *o.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  // ParaView's VTK defaults to sequential vtkSMPTools; its std::thread backend is built in.
  const bool smp = vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(threads);

  const fs::path out = o.output_dir.empty() ? run / RunFiles::kPost : fs::path(o.output_dir);
  // Writing into the run directory: it must not be a run's that is still going (io/RunLock.h).
  std::optional<RunLock> lock;
  if (o.output_dir.empty()) {
    try {
      lock.emplace(run, "wcmps post " + run.string());
    } catch (const IoError& e) {
      std::cerr << "wcmps: error: " << e.what() << '\n';
      return exit_code::kIo;
    }
  }
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out)) {
    std::cerr << "wcmps: error: " << out.string() << ": cannot create the output directory\n";
    return exit_code::kIo;
  }

  Csv sections_csv(
      "time [s],section,Y [-],h [m],x [m],y [m],u_along [m/s],u_normal [m/s],u [m/s],v [m/s],"
      "pressure [Pa],coverage [-]");
  Csv summary_csv(
      "time [s],section,x0 [m],y0 [m],x1 [m],y1 [m],H [m],mean_u_along [m/s],"
      "mean_u_normal [m/s],mean_speed [m/s],mean_pressure [Pa]");
  Csv averages_csv(
      "time [s],X/L [-],X [m],x0 [m],y0 [m],H [m],mean_u_along [m/s],mean_u_normal [m/s],"
      "mean_speed [m/s]");
  Csv surface_csv("time [s],x [m],eta [m]");
  Csv lines_csv(
      "time [s],line,arc_length [m],arc_fraction [-],x [m],y [m],pressure [Pa],u [m/s],"
      "v [m/s]");
  std::string grid_pvd;
  nlohmann::json files = nlohmann::json::array();
  Stopwatch clock;
  double grid_bounds[6] = {1, -1, 1, -1, 0, 0};

  TerminalProgress progress;
  const auto started = std::chrono::steady_clock::now();
  try {
    for (size_t k = 0; k < frames.size(); ++k) {
      const SeriesEntry& e = *frames[k];
      const fs::path frame_file = run / e.file;
      clock.start();
      const vtkSmartPointer<vtkPolyData> frame = read_frame_file(frame_file);
      clock.stop("read");
      const std::string t = num(e.time);

      if (post.wants(PostProduct::Grid)) {
        clock.start();
        vtkNew<vtkMPSSpeedVorticity> sv;
        sv->SetInputData(frame);
        if (post.corrected_gradient) sv->SetGradientToCorrected();
        vtkNew<vtkMPSParticlesToGrid> grid;
        grid->SetInputConnection(sv->GetOutputPort());
        if (!(grid_bounds[0] < grid_bounds[1])) {
          // One grid for every time: the box of all particles (the tank) at the first time.
          frame->GetBounds(grid_bounds);
        }
        vtkDataArray* dl_array = frame->GetFieldData()->GetArray("DL");
        if (!dl_array) throw IoError(frame_file.string() + ": no DL field data: not a wcmps frame");
        const double dl = dl_array->GetComponent(0, 0);
        grid->SetSpacing(post.grid_spacing > 0.0 ? post.grid_spacing : dl);
        grid->SetSamplingBounds(grid_bounds);
        for (const auto& f : post.grid_fields) grid->AddArrayName(f.c_str());
        grid->Update();
        clock.stop("grid");
        char name[64];
        std::snprintf(name, sizeof name, "grid_%06zu.vti", k);
        const fs::path file = out / name;
        vtkNew<vtkXMLImageDataWriter> w;
        w->SetInputConnection(grid->GetOutputPort());
        w->SetDataModeToBinary();
        write_vtk_xml_atomically(*w, file);
        grid_pvd +=
            "    <DataSet timestep=\"" + t + "\" group=\"\" part=\"0\" file=\"" + name + "\"/>\n";
      }
      if (post.wants(PostProduct::Sections)) {
        clock.start();
        vtkNew<vtkMPSSections> f;
        for (const auto& s : spec.sections) {
          f->AddSection(s.name.c_str(), s.origin.x, s.origin.y, s.direction.x, s.direction.y);
        }
        f->SetNumberOfSamples(post.section_samples);
        f->SetInputData(frame);
        f->Update();
        clock.stop("sections");
        vtkPolyData* p = f->GetOutput();
        for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i) {
          const int s = static_cast<int>(component(p, "section", i));
          double x[3];
          p->GetPoint(i, x);
          sections_csv.row({t, spec.sections[static_cast<size_t>(s)].name,
                            num(component(p, "Y", i)), num(component(p, "h", i)), num(x[0]),
                            num(x[1]), num(component(p, "u_along", i)),
                            num(component(p, "u_normal", i)), num(component(p, "velocity", i, 0)),
                            num(component(p, "velocity", i, 1)), num(component(p, "pressure", i)),
                            num(component(p, "coverage", i))});
        }
        vtkTable* sum = f->GetSummary();
        for (vtkIdType r = 0; r < sum->GetNumberOfRows(); ++r) {
          summary_csv.row({t, sum->GetValueByName(r, "section").ToString(),
                           num(column(sum, r, "x0")), num(column(sum, r, "y0")),
                           num(column(sum, r, "x1")), num(column(sum, r, "y1")),
                           num(column(sum, r, "H")), num(column(sum, r, "mean_u_along")),
                           num(column(sum, r, "mean_u_normal")), num(column(sum, r, "mean_speed")),
                           num(column(sum, r, "mean_pressure"))});
        }
      }
      if (post.wants(PostProduct::SectionAverages)) {
        clock.start();
        vtkNew<vtkMPSSectionAverages> f;
        f->SetMaximumXOverL(post.average_max_x_over_l);
        f->SetNumberOfStations(post.average_stations);
        f->SetNumberOfSamples(post.section_samples);
        if (spec.body) f->SetBedNormal(spec.body->bed_normal.x, spec.body->bed_normal.y);
        f->SetInputData(frame);
        f->Update();
        clock.stop("section_averages");
        vtkTable* a = f->GetOutput();
        for (vtkIdType r = 0; r < a->GetNumberOfRows(); ++r) {
          averages_csv.row({t, num(column(a, r, "X_over_L")), num(column(a, r, "X")),
                            num(column(a, r, "x0")), num(column(a, r, "y0")),
                            num(column(a, r, "H")), num(column(a, r, "mean_u_along")),
                            num(column(a, r, "mean_u_normal")), num(column(a, r, "mean_speed"))});
        }
      }
      if (post.wants(PostProduct::FreeSurface)) {
        clock.start();
        vtkNew<vtkMPSFreeSurface> f;
        f->SetSpacing(post.surface_spacing);
        f->SetInputData(frame);
        f->Update();
        clock.stop("free_surface");
        vtkPolyData* s = f->GetOutput();
        for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i) {
          surface_csv.row({t, num(component(s, "x", i)), num(component(s, "eta", i))});
        }
      }
      if (post.wants(PostProduct::Lines)) {
        clock.start();
        for (const auto& [from, to] : post.lines) {
          double a[2], b[2];
          if (!block_point(frame, from, a) || !block_point(frame, to, b)) {
            throw IoError(frame_file.string() + ": the frame has no BlockOutline for line " + from +
                          "-" + to);
          }
          vtkNew<vtkMPSPolylineProbe> f;
          f->AddPoint(a[0], a[1]);
          f->AddPoint(b[0], b[1]);
          f->SetInputData(frame);
          f->Update();
          vtkPolyData* p = f->GetOutput();
          for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i) {
            double x[3];
            p->GetPoint(i, x);
            lines_csv.row({t, from + "-" + to, num(component(p, "arc_length", i)),
                           num(component(p, "arc_fraction", i)), num(x[0]), num(x[1]),
                           num(component(p, "pressure", i)), num(component(p, "velocity", i, 0)),
                           num(component(p, "velocity", i, 1))});
          }
        }
        clock.stop("lines");
      }
      std::cout << "t = " << t << " s: " << e.file << " done\n";
    }
    Csv cavity_csv("time [s],area [m^2],area [DL^2],points,first_x [m],first_y [m]");
    if (post.wants(PostProduct::Cavity)) {
      // Every frame of the series, not only the times asked for: a cavity opens and closes
      // between them.
      const WaterCavity cavity(spec);
      for (const auto& e : series) {
        progress.show(
            "post: cavity of frame " + std::to_string(&e - series.data() + 1) + " of " +
            std::to_string(series.size()) + ", " +
            format_duration(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()) +
            " so far");
        clock.start();
        const fs::path frame_file = run / e.file;
        const CavityMeasure m = measure_cavity(cavity, read_frame_file(frame_file), frame_file);
        cavity_csv.row({num(e.time), num(m.area), num(m.area / (spec.dl * spec.dl)),
                        std::to_string(m.points), m.points ? num(m.first.x) : "",
                        m.points ? num(m.first.y) : ""});
        clock.stop("cavity");
      }
      progress.done();
      std::cout << "cavity: " << series.size() << " frames done\n";
    }

    auto write = [&](const char* name, const std::string& text, const char* what) {
      write_file_atomically(out / name, text);
      files.push_back({{"file", name}, {"what", what}});
    };
    if (post.wants(PostProduct::Grid)) {
      write("grid.pvd",
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
            "  <Collection>\n" +
                grid_pvd + "  </Collection>\n</VTKFile>\n",
            "the grids (grid_NNNNNN.vti): interpolated fields, speed, vorticity, coverage, "
            "vtkValidPointMask");
    }
    if (post.wants(PostProduct::Sections)) {
      write("sections.csv", sections_csv.text, "profiles along each section, bed to surface");
      write("section_summary.csv", summary_csv.text, "each section's extent and depth averages");
    }
    if (post.wants(PostProduct::SectionAverages)) {
      write("section_averages.csv", averages_csv.text,
            "depth-averaged velocity against X/L over the block");
    }
    if (post.wants(PostProduct::FreeSurface)) {
      write("free_surface.csv", surface_csv.text, "water surface eta(x)");
    }
    if (post.wants(PostProduct::Lines)) {
      write("lines.csv", lines_csv.text, "pressure and velocity along lines between block points");
    }
    if (post.wants(PostProduct::Cavity)) {
      write("cavity.csv", cavity_csv.text,
            "area under the water farther than DL from every particle, at every frame");
    }
    nlohmann::json j;
    j["version"] = kVersion;
    j["run"] = fs::absolute(run).string();
    j["case"] = spec.name;
    j["times"] = nlohmann::json::array();
    for (const auto* e : frames) j["times"].push_back(e->time);
    j["threads"] = smp ? threads : 1;
    j["files"] = files;
    nlohmann::json cost;
    for (const auto& [product, s] : clock.seconds) {
      cost[product] = {{"median_seconds_per_frame", median(s)}, {"frames", s.size()}};
    }
    j["cost"] = cost;
    write_file_atomically(out / "post.json", j.dump(2) + "\n");
    std::cout << "wrote " << files.size() << " products for " << frames.size() << " times to "
              << out.string() << "\n";
    for (const auto& [product, s] : clock.seconds) {
      std::printf("  %-17s %8.3f s per frame (median of %zu)\n", product.c_str(), median(s),
                  s.size());
    }
  } catch (const IoError& e) {
    std::cerr << "wcmps: error: " << e.what() << '\n';
    return exit_code::kIo;
  }
  return exit_code::kOk;
}

}  // namespace wcmps
