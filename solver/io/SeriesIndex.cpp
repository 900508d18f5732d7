#include "io/SeriesIndex.h"

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/Error.h"

namespace wcmps {

std::vector<SeriesEntry> read_series(const std::filesystem::path& pvd) {
  std::ifstream in(pvd);
  if (!in) throw IoError(pvd.string() + ": cannot read");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  static const std::regex dataset(R"(<DataSet\s[^>]*>)");
  static const std::regex timestep(R"re(timestep="([^"]*)")re");
  static const std::regex file(R"re(file="([^"]*)")re");
  std::vector<SeriesEntry> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), dataset); it != std::sregex_iterator();
       ++it) {
    const std::string tag = it->str();
    std::smatch t, f;
    if (!std::regex_search(tag, t, timestep) || !std::regex_search(tag, f, file)) {
      throw IoError(pvd.string() + ": a DataSet without timestep or file: " + tag);
    }
    out.push_back({std::stod(t[1].str()), f[1].str()});
  }
  return out;
}

const SeriesEntry* frame_at(const std::vector<SeriesEntry>& series, double t) {
  const SeriesEntry* best = nullptr;
  for (const auto& e : series) {
    if (!best || std::abs(e.time - t) < std::abs(best->time - t)) best = &e;
  }
  return best && std::abs(best->time - t) <= 1e-4 ? best : nullptr;
}

}  // namespace wcmps
