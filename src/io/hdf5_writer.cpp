#include "io/hdf5_writer.hpp"

#include <hdf5.h>

#include <algorithm>

#include "core/errors.hpp"

namespace rollnoise::io {
namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what);
}

void set_string_attribute(hid_t obj, const std::string& name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_cset(type, H5T_CSET_UTF8);
  const hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  const hid_t attr = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  check(H5Awrite(attr, type, value.empty() ? "" : value.c_str()), "attribute " + name);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

}  // namespace

Hdf5Writer::Hdf5Writer(std::string path) : path_(std::move(path)), temp_(path_, "-o") {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by exceptions here
  file_ = H5Fcreate(temp_.path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw InputError("-o", "-o " + path_ + ": cannot create the HDF5 file " + temp_.path());
  try {
    const Provenance& p = provenance();
    attribute("/", "program_version", p.program_version);
    attribute("/", "command_line", p.command_line);
    attribute("/", "date", p.date);
  } catch (...) {
    H5Fclose(file_);  // the destructor does not run for a throwing constructor
    throw;
  }
}

Hdf5Writer::~Hdf5Writer() {
  if (file_ >= 0) H5Fclose(file_);  // then temp_ removes the temporary unless committed
}

void Hdf5Writer::write_raw(const std::string& path, long type, const void* data,
                           const std::vector<std::size_t>& dims, const std::string& units) {
  std::vector<hsize_t> d(dims.begin(), dims.end());
  const hid_t space = d.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(d.size(), d.data(), nullptr);
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const hid_t set = H5Dcreate2(file_, path.c_str(), type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) throw std::runtime_error("HDF5: cannot create dataset " + path);
  check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + path);
  set_string_attribute(set, "units", units);
  H5Dclose(set);
  H5Pclose(lcpl);
  H5Sclose(space);
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

void Hdf5Writer::write(const std::string& path, const std::vector<std::string>& data, const std::string& units) {
  std::size_t width = 1;
  for (const auto& s : data) width = std::max(width, s.size());
  std::vector<char> buf(data.size() * width, '\0');
  for (std::size_t i = 0; i < data.size(); ++i) std::copy(data[i].begin(), data[i].end(), buf.begin() + i * width);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, width);
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_UTF8);
  write_raw(path, type, buf.data(), {data.size()}, units);
  H5Tclose(type);
}

void Hdf5Writer::write(const std::string& path, const std::vector<std::complex<double>>& data,
                       const std::vector<std::size_t>& dims, const std::string& units) {
  const hid_t type = H5Tcreate(H5T_COMPOUND, sizeof(std::complex<double>));
  H5Tinsert(type, "r", 0, H5T_NATIVE_DOUBLE);
  H5Tinsert(type, "i", sizeof(double), H5T_NATIVE_DOUBLE);
  write_raw(path, type, data.data(), dims, units);
  H5Tclose(type);
}

long Hdf5Writer::open_object(const std::string& object) {
  hid_t obj = -1;
  if (object == "/" || H5Lexists(file_, object.c_str(), H5P_DEFAULT) > 0) {
    obj = H5Oopen(file_, object.c_str(), H5P_DEFAULT);
  } else {
    const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(lcpl, 1);
    obj = H5Gcreate2(file_, object.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
    H5Pclose(lcpl);
  }
  if (obj < 0) throw std::runtime_error("HDF5: cannot open " + object);
  return obj;
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, const std::string& value) {
  const hid_t obj = open_object(object);
  set_string_attribute(obj, name, value);
  H5Oclose(obj);
}

void Hdf5Writer::attribute(const std::string& object, const std::string& name, std::uint64_t value) {
  const hid_t obj = open_object(object);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(obj, name.c_str(), H5T_NATIVE_UINT64, space, H5P_DEFAULT, H5P_DEFAULT);
  check(H5Awrite(attr, H5T_NATIVE_UINT64, &value), "attribute " + name);
  H5Aclose(attr);
  H5Sclose(space);
  H5Oclose(obj);
}

void Hdf5Writer::commit() {
  check(H5Fclose(file_), "close " + temp_.path());
  file_ = -1;
  temp_.commit();
}

}  // namespace rollnoise::io
