#pragma once
/// @file Fields.h
/// @brief The per-particle fields a frame can carry, registered by name in one place so that
/// the case file, the writer and the filters agree on names, units and meaning.

#include <optional>
#include <string_view>

namespace wcmps {

enum class FieldId { Velocity, Pressure, NumberDensity, Kind, FreeSurface, Id };

struct FieldInfo {
  FieldId id;
  std::string_view name;  ///< array name in the .vtp files and key in [output].fields
  int components;         ///< 3 for vectors (z = 0 in 2D), 1 for scalars
  std::string_view unit;
  std::string_view description;
};

inline constexpr FieldInfo kFields[] = {
    {FieldId::Velocity, "velocity", 3, "m/s", "particle velocity (u, v, 0)"},
    {FieldId::Pressure, "pressure", 1, "Pa", "pressure from the equation of state"},
    {FieldId::NumberDensity, "number_density", 1, "-",
     "particle number density n* at the predicted positions (Eq. 2.17)"},
    {FieldId::Kind, "kind", 1, "-", "0 fluid, 1 wall, 2 ghost"},
    {FieldId::FreeSurface, "free_surface", 1, "-", "1 where n* < beta n0 (Eq. 2.10), else 0"},
    {FieldId::Id, "id", 1, "-", "particle id, stable over the run"},
};

inline std::optional<FieldInfo> find_field(std::string_view name) {
  for (const auto& f : kFields) {
    if (f.name == name) return f;
  }
  return std::nullopt;
}

}  // namespace wcmps
