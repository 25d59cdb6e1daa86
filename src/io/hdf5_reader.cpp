#include "io/hdf5_reader.hpp"

#include <hdf5.h>

namespace rollnoise::io {

Hdf5Reader::Hdf5Reader(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // a missing file or object is an answer, not an error
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
}

Hdf5Reader::~Hdf5Reader() {
  if (file_ >= 0) H5Fclose(file_);
}

std::optional<std::vector<double>> Hdf5Reader::numbers(const std::string& path, std::vector<std::size_t>* dims) const {
  if (file_ < 0 || H5Lexists(file_, path.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
  const hid_t set = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
  if (set < 0) return std::nullopt;
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> d(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space, d.data(), nullptr);
  std::size_t n = 1;
  for (hsize_t x : d) n *= x;
  std::vector<double> v(n);
  const hid_t type = H5Dget_type(set);
  const bool numeric = H5Tget_class(type) == H5T_FLOAT || H5Tget_class(type) == H5T_INTEGER;
  const herr_t st = numeric ? H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : -1;
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(set);
  if (st < 0) return std::nullopt;
  if (dims) dims->assign(d.begin(), d.end());
  return v;
}

std::optional<std::string> Hdf5Reader::attribute(const std::string& object, const std::string& name) const {
  if (file_ < 0) return std::nullopt;
  if (H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
  const hid_t attr = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (attr < 0) return std::nullopt;
  const hid_t type = H5Aget_type(attr);
  std::optional<std::string> out;
  if (H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type)) {
    std::string s(H5Tget_size(type), '\0');
    if (H5Aread(attr, type, s.data()) >= 0) out = std::string(s.c_str());
  }
  H5Tclose(type);
  H5Aclose(attr);
  return out;
}

}  // namespace rollnoise::io
