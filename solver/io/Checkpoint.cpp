#include "io/Checkpoint.h"

#include <vtk_hdf5.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/Error.h"
#include "core/Version.h"
#include "io/AtomicFile.h"

namespace fs = std::filesystem;

namespace wcmps {
namespace {

constexpr const char* kPrefix = "checkpoint_";
constexpr const char* kSuffix = ".h5";
constexpr const char* kFormat = "wcmps checkpoint";

/// An HDF5 identifier, closed with the function that fits it.
class Handle {
 public:
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), close_(closer) {}
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// Our errors carry the file and the reason; HDF5's own error stack would only repeat them.
void silence_hdf5() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

std::int64_t sequence_of(const fs::path& p) {
  const std::string s = p.filename().string();
  return std::stoll(
      s.substr(std::strlen(kPrefix), s.size() - std::strlen(kPrefix) - std::strlen(kSuffix)));
}

class Hdf5Writer final : public StateWriter {
 public:
  Hdf5Writer(hid_t file, std::string name) : file_(file), name_(std::move(name)) {}

  void field(const std::string& name, std::initializer_list<const double*> components,
             std::size_t count) override {
    const hsize_t dims[2] = {components.size(), count};
    Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
    Handle ds(H5Dcreate2(file_, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT),
              H5Dclose);
    check(space.ok() && ds.ok(), name);
    if (count == 0) return;
    const hsize_t n = count;
    Handle memory(H5Screate_simple(1, &n, nullptr), H5Sclose);
    hsize_t row = 0;
    for (const double* c : components) {
      const hsize_t start[2] = {row++, 0}, size[2] = {1, count};
      check(
          H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, size, nullptr) >= 0 &&
              H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, c) >= 0,
          name);
    }
  }
  void field(const std::string& name, const std::int32_t* v, std::size_t count) override {
    integers(name, H5T_STD_I32LE, H5T_NATIVE_INT32, v, count);
  }
  void field(const std::string& name, const std::uint8_t* v, std::size_t count) override {
    integers(name, H5T_STD_U8LE, H5T_NATIVE_UINT8, v, count);
  }
  void field(const std::string& name, const std::int64_t* v, std::size_t count) override {
    integers(name, H5T_STD_I64LE, H5T_NATIVE_INT64, v, count);
  }
  void scalar(const std::string& name, double value) override {
    attribute(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
  }
  void integer(const std::string& name, std::int64_t value) override {
    attribute(name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
  }
  void text(const std::string& name, const std::string& value) {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    check(type.ok() && H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1)) >= 0, name);
    const std::string padded = value.empty() ? std::string(1, '\0') : value;
    attribute(name, type.get(), type.get(), padded.data());
  }

 private:
  void check(bool ok, const std::string& what) const {
    if (!ok) throw IoError("cannot write checkpoint " + name_ + " (" + what + ")");
  }
  void integers(const std::string& name, hid_t file_type, hid_t memory_type, const void* v,
                std::size_t count) {
    const hsize_t n = count;
    Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    Handle ds(H5Dcreate2(file_, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT),
              H5Dclose);
    check(
        space.ok() && ds.ok() &&
            (count == 0 || H5Dwrite(ds.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0),
        name);
  }
  void attribute(const std::string& name, hid_t file_type, hid_t memory_type, const void* v) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle a(H5Acreate2(file_, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose);
    check(space.ok() && a.ok() && H5Awrite(a.get(), memory_type, v) >= 0, name);
  }

  hid_t file_;
  std::string name_;
};

class Hdf5Reader final : public StateReader {
 public:
  Hdf5Reader(hid_t file, std::string name) : file_(file), name_(std::move(name)) {}

  void field(const std::string& name, std::initializer_list<double*> components,
             std::size_t count) override {
    Handle ds = open(name);
    Handle space(H5Dget_space(ds.get()), H5Sclose);
    hsize_t dims[2] = {0, 0};
    if (!space.ok() || H5Sget_simple_extent_ndims(space.get()) != 2 ||
        H5Sget_simple_extent_dims(space.get(), dims, nullptr) != 2 ||
        dims[0] != components.size() || dims[1] != count) {
      fail(name + " has " + shape(space.get()) + " values, expected " +
           std::to_string(components.size()) + " x " + std::to_string(count));
    }
    if (count == 0) return;
    const hsize_t n = count;
    Handle memory(H5Screate_simple(1, &n, nullptr), H5Sclose);
    hsize_t row = 0;
    for (double* c : components) {
      const hsize_t start[2] = {row++, 0}, size[2] = {1, count};
      if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, size, nullptr) < 0 ||
          H5Dread(ds.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, c) < 0) {
        fail("cannot read " + name);
      }
    }
  }
  void field(const std::string& name, std::int32_t* v, std::size_t count) override {
    integers(name, H5T_NATIVE_INT32, v, count);
  }
  void field(const std::string& name, std::uint8_t* v, std::size_t count) override {
    integers(name, H5T_NATIVE_UINT8, v, count);
  }
  void field(const std::string& name, std::int64_t* v, std::size_t count) override {
    integers(name, H5T_NATIVE_INT64, v, count);
  }
  std::size_t count(const std::string& name) override {
    Handle ds = open(name);
    Handle space(H5Dget_space(ds.get()), H5Sclose);
    hsize_t dims[2] = {0, 0};
    const int rank = space.ok() ? H5Sget_simple_extent_dims(space.get(), dims, nullptr) : -1;
    if (rank < 1 || rank > 2) fail(name + " is not a field");
    return static_cast<std::size_t>(dims[rank - 1]);
  }
  bool has(const std::string& name) override {
    return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0;
  }
  double scalar(const std::string& name) override {
    double v = 0.0;
    attribute(name, H5T_NATIVE_DOUBLE, &v);
    return v;
  }
  std::int64_t integer(const std::string& name) override {
    std::int64_t v = 0;
    attribute(name, H5T_NATIVE_INT64, &v);
    return v;
  }
  std::string text(const std::string& name) {
    if (H5Aexists(file_, name.c_str()) <= 0) fail("no " + name);
    Handle a(H5Aopen(file_, name.c_str(), H5P_DEFAULT), H5Aclose);
    Handle type(a.ok() ? H5Aget_type(a.get()) : -1, H5Tclose);
    if (!type.ok() || H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get())) {
      fail(name + " is not a text");
    }
    std::string v(H5Tget_size(type.get()), '\0');
    if (H5Aread(a.get(), type.get(), v.data()) < 0) fail("cannot read " + name);
    v.resize(std::strlen(v.c_str()));
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw CheckpointError(name_ + ": " + what);
  }
  static std::string shape(hid_t space) {
    hsize_t dims[2] = {0, 0};
    const int rank = space >= 0 ? H5Sget_simple_extent_dims(space, dims, nullptr) : -1;
    if (rank == 1) return std::to_string(dims[0]);
    if (rank == 2) return std::to_string(dims[0]) + " x " + std::to_string(dims[1]);
    return "no";
  }
  Handle open(const std::string& name) const {
    if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) <= 0) fail("no field " + name);
    Handle ds(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!ds.ok()) fail("cannot open " + name);
    return ds;
  }
  void integers(const std::string& name, hid_t memory_type, void* v, std::size_t count) {
    Handle ds = open(name);
    Handle space(H5Dget_space(ds.get()), H5Sclose);
    hsize_t n = 0;
    if (!space.ok() || H5Sget_simple_extent_ndims(space.get()) != 1 ||
        H5Sget_simple_extent_dims(space.get(), &n, nullptr) != 1 || n != count) {
      fail(name + " has " + shape(space.get()) + " values, expected " + std::to_string(count));
    }
    if (count > 0 && H5Dread(ds.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0) {
      fail("cannot read " + name);
    }
  }
  void attribute(const std::string& name, hid_t memory_type, void* v) const {
    if (H5Aexists(file_, name.c_str()) <= 0) fail("no value " + name);
    Handle a(H5Aopen(file_, name.c_str(), H5P_DEFAULT), H5Aclose);
    Handle space(a.ok() ? H5Aget_space(a.get()) : -1, H5Sclose);
    if (!space.ok() || H5Sget_simple_extent_npoints(space.get()) != 1 ||
        H5Aread(a.get(), memory_type, v) < 0) {
      fail("cannot read " + name);
    }
  }

  hid_t file_;
  std::string name_;
};

}  // namespace

CheckpointStore::CheckpointStore(fs::path dir, int keep) : dir_(std::move(dir)), keep_(keep) {
  silence_hdf5();
}

bool CheckpointStore::is_checkpoint_name(const std::string& name) {
  const std::size_t p = std::strlen(kPrefix), s = std::strlen(kSuffix);
  if (name.size() <= p + s || name.rfind(kPrefix, 0) != 0 ||
      name.compare(name.size() - s, s, kSuffix) != 0) {
    return false;
  }
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(p),
                     name.end() - static_cast<std::ptrdiff_t>(s),
                     [](char c) { return c >= '0' && c <= '9'; });
}

std::vector<fs::path> CheckpointStore::files() const {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir_, ec)) {
    if (is_checkpoint_name(e.path().filename().string())) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end(),
            [](const fs::path& a, const fs::path& b) { return sequence_of(a) < sequence_of(b); });
  return out;
}

/// The core driver's memory, reached through HDF5's file image callbacks, so that a checkpoint
/// is written to the disk from it: H5Fget_file_image would first copy it (22 MB at DL 2 mm, at
/// the run's peak of memory). The driver zero-fills what it allocates beyond what it wrote.
struct CoreImage {
  void* data = nullptr;
  std::size_t size = 0;  // allocated

  static CoreImage& of(void* udata) { return *static_cast<CoreImage*>(udata); }
  static void* allocate(std::size_t size, H5FD_file_image_op_t, void* udata) {
    CoreImage& im = of(udata);
    im.data = std::malloc(size);
    im.size = im.data ? size : 0;
    return im.data;
  }
  static void* copy(void* dest, const void* src, std::size_t size, H5FD_file_image_op_t, void*) {
    return std::memcpy(dest, src, size);
  }
  static void* resize(void* ptr, std::size_t size, H5FD_file_image_op_t, void* udata) {
    CoreImage& im = of(udata);
    void* p = std::realloc(ptr, size);
    if (p) {
      im.data = p;
      im.size = size;
    }
    return p;
  }
  static herr_t release(void* ptr, H5FD_file_image_op_t, void* udata) {
    CoreImage& im = of(udata);
    if (ptr == im.data) im = {};
    std::free(ptr);
    return 0;
  }
  // The property list is copied when the file is created; every copy shares this image.
  static void* share(void* udata) { return udata; }
  static herr_t unshare(void*) { return 0; }
};

fs::path CheckpointStore::write(const std::string& case_text,
                                const std::function<void(StateWriter&)>& save) {
  const auto existing = files();
  const std::int64_t seq = existing.empty() ? 1 : sequence_of(existing.back()) + 1;
  char name[64];
  std::snprintf(name, sizeof name, "%s%06lld%s", kPrefix, static_cast<long long>(seq), kSuffix);
  const fs::path path = dir_ / name;
  // Built in memory (HDF5's core driver) and written by us: HDF5 1.10 crashes at exit when
  // closing a file failed (a disk that filled up), and this way the file is written
  // atomically.
  {
    CoreImage image;
    H5FD_file_image_callbacks_t callbacks{&CoreImage::allocate,
                                          &CoreImage::copy,
                                          &CoreImage::resize,
                                          &CoreImage::release,
                                          &CoreImage::share,
                                          &CoreImage::unshare,
                                          &image};
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    const bool core = access.ok() && H5Pset_fapl_core(access.get(), 1 << 20, 0) >= 0 &&
                      H5Pset_file_image_callbacks(access.get(), &callbacks) >= 0;
    Handle file(core ? H5Fcreate(name, H5F_ACC_TRUNC, H5P_DEFAULT, access.get()) : -1, H5Fclose);
    if (!file.ok()) throw IoError("cannot create checkpoint " + path.string() + " in memory");
    Hdf5Writer w(file.get(), path.string());
    w.text("format", kFormat);
    w.integer("format_version", kFormatVersion);
    w.text("wcmps_version", kVersion);
    w.text("case_text", case_text);
    save(w);
    w.integer("complete", 1);
    // The file's size is its end of allocated address space, which H5Fget_file_image gives
    // without copying; the bytes are the driver's memory up to there.
    const ssize_t size =
        H5Fflush(file.get(), H5F_SCOPE_LOCAL) >= 0 ? H5Fget_file_image(file.get(), nullptr, 0) : -1;
    if (size <= 0 || image.data == nullptr || static_cast<std::size_t>(size) > image.size) {
      throw IoError("cannot encode checkpoint " + path.string());
    }
    write_file_atomically(path,
                          {static_cast<const char*>(image.data), static_cast<std::size_t>(size)},
                          Durability::Synced);
  }
  auto all = files();
  for (std::size_t k = 0; k + static_cast<std::size_t>(keep_) < all.size(); ++k) {
    std::error_code ec;
    fs::remove(all[k], ec);
  }
  return path;
}

fs::path CheckpointStore::load_newest(const std::string& case_text,
                                      const std::function<void(StateReader&)>& load,
                                      std::vector<std::string>& rejected) {
  auto all = files();
  if (all.empty()) {
    throw CheckpointError(dir_.string() +
                          " holds no checkpoint (checkpoint_NNNNNN.h5): the run stopped before "
                          "its first one; start it again");
  }
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    const std::string name = it->string();
    try {
      Handle file(H5Fopen(it->c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
      if (!file.ok()) throw CheckpointError(name + ": not a readable HDF5 file");
      Hdf5Reader r(file.get(), name);
      if (r.text("format") != kFormat) throw CheckpointError(name + ": not a wcmps checkpoint");
      if (r.integer("format_version") != kFormatVersion) {
        throw CheckpointError(name + ": format version " +
                              std::to_string(r.integer("format_version")) + ", this wcmps reads " +
                              std::to_string(kFormatVersion));
      }
      if (r.integer("complete") != 1) throw CheckpointError(name + ": incomplete");
      if (r.text("case_text") != case_text) {
        throw CheckpointError(name + ": written for another case file than the run's " +
                              "case.toml (was it edited?)");
      }
      load(r);
    } catch (const CheckpointError& e) {
      rejected.push_back(e.what());
      continue;
    }
    // Newer ones could not be used: out of the way, so that new checkpoints follow this one.
    for (auto newer = all.rbegin(); newer != it; ++newer) {
      std::error_code ec;
      fs::remove(*newer, ec);
    }
    return *it;
  }
  std::string why;
  for (const auto& r : rejected) why += "\n  " + r;
  throw CheckpointError("no usable checkpoint in " + dir_.string() + ":" + why);
}

}  // namespace wcmps
