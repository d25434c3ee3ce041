#include "core/h5.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace lbdem {

namespace {
void check(herr_t rc, const std::string& what) {
  if (rc < 0) throw std::runtime_error("HDF5: " + what + " failed");
}
void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot rename " + tmp + " to " + path);
}
}  // namespace

H5Out::H5Out(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(tmp_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("cannot create " + tmp_);
}

H5Out::~H5Out() {
  if (file_ >= 0) {
    H5Fclose(file_);
    std::remove(tmp_.c_str());
  }
}

void H5Out::group(const std::string& name) {
  hid_t g = H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) throw std::runtime_error("HDF5: cannot create group " + name);
  H5Gclose(g);
}

void H5Out::write_raw(const std::string& name, hid_t type, const void* data, int rank,
                      const hsize_t* dims) {
  hid_t space = H5Screate_simple(rank, dims, nullptr);
  hid_t set = H5Dcreate2(file_, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) {
    H5Sclose(space);
    throw std::runtime_error("HDF5: cannot create dataset " + name);
  }
  bool empty = false;
  for (int r = 0; r < rank; ++r) empty = empty || dims[r] == 0;
  if (!empty) check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + name);
  H5Dclose(set);
  H5Sclose(space);
}

void H5Out::write(const std::string& name, const std::vector<double>& v) {
  const hsize_t d[1] = {v.size()};
  write_raw(name, H5T_NATIVE_DOUBLE, v.data(), 1, d);
}
void H5Out::write(const std::string& name, const std::vector<Vec3>& v) {
  const hsize_t d[2] = {v.size(), 3};
  write_raw(name, H5T_NATIVE_DOUBLE, v.empty() ? nullptr : v.front().data(), 2, d);
}
void H5Out::write(const std::string& name, const std::vector<std::int64_t>& v) {
  const hsize_t d[1] = {v.size()};
  write_raw(name, H5T_NATIVE_INT64, v.data(), 1, d);
}
void H5Out::write(const std::string& name, const std::vector<std::int32_t>& v) {
  const hsize_t d[1] = {v.size()};
  write_raw(name, H5T_NATIVE_INT32, v.data(), 1, d);
}
void H5Out::write(const std::string& name, const std::vector<std::uint8_t>& v) {
  const hsize_t d[1] = {v.size()};
  write_raw(name, H5T_NATIVE_UINT8, v.data(), 1, d);
}
void H5Out::write_matrix(const std::string& name, const std::vector<double>& v, std::size_t rows,
                         std::size_t cols) {
  const hsize_t d[2] = {rows, cols};
  write_raw(name, H5T_NATIVE_DOUBLE, v.data(), 2, d);
}

void H5Out::write_array(const std::string& name, const std::vector<double>& v,
                        const std::vector<std::size_t>& dims) {
  std::vector<hsize_t> d(dims.begin(), dims.end());
  write_raw(name, H5T_NATIVE_DOUBLE, v.data(), static_cast<int>(d.size()), d.data());
}

void H5Out::attr(const std::string& name, double v, const std::string& object) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate_by_name(file_, object.c_str(), name.c_str(), H5T_NATIVE_DOUBLE, space,
                              H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(a, "attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_DOUBLE, &v), "attribute " + name);
  H5Aclose(a);
  H5Sclose(space);
}
void H5Out::attr(const std::string& name, std::int64_t v, const std::string& object) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate_by_name(file_, object.c_str(), name.c_str(), H5T_NATIVE_INT64, space,
                              H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(a, "attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_INT64, &v), "attribute " + name);
  H5Aclose(a);
  H5Sclose(space);
}
void H5Out::attr(const std::string& name, const std::string& v, const std::string& object) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, v.size() + 1);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate_by_name(file_, object.c_str(), name.c_str(), type, space, H5P_DEFAULT,
                              H5P_DEFAULT, H5P_DEFAULT);
  check(a, "attribute " + name);
  check(H5Awrite(a, type, v.c_str()), "attribute " + name);
  H5Aclose(a);
  H5Sclose(space);
  H5Tclose(type);
}

void H5Out::external_link(const std::string& name, const std::string& file,
                          const std::string& object) {
  check(H5Lcreate_external(file.c_str(), object.c_str(), file_, name.c_str(), H5P_DEFAULT,
                           H5P_DEFAULT),
        "external link " + name);
}

void H5Out::commit() {
  check(H5Fclose(file_), "close " + tmp_);
  file_ = -1;
  rename_into_place(tmp_, path_);
}

H5In::H5In(const std::string& path) : path_(path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("cannot open HDF5 file " + path);
}
H5In::~H5In() {
  if (file_ >= 0) H5Fclose(file_);
}

bool H5In::has(const std::string& name) const {
  return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0;
}

std::size_t H5In::read_raw(const std::string& name, hid_t type, std::vector<char>& out,
                           std::size_t elem) const {
  hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw std::runtime_error(path_ + ": no dataset " + name);
  hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  out.resize(static_cast<std::size_t>(n) * elem);
  if (n > 0) check(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  H5Sclose(space);
  H5Dclose(set);
  return static_cast<std::size_t>(n);
}

template <class T>
static std::vector<T> as_vector(const std::vector<char>& raw, std::size_t n) {
  std::vector<T> v(n);
  if (n) std::memcpy(v.data(), raw.data(), n * sizeof(T));
  return v;
}

std::vector<double> H5In::doubles(const std::string& name) const {
  std::vector<char> raw;
  const auto n = read_raw(name, H5T_NATIVE_DOUBLE, raw, sizeof(double));
  return as_vector<double>(raw, n);
}
std::vector<Vec3> H5In::vec3s(const std::string& name) const {
  const auto d = doubles(name);
  std::vector<Vec3> v(d.size() / 3);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
  return v;
}
std::vector<std::int64_t> H5In::int64s(const std::string& name) const {
  std::vector<char> raw;
  const auto n = read_raw(name, H5T_NATIVE_INT64, raw, sizeof(std::int64_t));
  return as_vector<std::int64_t>(raw, n);
}
std::vector<std::int32_t> H5In::int32s(const std::string& name) const {
  std::vector<char> raw;
  const auto n = read_raw(name, H5T_NATIVE_INT32, raw, sizeof(std::int32_t));
  return as_vector<std::int32_t>(raw, n);
}
std::vector<std::uint8_t> H5In::uint8s(const std::string& name) const {
  std::vector<char> raw;
  const auto n = read_raw(name, H5T_NATIVE_UINT8, raw, 1);
  return as_vector<std::uint8_t>(raw, n);
}

double H5In::attr_double(const std::string& name, const std::string& object) const {
  double v = 0;
  hid_t a = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(path_ + ": no attribute " + name);
  check(H5Aread(a, H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  H5Aclose(a);
  return v;
}
std::int64_t H5In::attr_int(const std::string& name, const std::string& object) const {
  std::int64_t v = 0;
  hid_t a = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(path_ + ": no attribute " + name);
  check(H5Aread(a, H5T_NATIVE_INT64, &v), "read attribute " + name);
  H5Aclose(a);
  return v;
}
std::string H5In::attr_string(const std::string& name, const std::string& object) const {
  hid_t a = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(path_ + ": no attribute " + name);
  hid_t type = H5Aget_type(a);
  std::string s(H5Tget_size(type), '\0');
  hid_t mem = H5Tcopy(H5T_C_S1);
  H5Tset_size(mem, s.size());
  check(H5Aread(a, mem, s.data()), "read attribute " + name);
  H5Tclose(mem);
  H5Tclose(type);
  H5Aclose(a);
  if (auto z = s.find('\0'); z != std::string::npos) s.resize(z);
  return s;
}

bool H5In::has_attr(const std::string& name, const std::string& object) const {
  return H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f << content;
    f.flush();
    if (!f) throw std::runtime_error("cannot write " + tmp);
  }
  rename_into_place(tmp, path);
}

}  // namespace lbdem
