#pragma once
/// @file BodyCsv.h
/// @brief block.csv: the rigid body's state after every step, one line per step.
///
/// Columns (forces per metre of width, since the scene is 2D):
///   time_s, S_m, U_m_s, A_m_s2          distance moved along the bed, speed, acceleration
///   Fp_x_N_m, Fp_y_N_m                  the fluid's pressure force on the body
///   Fv_x_N_m, Fv_y_N_m                  the fluid's viscous force on the body
///   N_N_m                               the force the bed carries (normal to it)
///   along_N_m                           M A - (M g + F) . t: the force along the bed that the
///                                       motion needs beyond gravity and the fluid (free motion:
///                                       minus the friction)

#include <filesystem>
#include <vector>

#include "body/SlidingBody.h"

namespace wcmps {

/// Writes the samples atomically to `path`; throws IoError.
void write_body_csv(const std::filesystem::path& path, const std::vector<BodySample>& samples);

}  // namespace wcmps
