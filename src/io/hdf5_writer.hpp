// Results files in HDF5 with the layout of docs/conventions.md Sec. 4.
//
// Every dataset carries a string attribute `units`; complex values use the compound type {r, i}
// (what h5py and NumPy read as complex). The file is written to a unique temporary beside OUT.h5
// (io/output_files.hpp) and renamed to OUT.h5 only by commit(), after every write, the flush and the
// close have succeeded: a run that fails (also for a full disk or a file-size limit) or is
// interrupted leaves neither the temporary nor a file that looks complete. Attributes may exceed
// 64 kB (the file uses the HDF5 1.8 format, dense attribute storage). The root group holds
// the provenance attributes program_version, command_line, command and date (output_files.hpp).
#pragma once

#include <complex>
#include <cstdint>
#include <string>
#include <vector>

#include "io/output_files.hpp"

namespace rollnoise::io {

class Hdf5Writer {
 public:
  explicit Hdf5Writer(std::string path);
  ~Hdf5Writer();  // removes the temporary unless committed
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
  /// Unsigned 64-bit integer attribute (e.g. a seed) on a group or dataset.
  void attribute(const std::string& object, const std::string& name, std::uint64_t value);

  /// Flush and close the file (each checked), sync it to disk, and only then move it to its final
  /// name. std::runtime_error naming the file and the reason if any of it fails (a full disk, a
  /// file-size limit): the temporary is then removed when the writer is dropped.
  void commit();
  const std::string& path() const { return path_; }

 private:
  void write_raw(const std::string& path, long type, const void* data,
                 const std::vector<std::size_t>& dims, const std::string& units);
  long open_object(const std::string& object);  // group or dataset (a group is created if missing)
  void set_string_attribute(long obj, const std::string& name, const std::string& value);
  void check(long status, const std::string& what) const;  // throws with the file and HDF5's reason
  std::string path_;
  TemporaryFile temp_;
  long file_ = -1;
};

}  // namespace rollnoise::io
