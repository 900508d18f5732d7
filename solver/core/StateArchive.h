#pragma once
/// @file StateArchive.h
/// @brief Where the state of a run goes for a checkpoint and where it comes back from: named
/// per-particle fields (one array per component, as the particles hold them) and named
/// scalars. The solver's classes save and load through these interfaces and know nothing of
/// the file format; io/Checkpoint implements them on HDF5.
///
/// Field names are those of particles/Fields.h where the field is one of them ("velocity",
/// "pressure", "number_density", "free_surface", "id"), so that frames and checkpoints agree.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>

namespace wcmps {

class StateWriter {
 public:
  virtual ~StateWriter() = default;
  /// A field of `count` tuples whose components are the arrays `components` (x, y, ...).
  virtual void field(const std::string& name, std::initializer_list<const double*> components,
                     std::size_t count) = 0;
  virtual void field(const std::string& name, const std::int32_t* values, std::size_t count) = 0;
  virtual void field(const std::string& name, const std::uint8_t* values, std::size_t count) = 0;
  virtual void field(const std::string& name, const std::int64_t* values, std::size_t count) = 0;
  virtual void scalar(const std::string& name, double value) = 0;
  virtual void integer(const std::string& name, std::int64_t value) = 0;
};

/// Reads what a StateWriter wrote. Every call throws CheckpointError if the name is missing or
/// its size or number of components differs from what the caller expects.
class StateReader {
 public:
  virtual ~StateReader() = default;
  virtual void field(const std::string& name, std::initializer_list<double*> components,
                     std::size_t count) = 0;
  virtual void field(const std::string& name, std::int32_t* values, std::size_t count) = 0;
  virtual void field(const std::string& name, std::uint8_t* values, std::size_t count) = 0;
  virtual void field(const std::string& name, std::int64_t* values, std::size_t count) = 0;
  /// The number of tuples of a field (0 if it has none), for fields whose length varies.
  virtual std::size_t count(const std::string& name) = 0;
  /// Whether the archive holds the field: for fields that earlier versions did not write.
  virtual bool has(const std::string& name) = 0;
  virtual double scalar(const std::string& name) = 0;
  virtual std::int64_t integer(const std::string& name) = 0;
};

}  // namespace wcmps
