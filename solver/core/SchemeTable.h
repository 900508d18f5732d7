#pragma once
/// @file SchemeTable.h
/// @brief Schemes are chosen by name in the case file. Each physics header lists its schemes
/// in a table of entries { key, scheme, reference }; these look names up in such a table.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wcmps {

/// One row of a scheme table: the name in the case file, the scheme, and its paper.
template <class Scheme>
struct SchemeEntry {
  std::string_view key;
  Scheme scheme;
  std::string_view reference;
};

/// The scheme a case-file key names, if any.
template <class Entry, std::size_t N>
auto scheme_from_key(const Entry (&table)[N], std::string_view key)
    -> std::optional<decltype(table[0].scheme)> {
  for (const auto& e : table) {
    if (e.key == key) return e.scheme;
  }
  return std::nullopt;
}

/// The case-file key of a scheme.
template <class Entry, std::size_t N, class Scheme>
std::string_view scheme_key(const Entry (&table)[N], Scheme s) {
  for (const auto& e : table) {
    if (e.scheme == s) return e.key;
  }
  return "?";
}

/// Every key of the table, in its order (the first is the default).
template <class Entry, std::size_t N>
std::vector<std::string> scheme_keys(const Entry (&table)[N]) {
  std::vector<std::string> keys;
  for (const auto& e : table) keys.emplace_back(e.key);
  return keys;
}

}  // namespace wcmps
