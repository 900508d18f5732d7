// Frames read back with VTK's reader, the series file, atomic writes, run-directory policy.

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <sys/resource.h>

#include <csignal>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/BodyCsv.h"
#include "io/RunDirectory.h"
#include "io/RunSummary.h"
#include "io/VtpSeriesWriter.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "support/TestSupport.h"

namespace fs = std::filesystem;

namespace wcmps {
namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

vtkSmartPointer<vtkPolyData> read_frame(const fs::path& p) {
  vtkNew<vtkXMLPolyDataReader> r;
  r->SetFileName(p.c_str());
  r->Update();
  return r->GetOutput();
}

TEST(VtpSeriesWriter, FramesReadBackWithEveryFieldAndTheirTimes) {
  // The hydrostatic case has 4532 particles: frames of ~100 kB, far beyond the few kB at which
  // ParaView 5.11's reader fails on appended data with Debian 12's Expat (see the writer).
  CaseSpec spec = test::load_case("cases/hydrostatic/case.toml");
  Simulation sim(spec, build_scene(spec));
  const auto dir = test::scratch_dir("series");
  VtpSeriesWriter writer(dir, spec);
  writer.write_frame(sim);
  sim.step(1.0);
  sim.step(1.0);
  writer.write_frame(sim);
  writer.write_frame(sim);  // same step again: ignored
  ASSERT_EQ(writer.entries().size(), 2u);

  const auto pd = read_frame(dir / writer.entries()[1].file);
  ASSERT_EQ(pd->GetNumberOfPoints(), sim.particles().size());
  EXPECT_EQ(pd->GetNumberOfVerts(), sim.particles().size());
  for (const auto& f : kFields) {
    vtkDataArray* a = pd->GetPointData()->GetArray(std::string(f.name).c_str());
    ASSERT_NE(a, nullptr) << f.name;
    EXPECT_EQ(a->GetNumberOfComponents(), f.components) << f.name;
  }
  vtkFieldData* fd = pd->GetFieldData();
  EXPECT_DOUBLE_EQ(fd->GetArray("TimeValue")->GetTuple1(0), sim.time());
  EXPECT_DOUBLE_EQ(fd->GetArray("DL")->GetTuple1(0), 0.01);
  EXPECT_DOUBLE_EQ(fd->GetArray("re")->GetTuple1(0), 0.035);
  EXPECT_NEAR(fd->GetArray("n0")->GetTuple1(0), 3.04303, 1e-5);
  EXPECT_GT(fd->GetArray("c0")->GetTuple1(0), 30.0);
  auto* name = vtkStringArray::SafeDownCast(fd->GetAbstractArray("CaseName"));
  ASSERT_NE(name, nullptr);
  EXPECT_EQ(name->GetValue(0), "hydrostatic");
  // Velocity is (u, v, 0) of the particle with the same id.
  vtkDataArray* vel = pd->GetPointData()->GetArray("velocity");
  vtkDataArray* ids = pd->GetPointData()->GetArray("id");
  const ParticleSet& ps = sim.particles();
  for (vtkIdType k = 0; k < pd->GetNumberOfPoints(); k += 97) {
    const auto i = static_cast<std::int64_t>(k);  // all kinds written: same order
    EXPECT_EQ(static_cast<int>(ids->GetTuple1(k)), ps.id[i]);
    EXPECT_FLOAT_EQ(static_cast<float>(vel->GetComponent(k, 0)), static_cast<float>(ps.now.u[i]));
    EXPECT_EQ(vel->GetComponent(k, 2), 0.0);
  }

  const std::string pvd = read_text(dir / "series.pvd");
  const std::regex entry(
      "<DataSet timestep=\"([^\"]+)\" group=\"\" part=\"0\" file=\"([^\"]+)\"/>");
  std::vector<std::pair<double, std::string>> found;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), entry); it != std::sregex_iterator();
       ++it) {
    found.emplace_back(std::stod((*it)[1]), (*it)[2]);
  }
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].first, 0.0);
  EXPECT_EQ(found[1].first, sim.time());  // written exactly (shortest round-trip decimal)
  EXPECT_EQ(found[1].second, "frame_000001.vtp");
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << "left over: " << e.path();
  }
}

// A case with a moving body: each frame carries its outline where the body is, block.csv a
// line per step, run.json the body's state and the case's sections.
TEST(VtpSeriesWriter, BodyOutlineBlockCsvAndSections) {
  CaseSpec spec = parse_case_text(test::minimal_case_text() + R"(
[[wall]]
rectangle = { min = [0.05, 0.02], max = [0.15, 0.10] }

[[section]]
name = "S1"
point = [0.1, 0.1]
direction = [0.0, 1.0]
)",
                                  "body.toml");
  BodySpec body;
  body.wall = 1;
  body.density = 2000.0;
  body.downslope = {1.0, 0.0};
  body.bed_normal = {0.0, 1.0};
  body.motion.type = BodyMotionType::LnCosh;
  body.motion.a0 = 5.0;
  body.motion.ut = 1.0;
  spec.body = body;
  Simulation sim(spec, build_scene(spec));
  const auto dir = test::scratch_dir("body");
  VtpSeriesWriter writer(dir, spec);
  sim.step(1.0);
  sim.step(1.0);
  writer.write_frame(sim);
  const double s = LnCoshSlide{5.0, 1.0}.at(sim.time()).s;
  ASSERT_GT(s, 0.0);
  const auto frame = read_frame(dir / writer.entries()[0].file);
  vtkFieldData* fd = frame->GetFieldData();
  vtkDataArray* outline = fd->GetArray("BlockOutline");
  ASSERT_NE(outline, nullptr);
  ASSERT_EQ(outline->GetNumberOfTuples(), 4);
  EXPECT_NEAR(outline->GetComponent(0, 0), 0.05 + s, 1e-12);  // first corner (min), moved by S
  EXPECT_NEAR(outline->GetComponent(0, 1), 0.02, 1e-12);
  EXPECT_NEAR(fd->GetArray("BlockS")->GetTuple1(0), s, 1e-12);

  write_body_csv(dir / RunFiles::kBody, sim.body_history());
  std::istringstream csv(read_text(dir / RunFiles::kBody));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("time_s,S_m,U_m_s,A_m_s2,", 0), 0u) << line;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 3);  // t = 0 and two steps

  const auto j = summarize(spec, sim, RunStats{}, std::nullopt).to_json();
  EXPECT_NEAR(j["block"]["S"].get<double>(), s, 1e-12);
  ASSERT_EQ(j["sections"].size(), 1u);
  EXPECT_EQ(j["sections"][0]["name"], "S1");
}

TEST(VtpSeriesWriter, WritesOnlyTheFieldsAndParticleKindsAskedFor) {
  CaseSpec spec = test::load_case("cases/hydrostatic/case.toml");
  spec.output_fields = {FieldId::Pressure};
  spec.output_kinds = {ParticleKind::Fluid};
  spec.output_double_precision = true;
  const Simulation sim(spec, build_scene(spec));
  const auto dir = test::scratch_dir("subset");
  VtpSeriesWriter writer(dir, spec);
  writer.write_frame(sim);
  const auto pd = read_frame(dir / "frame_000000.vtp");
  EXPECT_EQ(pd->GetNumberOfPoints(), sim.particles().fluid_count());
  EXPECT_EQ(pd->GetPointData()->GetNumberOfArrays(), 1);
  ASSERT_NE(pd->GetPointData()->GetArray("pressure"), nullptr);
  EXPECT_EQ(pd->GetPointData()->GetArray("pressure")->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(pd->GetPoints()->GetDataType(), VTK_DOUBLE);
}

TEST(AtomicFile, ReplacesContentAndLeavesNoTemporary) {
  const auto dir = test::scratch_dir("atomic");
  write_file_atomically(dir / "a.txt", "first");
  write_file_atomically(dir / "a.txt", "second");
  EXPECT_EQ(read_text(dir / "a.txt"), "second");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
  EXPECT_THROW(write_file_atomically(dir / "missing" / "a.txt", "x"), IoError);
}

std::size_t regular_files(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

// More than the 64 KiB buffer, with a seek back into what was flushed (as VTK's XML writer
// does for a compression header) and forth to the end.
TEST(AtomicOutputFile, StreamsSeeksBackAndRenamesOnCommit) {
  const auto dir = test::scratch_dir("atomic_stream");
  std::string expected;
  for (int k = 0; k < 30000; ++k) expected += "line " + std::to_string(k) + "\n";
  {
    AtomicOutputFile file(dir / "a.txt");
    std::ostream& os = file.stream();
    os << expected.substr(0, 100000);
    os.flush();
    EXPECT_EQ(static_cast<std::streamoff>(os.tellp()), 100000);
    os.seekp(10);
    os << "XY";
    os.seekp(0, std::ios_base::end);
    os << expected.substr(100000);
    EXPECT_TRUE(os.good());
    EXPECT_FALSE(fs::exists(dir / "a.txt"));  // under its temporary name until committed
    file.commit();
  }
  expected.replace(10, 2, "XY");
  EXPECT_EQ(read_text(dir / "a.txt"), expected);
  EXPECT_EQ(regular_files(dir), 1u);

  {
    AtomicOutputFile abandoned(dir / "b.txt");
    abandoned.stream() << "never committed";
  }
  EXPECT_FALSE(fs::exists(dir / "b.txt"));
  EXPECT_EQ(regular_files(dir), 1u);
}

// A write that fails part-way (here the file-size limit, EFBIG, as a stand-in for a full disk):
// the stream does not fail (VTK's XML writer must not see it), commit() throws naming the file,
// and nothing is left.
TEST(AtomicOutputFile, AFailedWriteIsReportedByCommitAndLeavesNothing) {
  const auto dir = test::scratch_dir("atomic_stream_fail");
  rlimit before{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &before), 0);
  rlimit small = before;
  small.rlim_cur = 100000;
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  bool good = false;
  std::string message;
  {
    AtomicOutputFile file(dir / "big.txt");
    file.stream() << std::string(300000, 'x');
    file.stream().flush();
    good = file.stream().good();
    try {
      file.commit();
    } catch (const IoError& e) {
      message = e.what();
    }
  }
  ::setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_TRUE(good);
  EXPECT_NE(message.find("cannot write " + (dir / "big.txt").string()), std::string::npos)
      << message;
  EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
  EXPECT_EQ(regular_files(dir), 0u);
}

TEST(RunDirectory, NewEarlierAndForeignDirectories) {
  const auto root = test::scratch_dir("rundir");
  const auto dir = root / "run";
  prepare_run_directory(dir, false);  // created
  EXPECT_TRUE(fs::is_directory(dir));
  write_file_atomically(dir / "series.pvd", "x");
  write_file_atomically(dir / "frame_000000.vtp", "x");
  write_file_atomically(dir / "gauges.csv", "x");
  fs::create_directories(dir / "post");  // what `wcmps post` made of it
  write_file_atomically(dir / "post" / "sections.csv", "x");
  EXPECT_THROW(prepare_run_directory(dir, false), IoError);  // an earlier run
  prepare_run_directory(dir, true);                          // replaced, with its products
  EXPECT_FALSE(fs::exists(dir / "series.pvd"));
  EXPECT_FALSE(fs::exists(dir / "frame_000000.vtp"));
  EXPECT_FALSE(fs::exists(dir / "gauges.csv"));
  EXPECT_FALSE(fs::exists(dir / "post"));
  write_file_atomically(dir / "notes.txt", "mine");
  try {
    prepare_run_directory(dir, true);  // never deletes what a run did not write
    FAIL() << "accepted a directory with a foreign file";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
  // A path through a regular file cannot become a directory.
  EXPECT_THROW(prepare_run_directory(dir / "notes.txt" / "sub", false), IoError);
}

}  // namespace
}  // namespace wcmps
