#pragma once
/// @file VtpSeriesWriter.h
/// @brief Writes frames as VTK XML PolyData (.vtp: binary, LZ4-compressed) and keeps
/// series.pvd listing every frame with its time, rewritten atomically after each frame, so a
/// series on disk is always complete and opens in ParaView with the right times.
///
/// Each frame carries the fields the case asks for (particles/Fields.h) for the particle kinds
/// it asks for, one vertex cell per particle, and field data that lets filters and scripts work
/// without the case file: TimeValue, Step, DL, re, n0, lambda, c0, rho0, CaseName, with a
/// block its outline (BlockOutline: corners as x y 0 tuples), BlockS and BlockU, and with
/// measuring sections their names (SectionNames) and lines (SectionLines: x y nx ny tuples,
/// the origin and the unit direction from the bed towards the surface).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/StateArchive.h"
#include "scene/CaseSpec.h"
#include "simulation/Runner.h"

namespace wcmps {

class VtpSeriesWriter : public FrameSink {
 public:
  VtpSeriesWriter(std::filesystem::path dir, const CaseSpec& spec);

  /// Writes an empty series.pvd, so that a new run directory holds a series from the start.
  void start() const { write_series(); }

  /// Writes the simulation's current state as the next frame (once per step: a second call at
  /// the same step is ignored).
  void write_frame(const Simulation& sim) override;

  struct Entry {
    double time;
    std::int64_t step;
    std::string file;
  };
  const std::vector<Entry>& entries() const { return entries_; }

  /// The frames written so far, for checkpoints. load() takes the series back to those frames:
  /// frames written after the checkpoint are deleted and series.pvd is rewritten, so that a
  /// continued run appends where the checkpoint was taken.
  void save(StateWriter& out) const;
  void load(StateReader& in);

 private:
  void write_series() const;
  static std::string frame_name(std::size_t index);

  std::filesystem::path dir_;
  std::string case_name_;
  std::vector<SectionSpec> sections_;
  std::vector<FieldId> fields_;
  std::vector<ParticleKind> kinds_;
  bool double_precision_;
  std::vector<Entry> entries_;
};

}  // namespace wcmps
