#include "io/VtpSeriesWriter.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <charconv>
#include <cstdio>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/RunDirectory.h"
#include "io/VtkXmlFile.h"

namespace fs = std::filesystem;

namespace wcmps {
namespace {

/// Shortest decimal text that reads back as the same double.
std::string exact(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// A floating-point array of the precision the case asks for.
vtkSmartPointer<vtkDataArray> new_real_array(bool double_precision, const std::string& name,
                                             int components, vtkIdType tuples) {
  vtkSmartPointer<vtkDataArray> a;
  if (double_precision) {
    a = vtkSmartPointer<vtkDoubleArray>::New();
  } else {
    a = vtkSmartPointer<vtkFloatArray>::New();
  }
  a->SetName(name.c_str());
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

void add_field_value(vtkFieldData* fd, const char* name, double value) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

}  // namespace

VtpSeriesWriter::VtpSeriesWriter(fs::path dir, const CaseSpec& spec)
    : dir_(std::move(dir)),
      case_name_(spec.name),
      sections_(spec.sections),
      fields_(spec.output_fields),
      kinds_(spec.output_kinds),
      double_precision_(spec.output_double_precision) {}

void VtpSeriesWriter::write_frame(const Simulation& sim) {
  if (!entries_.empty() && entries_.back().step == sim.steps()) return;
  const ParticleSet& ps = sim.particles();
  const ParticleState& s = ps.now;

  std::vector<std::int64_t> pick;
  pick.reserve(ps.size());
  for (std::int64_t i = 0; i < ps.size(); ++i) {
    if (std::find(kinds_.begin(), kinds_.end(), ps.kind[i]) != kinds_.end()) pick.push_back(i);
  }
  const auto n = static_cast<vtkIdType>(pick.size());

  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->SetDataType(double_precision_ ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(n);
  for (vtkIdType k = 0; k < n; ++k) points->SetPoint(k, s.x[pick[k]], s.y[pick[k]], 0.0);
  poly->SetPoints(points);

  // One vertex per particle, so that every ParaView representation and filter sees them.
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n);
  for (vtkIdType k = 0; k <= n; ++k) offsets->SetValue(k, k);
  for (vtkIdType k = 0; k < n; ++k) connectivity->SetValue(k, k);
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  poly->SetVerts(verts);

  vtkPointData* pd = poly->GetPointData();
  for (const FieldId f : fields_) {
    const auto info = *std::find_if(std::begin(kFields), std::end(kFields),
                                    [&](const FieldInfo& fi) { return fi.id == f; });
    const std::string name(info.name);
    switch (f) {
      case FieldId::Velocity: {
        auto a = new_real_array(double_precision_, name, 3, n);
        for (vtkIdType k = 0; k < n; ++k) a->SetTuple3(k, s.u[pick[k]], s.v[pick[k]], 0.0);
        pd->AddArray(a);
        pd->SetActiveVectors(name.c_str());
        break;
      }
      case FieldId::Pressure:
      case FieldId::NumberDensity: {
        const std::vector<double>& src = f == FieldId::Pressure ? s.p : s.n;
        auto a = new_real_array(double_precision_, name, 1, n);
        for (vtkIdType k = 0; k < n; ++k) a->SetTuple1(k, src[pick[k]]);
        pd->AddArray(a);
        break;
      }
      case FieldId::Kind:
      case FieldId::FreeSurface: {
        vtkNew<vtkUnsignedCharArray> a;
        a->SetName(name.c_str());
        a->SetNumberOfValues(n);
        for (vtkIdType k = 0; k < n; ++k) {
          const std::int64_t i = pick[k];
          a->SetValue(k,
                      f == FieldId::Kind ? static_cast<unsigned char>(ps.kind[i]) : s.surface[i]);
        }
        pd->AddArray(a);
        break;
      }
      case FieldId::Id: {
        vtkNew<vtkIntArray> a;
        a->SetName(name.c_str());
        a->SetNumberOfValues(n);
        for (vtkIdType k = 0; k < n; ++k) a->SetValue(k, ps.id[pick[k]]);
        pd->AddArray(a);
        break;
      }
    }
  }

  vtkFieldData* fd = poly->GetFieldData();
  add_field_value(fd, "TimeValue", sim.time());
  add_field_value(fd, "Step", static_cast<double>(sim.steps()));
  add_field_value(fd, "DL", sim.time_step_rule().dl);
  add_field_value(fd, "re", sim.operators().re());
  add_field_value(fd, "n0", sim.operators().n0());
  add_field_value(fd, "lambda", sim.operators().lambda());
  add_field_value(fd, "c0", sim.scene().sound_speed);
  add_field_value(fd, "rho0", sim.density());
  if (const SlidingBody* body = sim.body()) {
    // The block's outline (its corners, x y 0) and motion, for figures and filters.
    vtkNew<vtkDoubleArray> outline;
    outline->SetName("BlockOutline");
    outline->SetNumberOfComponents(3);
    for (const Vec2 c : body->outline(body->state().s)) outline->InsertNextTuple3(c.x, c.y, 0.0);
    fd->AddArray(outline);
    add_field_value(fd, "BlockS", body->state().s);
    add_field_value(fd, "BlockU", body->state().u);
  }
  vtkNew<vtkStringArray> name;
  name->SetName("CaseName");
  name->InsertNextValue(case_name_);
  fd->AddArray(name);
  if (!sections_.empty()) {
    // The case's measuring sections (fixed in space): vtkMPSSections' default lines.
    vtkNew<vtkStringArray> names;
    names->SetName("SectionNames");
    vtkNew<vtkDoubleArray> lines;
    lines->SetName("SectionLines");
    lines->SetNumberOfComponents(4);
    for (const SectionSpec& sec : sections_) {
      names->InsertNextValue(sec.name);
      lines->InsertNextTuple4(sec.origin.x, sec.origin.y, sec.direction.x, sec.direction.y);
    }
    fd->AddArray(names);
    fd->AddArray(lines);
  }

  const std::string file = frame_name(entries_.size());
  const fs::path path = dir_ / file;
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  // Inline binary (base64 of LZ4 blocks), not appended: with Debian 12's Expat (security
  // fixes of 2.5.0-1+deb12u*), ParaView 5.11's reader fails on appended data of more than a
  // few kB ("not well-formed (invalid token)"), raw or encoded. Pinned by a test.
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToLZ4();
  write_vtk_xml_atomically(*writer, path);
  entries_.push_back({sim.time(), sim.steps(), file});
  write_series();
}

std::string VtpSeriesWriter::frame_name(std::size_t index) {
  char file[64];
  std::snprintf(file, sizeof file, "%s%06zu.vtp", RunFiles::kFramePrefix, index);
  return file;
}

void VtpSeriesWriter::save(StateWriter& out) const {
  std::vector<double> times;
  std::vector<std::int64_t> steps;
  for (const auto& e : entries_) {
    times.push_back(e.time);
    steps.push_back(e.step);
  }
  out.field("frame_time", {times.data()}, times.size());
  out.field("frame_step", steps.data(), steps.size());
}

void VtpSeriesWriter::load(StateReader& in) {
  const std::size_t n = in.count("frame_time");
  std::vector<double> times(n);
  std::vector<std::int64_t> steps(n);
  in.field("frame_time", {times.data()}, n);
  in.field("frame_step", steps.data(), n);
  entries_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const std::string file = frame_name(k);
    if (!fs::exists(dir_ / file)) {
      throw CheckpointError("frame " + (dir_ / file).string() +
                            " of the checkpoint's series is missing");
    }
    entries_.push_back({times[k], steps[k], file});
  }
  // Frames written after the checkpoint: the continued run writes them again.
  std::error_code ec;
  for (std::size_t k = n;; ++k) {
    const fs::path later = dir_ / frame_name(k);
    if (!fs::exists(later, ec)) break;
    fs::remove(later, ec);
    if (ec) throw IoError("cannot remove " + later.string() + ": " + ec.message());
  }
  write_series();
}

void VtpSeriesWriter::write_series() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& e : entries_) {
    xml += "    <DataSet timestep=\"" + exact(e.time) + "\" group=\"\" part=\"0\" file=\"" +
           e.file + "\"/>\n";
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(dir_ / RunFiles::kSeries, xml);
}

}  // namespace wcmps
