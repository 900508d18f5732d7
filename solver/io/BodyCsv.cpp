#include "io/BodyCsv.h"

#include <cstdio>
#include <string>

#include "io/AtomicFile.h"

namespace wcmps {

void write_body_csv(const std::filesystem::path& path, const std::vector<BodySample>& samples) {
  std::string text =
      "time_s,S_m,U_m_s,A_m_s2,Fp_x_N_m,Fp_y_N_m,Fv_x_N_m,Fv_y_N_m,N_N_m,along_N_m\n";
  text.reserve(text.size() + samples.size() * 160);
  char line[320];
  for (const BodySample& b : samples) {
    std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", b.time,
                  b.state.s, b.state.u, b.state.a, b.force.pressure.x, b.force.pressure.y,
                  b.force.viscous.x, b.force.viscous.y, b.normal, b.along);
    text += line;
  }
  write_file_atomically(path, text);
}

}  // namespace wcmps
