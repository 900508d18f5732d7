#pragma once
/// @file SeriesIndex.h
/// @brief The frames a run's series.pvd lists, and the frame of a given time, for the
/// commands that read a run (`wcmps post`, `wcmps figures`).

#include <filesystem>
#include <string>
#include <vector>

namespace wcmps {

struct SeriesEntry {
  double time;
  std::string file;  ///< relative to the series' directory
};

/// The frames a series.pvd lists (as VtpSeriesWriter writes it); throws IoError.
std::vector<SeriesEntry> read_series(const std::filesystem::path& pvd);

/// The frame written for time t: the nearest, if within 1e-4 s (a fixed step writes a frame
/// up to half a step after its time; the study's step is 2.5e-5 s), else nullptr.
const SeriesEntry* frame_at(const std::vector<SeriesEntry>& series, double t);

}  // namespace wcmps
