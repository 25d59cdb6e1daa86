#include "io/hdf5_writer.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/errors.hpp"

namespace rollnoise::io {
namespace {

// The deepest message of HDF5's error stack (for a failed write: the system's reason, e.g.
// "... errno = 28, error message = 'No space left on device'"), or "".
std::string hdf5_reason() {
  std::string reason;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* out) -> herr_t {
        if (n == 0 && e->desc) *static_cast<std::string*>(out) = e->desc;
        return 0;
      },
      &reason);
  // a system error reads "file write failed: time = ..., errno = 28, error message = 'No space
  // left on device', ...": keep the system's message
  const std::string tag = "error message = '";
  const auto at = reason.find(tag);
  if (at != std::string::npos) {
    const auto from = at + tag.size();
    return reason.substr(from, reason.find('\'', from) - from);
  }
  for (char& c : reason)
    if (c == '\n') c = ' ';
  return reason;
}

// A file whose flush or close failed stays open inside the HDF5 library, and the library's own
// clean-up at exit would flush it again and crash (exit 139 after the error message). The run has
// already reported the failure and removed the temporary: the library's exit clean-up is turned
// off (before any other HDF5 call, at static initialisation); every file is closed explicitly.
const bool kNoHdf5AtExit = H5dont_atexit() >= 0;

// An HDF5 identifier closed when it goes out of scope (also when a write throws).
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id_; }
  /// Close now and return the status: closing a dataset or an attribute writes what HDF5 buffered
  /// (its data sieve), so a full disk may show only here.
  herr_t close() {
    const herr_t status = close_(id_);
    id_ = -1;
    return status;
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

}  // namespace

// Every call that writes is checked: a failure (a full disk, a file-size limit, a quota) throws
// with the file and the reason, and the temporary is removed (docs/conventions.md, Output files).
void Hdf5Writer::check(long status, const std::string& what) const {
  if (status >= 0) return;
  const std::string reason = hdf5_reason();
  throw std::runtime_error("writing " + path_ + " (temporary " + temp_.path() + "): HDF5 cannot " +
                           what + (reason.empty() ? std::string() : ": " + reason));
}

Hdf5Writer::Hdf5Writer(std::string path) : path_(std::move(path)), temp_(path_, "-o") {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by exceptions here
  const Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  // closing the file closes everything in it, so that its close really writes and reports errors
  H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG);
  // the 1.8 format: attributes above 64 kB (a long case text or command line) go to dense storage
  H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  file_ = H5Fcreate(temp_.path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  if (file_ < 0)
    throw InputError("-o", "-o " + path_ + ": cannot create the HDF5 file " + temp_.path());
  try {
    const Provenance& p = provenance();
    attribute("/", "program_version", p.program_version);
    attribute("/", "command_line", p.command_line);
    attribute("/", "command", p.command);
    attribute("/", "date", p.date);
  } catch (...) {
    H5Fclose(file_);  // the destructor does not run for a throwing constructor
    throw;
  }
}

Hdf5Writer::~Hdf5Writer() {
  if (file_ >= 0) H5Fclose(file_);  // then temp_ removes the temporary unless committed
}

void Hdf5Writer::set_string_attribute(long obj, const std::string& name, const std::string& value) {
  const Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_cset(type, H5T_CSET_UTF8);
  const Id space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(obj, name.c_str()) > 0)
    check(H5Adelete(obj, name.c_str()), "replace attribute " + name);
  Id attr(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  check(attr, "create attribute " + name);
  check(H5Awrite(attr, type, value.empty() ? "" : value.c_str()), "write attribute " + name);
  check(attr.close(), "write attribute " + name);
}

void Hdf5Writer::write_raw(const std::string& path, long type, const void* data,
                           const std::vector<std::size_t>& dims, const std::string& units) {
  std::vector<hsize_t> d(dims.begin(), dims.end());
  const Id space(
      d.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(int(d.size()), d.data(), nullptr),
      H5Sclose);
  const Id lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(lcpl, 1);
  Id set(H5Dcreate2(file_, path.c_str(), type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  check(set, "create dataset " + path);
  check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + path);
  set_string_attribute(set, "units", units);
  check(set.close(), "write " + path);
}

void Hdf5Writer::write(const std::string& path, const std::vector<double>& data,
                       const std::vector<std::size_t>& dims, const std::string& units) {
  write_raw(path, H5T_NATIVE_DOUBLE, data.data(), dims, units);
}

void Hdf5Writer::write(const std::string& path, double value, const std::string& units) {
  write_raw(path, H5T_NATIVE_DOUBLE, &value, {}, units);
}

void Hdf5Writer::write(const std::string& path, const std::vector<std::int8_t>& data,
                       const std::vector<std::size_t>& dims, const std::string& units) {
  write_raw(path, H5T_NATIVE_INT8, data.data(), dims, units);
}

void Hdf5Writer::write(const std::string& path, const std::vector<int>& data,
                       const std::vector<std::size_t>& dims, const std::string& units) {
  write_raw(path, H5T_NATIVE_INT, data.data(), dims, units);
}

void Hdf5Writer::write(const std::string& path, const std::vector<std::string>& data,
                       const std::string& units) {
  std::size_t width = 1;
  for (const auto& s : data) width = std::max(width, s.size());
  std::vector<char> buf(data.size() * width, '\0');
  for (std::size_t i = 0; i < data.size(); ++i)
    std::copy(data[i].begin(), data[i].end(), buf.begin() + i * width);
  const Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, width);
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_UTF8);
  write_raw(path, type, buf.data(), {data.size()}, units);
}

void Hdf5Writer::write(const std::string& path, const std::vector<std::complex<double>>& data,
                       const std::vector<std::size_t>& dims, const std::string& units) {
  const Id type(H5Tcreate(H5T_COMPOUND, sizeof(std::complex<double>)), H5Tclose);
  H5Tinsert(type, "r", 0, H5T_NATIVE_DOUBLE);
  H5Tinsert(type, "i", sizeof(double), H5T_NATIVE_DOUBLE);
  write_raw(path, type, data.data(), dims, units);
}

long Hdf5Writer::open_object(const std::string& object) {
  hid_t obj = -1;
  if (object == "/" || H5Lexists(file_, object.c_str(), H5P_DEFAULT) > 0) {
    obj = H5Oopen(file_, object.c_str(), H5P_DEFAULT);
  } else {
    const Id lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_create_intermediate_group(lcpl, 1);
    obj = H5Gcreate2(file_, object.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
  }
  check(obj, "open " + object);
  return obj;
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name,
                           const std::string& value) {
  Id obj(open_object(object), H5Oclose);
  set_string_attribute(obj, name, value);
  check(obj.close(), "write attribute " + name + " of " + object);
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name,
                           std::uint64_t value) {
  Id obj(open_object(object), H5Oclose);
  if (H5Aexists(obj, name.c_str()) > 0)
    check(H5Adelete(obj, name.c_str()), "replace attribute " + name);
  const Id space(H5Screate(H5S_SCALAR), H5Sclose);
  Id attr(H5Acreate2(obj, name.c_str(), H5T_NATIVE_UINT64, space, H5P_DEFAULT, H5P_DEFAULT),
          H5Aclose);
  check(attr, "create attribute " + name);
  check(H5Awrite(attr, H5T_NATIVE_UINT64, &value), "write attribute " + name);
  check(attr.close(), "write attribute " + name);
  check(obj.close(), "write attribute " + name + " of " + object);
}

void Hdf5Writer::commit() {
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush the file");
  const herr_t closed = H5Fclose(file_);
  file_ = -1;
  check(closed, "close the file");
  sync_file(temp_.path(),
            path_);  // the data on disk (a full disk can show only now), then the rename
  temp_.commit();
}

}  // namespace rollnoise::io
