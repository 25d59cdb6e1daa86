// Results files in HDF5 with the layout of docs/conventions.md Sec. 4.
//
// Every dataset carries a string attribute `units`; complex values use the compound type {r, i}
// (what h5py and NumPy read as complex). The file is written as OUT.h5.partial and renamed to
// OUT.h5 only by commit(): a run that fails leaves no file that looks complete.
#pragma once

#include <complex>
#include <cstdint>
#include <string>
#include <vector>

namespace rollnoise::io {

class Hdf5Writer {
 public:
  explicit Hdf5Writer(std::string path);
  ~Hdf5Writer();  // removes the partial file unless committed
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  /// Dataset of doubles with shape `dims` (empty dims: scalar). Intermediate groups are created.
  void write(const std::string& path, const std::vector<double>& data,
             const std::vector<std::size_t>& dims, const std::string& units);
  void write(const std::string& path, double value, const std::string& units);
  void write(const std::string& path, const std::vector<std::int8_t>& data,
             const std::vector<std::size_t>& dims, const std::string& units);
  void write(const std::string& path, const std::vector<int>& data,
             const std::vector<std::size_t>& dims, const std::string& units);
  void write(const std::string& path, const std::vector<std::complex<double>>& data,
             const std::vector<std::size_t>& dims, const std::string& units);
  /// Strings (fixed length, UTF-8), e.g. a table's text column.
  void write(const std::string& path, const std::vector<std::string>& data, const std::string& units);
  /// String attribute on a group or dataset (created as a group if missing).
  void attribute(const std::string& object, const std::string& name, const std::string& value);

  /// Close the file and move it to its final name.
  void commit();
  const std::string& path() const { return path_; }

 private:
  void write_raw(const std::string& path, long type, const void* data,
                 const std::vector<std::size_t>& dims, const std::string& units);
  std::string path_, partial_;
  long file_ = -1;
  bool committed_ = false;
};

}  // namespace rollnoise::io
