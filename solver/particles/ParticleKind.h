#pragma once
/// @file ParticleKind.h
/// @brief What a particle is. Stored per particle as one byte in the "kind" field.

#include <cstdint>
#include <optional>
#include <string_view>

namespace wcmps {

enum class ParticleKind : std::uint8_t {
  Fluid = 0,  ///< moves with the flow
  Wall = 1,   ///< first boundary layer: pressure from the equation of state, zero velocity
  Ghost = 2,  ///< further boundary layers (as many as re needs): pressure copied from a wall
};

constexpr std::string_view kind_name(ParticleKind k) {
  switch (k) {
    case ParticleKind::Fluid:
      return "fluid";
    case ParticleKind::Wall:
      return "wall";
    case ParticleKind::Ghost:
      return "ghost";
  }
  return "?";
}

inline std::optional<ParticleKind> kind_from_name(std::string_view s) {
  for (auto k : {ParticleKind::Fluid, ParticleKind::Wall, ParticleKind::Ghost}) {
    if (kind_name(k) == s) return k;
  }
  return std::nullopt;
}

}  // namespace wcmps
