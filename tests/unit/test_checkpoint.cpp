/// @file test_checkpoint.cpp
/// @brief Checkpoints: the HDF5 store (round trip, keeping the newest, skipping a damaged or
/// foreign file) and a simulation continued from a checkpoint, which must be identical to
/// one that was not stopped: the same operations in the same order give the same bits, so
/// the comparison is exact (memcmp), not within a tolerance.

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "core/Error.h"
#include "io/Checkpoint.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Runner.h"
#include "simulation/Simulation.h"
#include "support/TestSupport.h"

namespace wcmps {
namespace {

namespace fs = std::filesystem;

/// Writes a few named values of every kind; reads them back.
void save_sample(StateWriter& out, double scale) {
  const std::vector<double> x{1.0 * scale, 2.0, 3.0}, y{-1.0, -2.0, 0.5 * scale};
  const std::vector<std::int32_t> id{7, 8, 9};
  const std::vector<std::uint8_t> flag{0, 1, 0};
  const std::vector<std::int64_t> big{1LL << 40, -5};
  out.field("position", {x.data(), y.data()}, x.size());
  out.field("id", id.data(), id.size());
  out.field("flag", flag.data(), flag.size());
  out.field("big", big.data(), big.size());
  out.field("empty", {static_cast<const double*>(nullptr)}, 0);
  out.scalar("time", 0.25 * scale);
  out.integer("steps", 1234);
}

TEST(CheckpointStore, RoundTripOfEveryKindOfValue) {
  const fs::path dir = test::scratch_dir("checkpoint_round_trip");
  CheckpointStore store(dir, 2);
  const fs::path file = store.write("case text", [](StateWriter& w) { save_sample(w, 1.0); });
  EXPECT_EQ(file.filename(), "checkpoint_000001.h5");
  std::vector<std::string> rejected;
  store.load_newest(
      "case text",
      [](StateReader& r) {
        std::vector<double> x(3), y(3);
        r.field("position", {x.data(), y.data()}, 3);
        EXPECT_EQ(x, (std::vector<double>{1.0, 2.0, 3.0}));
        EXPECT_EQ(y, (std::vector<double>{-1.0, -2.0, 0.5}));
        std::vector<std::int32_t> id(3);
        r.field("id", id.data(), 3);
        EXPECT_EQ(id, (std::vector<std::int32_t>{7, 8, 9}));
        std::vector<std::uint8_t> flag(3);
        r.field("flag", flag.data(), 3);
        EXPECT_EQ(flag, (std::vector<std::uint8_t>{0, 1, 0}));
        std::vector<std::int64_t> big(2);
        r.field("big", big.data(), 2);
        EXPECT_EQ(big[0], 1LL << 40);
        EXPECT_EQ(r.count("empty"), 0u);
        EXPECT_EQ(r.scalar("time"), 0.25);
        EXPECT_EQ(r.integer("steps"), 1234);
        // A field of another size, or a missing name, is an error naming it.
        std::vector<double> four(4);
        EXPECT_THROW(r.field("position", {four.data()}, 4), CheckpointError);
        EXPECT_THROW(r.scalar("no_such_value"), CheckpointError);
      },
      rejected);
  EXPECT_TRUE(rejected.empty());
}

TEST(CheckpointStore, KeepsTheNewestAndSkipsDamagedOrForeignOnes) {
  const fs::path dir = test::scratch_dir("checkpoint_keep");
  CheckpointStore store(dir, 2);
  for (int k = 1; k <= 4; ++k) {
    store.write("case", [&](StateWriter& w) { save_sample(w, k); });
  }
  const auto files = store.files();
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].filename(), "checkpoint_000003.h5");
  EXPECT_EQ(files[1].filename(), "checkpoint_000004.h5");

  // The newest cut in half (a damaged disk): skipped with its reason, removed; the older one
  // is loaded.
  fs::resize_file(files[1], fs::file_size(files[1]) / 2);
  std::vector<std::string> rejected;
  double time = 0.0;
  const fs::path used = store.load_newest(
      "case", [&](StateReader& r) { time = r.scalar("time"); }, rejected);
  EXPECT_EQ(used.filename(), "checkpoint_000003.h5");
  EXPECT_EQ(time, 0.75);
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_NE(rejected[0].find("checkpoint_000004.h5"), std::string::npos);
  EXPECT_FALSE(fs::exists(files[1]));
  // The next one written follows the one loaded.
  EXPECT_EQ(store.write("case", [](StateWriter& w) { save_sample(w, 5.0); }).filename(),
            "checkpoint_000004.h5");

  // Written for another case file: refused, with the reason.
  rejected.clear();
  try {
    store.load_newest(
        "another case", [](StateReader&) {}, rejected);
    FAIL() << "a checkpoint of another case was loaded";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("another case file"), std::string::npos) << e.what();
  }
}

TEST(CheckpointStore, NoCheckpointIsAnError) {
  const fs::path dir = test::scratch_dir("checkpoint_none");
  CheckpointStore store(dir, 2);
  std::vector<std::string> rejected;
  EXPECT_THROW(store.load_newest(
                   "case", [](StateReader&) {}, rejected),
               CheckpointError);
}

/// The whole state of a simulation as bytes, for an exact comparison.
std::string state_bytes(const Simulation& sim) {
  const ParticleState& s = sim.particles().now;
  std::string out;
  auto add = [&](const auto& v) {
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v[0]));
  };
  add(s.x);
  add(s.y);
  add(s.u);
  add(s.v);
  add(s.p);
  add(s.n);
  add(s.shift_u);
  add(s.shift_v);
  add(s.struck_n);
  add(s.rest_a);
  add(s.rest_b);
  add(s.surface);
  add(sim.particles().id);
  const double t = sim.time();
  out.append(reinterpret_cast<const char*>(&t), sizeof t);
  if (sim.body()) {
    const SlideState b = sim.body()->state();
    out.append(reinterpret_cast<const char*>(&b), sizeof b);
  }
  return out;
}

/// The restart case of the command-line tests (a free block, gauges, settling): stop in the
/// middle of settling and in the middle of the run, continue in a new Simulation.
void expect_continued_identical(bool shift_in_continuity, GradientRenormalisation renormalisation =
                                                              GradientRenormalisation::None) {
  CaseSpec spec = parse_case_file(test::source_path("tests/cli/restart.toml"));
  spec.end_time = 0.03;
  spec.shifting_in_continuity = shift_in_continuity;
  spec.gradient_renormalisation = renormalisation;
  const fs::path dir = test::scratch_dir(renormalisation != GradientRenormalisation::None
                                             ? "checkpoint_simulation_strain"
                                         : shift_in_continuity ? "checkpoint_simulation_shift"
                                                               : "checkpoint_simulation");
  CheckpointStore store(dir, 2);

  Simulation reference(spec, build_scene(spec));
  for (int k = 0; k < 40; ++k) reference.settle_step();
  ASSERT_TRUE(reference.settling());
  store.write(spec.source_text, [&](StateWriter& w) { reference.save(w); });
  reference.settle();
  for (int k = 0; k < 60; ++k) reference.step(spec.end_time);
  store.write(spec.source_text, [&](StateWriter& w) { reference.save(w); });
  for (int k = 0; k < 60; ++k) reference.step(spec.end_time);
  const std::string expected = state_bytes(reference);

  // From the second checkpoint (after t = 0).
  Simulation continued(spec, build_scene(spec));
  std::vector<std::string> rejected;
  store.load_newest(
      spec.source_text, [&](StateReader& r) { continued.load(r); }, rejected);
  EXPECT_FALSE(continued.settling());
  for (int k = 0; k < 60; ++k) continued.step(spec.end_time);
  EXPECT_EQ(continued.steps(), reference.steps());
  EXPECT_TRUE(state_bytes(continued) == expected) << "the continued run differs";
  ASSERT_EQ(continued.body_history().size(), reference.body_history().size());
  EXPECT_EQ(std::memcmp(continued.body_history().data(), reference.body_history().data(),
                        reference.body_history().size() * sizeof(BodySample)),
            0);

  // From the first (while settling): the rest of settling, then the same steps.
  fs::remove(store.files().back());
  Simulation from_settling(spec, build_scene(spec));
  store.load_newest(
      spec.source_text, [&](StateReader& r) { from_settling.load(r); }, rejected);
  EXPECT_TRUE(from_settling.settling());
  from_settling.settle();
  EXPECT_EQ(from_settling.settle_steps(), reference.settle_steps());
  for (int k = 0; k < 120; ++k) from_settling.step(spec.end_time);
  EXPECT_TRUE(state_bytes(from_settling) == expected) << "the run continued from settling differs";
}

TEST(Checkpoint, AContinuedSimulationIsIdenticalToAnUninterruptedOne) {
  expect_continued_identical(false);
}

TEST(Checkpoint, AContinuedSimulationFollowingTheShiftIsIdentical) {
  // The shift's velocities of the last step are part of the state the next step reads.
  expect_continued_identical(true);
}

TEST(Checkpoint, AContinuedSimulationWithRestShapesIsIdentical) {
  // "khayyer2011-strain" corrects each particle's shape against its rest shape, which the
  // checkpoint carries (a restart that began every particle from its own shape would differ).
  expect_continued_identical(false, GradientRenormalisation::Strain);
}

/// Records frame times; writes checkpoints of the simulation and the run's figures.
struct RecordingSink : FrameSink {
  RecordingSink(CheckpointStore& s, const std::string& text) : store(s), case_text(text) {}
  void write_frame(const Simulation& sim) override { times.push_back(sim.time()); }
  void checkpoint(const Simulation& sim, const RunStats& stats) override {
    store.write(case_text, [&](StateWriter& w) {
      sim.save(w);
      stats.save(w);
    });
  }
  CheckpointStore& store;
  const std::string& case_text;
  std::vector<double> times;
};

TEST(Checkpoint, AStopAsSettlingEndsKeepsTheFirstFrame) {
  // A signal seen right after the last settling step: the run stops after the frame of t = 0,
  // so that the frames of the stopped and the continued run are those of an uninterrupted one.
  CaseSpec spec = parse_case_file(test::source_path("tests/cli/restart.toml"));
  spec.end_time = 0.04;
  const auto times = output_times(spec, spec.end_time);
  const fs::path dir = test::scratch_dir("checkpoint_stop_at_settled");
  CheckpointStore store(dir, 2);

  Simulation sim(spec, build_scene(spec));
  RecordingSink first(store, spec.source_text);
  Runner runner(sim, times, spec.end_time);
  runner.set_stop_request([&] { return sim.settling() ? 0 : 15; });
  const RunStats stopped = runner.run(first, nullptr);
  EXPECT_EQ(stopped.stop_signal, 15);
  EXPECT_FALSE(stopped.completed);

  Simulation continued(spec, build_scene(spec));
  RunStats before;
  std::vector<std::string> rejected;
  store.load_newest(
      spec.source_text,
      [&](StateReader& r) {
        continued.load(r);
        before.load(r);
      },
      rejected);
  RecordingSink second(store, spec.source_text);
  Runner rest(continued, times, spec.end_time);
  rest.resume(before);
  EXPECT_TRUE(rest.run(second, nullptr).completed);

  // Exact: the Courant step lands on each output time, and frames record it.
  std::vector<double> all = first.times;
  all.insert(all.end(), second.times.begin(), second.times.end());
  EXPECT_EQ(all, times) << "frames of the stopped run: " << first.times.size();
}

TEST(Checkpoint, AnotherSceneIsRefused) {
  // A checkpoint of one scene loaded into a simulation of another: the particle counts differ,
  // and loading says so instead of reading past its arrays.
  CaseSpec spec = parse_case_file(test::source_path("tests/cli/restart.toml"));
  const fs::path dir = test::scratch_dir("checkpoint_other_scene");
  CheckpointStore store(dir, 2);
  Simulation sim(spec, build_scene(spec));
  store.write("case", [&](StateWriter& w) { sim.save(w); });
  CaseSpec finer = spec;
  finer.dl = 0.006;
  Simulation other(finer, build_scene(finer));
  std::vector<std::string> rejected;
  EXPECT_THROW(store.load_newest(
                   "case", [&](StateReader& r) { other.load(r); }, rejected),
               CheckpointError);
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_NE(rejected[0].find("position has 2 x"), std::string::npos) << rejected[0];
}

}  // namespace
}  // namespace wcmps
