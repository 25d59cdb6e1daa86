// Reading back rollnoise's own HDF5 results (what `collect` gathers from the cases of a study).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rollnoise::io {

class Hdf5Reader {
 public:
  /// Opens `path` read-only; NumericalError-free: check ok() (a missing or corrupt file is not open).
  explicit Hdf5Reader(const std::string& path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  bool ok() const { return file_ >= 0; }
  /// A dataset of numbers as doubles (integers converted) and its shape; nullopt when missing.
  std::optional<std::vector<double>> numbers(const std::string& path, std::vector<std::size_t>* dims = nullptr) const;
  /// A string attribute of a group or dataset; nullopt when missing.
  std::optional<std::string> attribute(const std::string& object, const std::string& name) const;

 private:
  long file_ = -1;
};

}  // namespace rollnoise::io
