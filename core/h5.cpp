#include "core/h5.hpp"

#include <algorithm>
#include <sys/statvfs.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/error.hpp"

namespace lbdem {

namespace {
void check(herr_t rc, const std::string& what) {
  if (rc < 0) throw std::runtime_error("HDF5: " + what + " failed");
}
void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw write_error(path, err);
  }
}
}  // namespace

WriteError write_error(const std::string& path, int err) {
  if (err == 0) {
    const auto dir = std::filesystem::path(path).parent_path();
    struct statvfs fs {};
    err = statvfs(dir.empty() ? "." : dir.c_str(), &fs) == 0 && fs.f_bavail == 0 ? ENOSPC : EIO;
  }
  return WriteError(path, std::strerror(err), err == ENOSPC || err == EDQUOT);
}

H5Out::H5Out(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  errno = 0;
  file_ = H5Fcreate(tmp_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw write_error(tmp_, errno);
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
  errno = 0;
  if (!empty && H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
    const int err = errno;
    H5Dclose(set);
    H5Sclose(space);
    throw write_error(tmp_ + " (" + name + ")", err);
  }
  if (checksums_) {
    std::size_t bytes = H5Tget_size(type);
    for (int r = 0; r < rank; ++r) bytes *= dims[r];
    const std::uint64_t h = checksum64(data, empty ? 0 : bytes);
    std::int64_t v;
    std::memcpy(&v, &h, sizeof v);
    hid_t scalar = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(set, kChecksumAttr, H5T_NATIVE_INT64, scalar, H5P_DEFAULT, H5P_DEFAULT);
    const bool ok = a >= 0 && H5Awrite(a, H5T_NATIVE_INT64, &v) >= 0;
    if (a >= 0) H5Aclose(a);
    H5Sclose(scalar);
    if (!ok) {
      H5Dclose(set);
      H5Sclose(space);
      throw std::runtime_error("HDF5: checksum of " + name + " failed");
    }
    ++checksummed_;
  }
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
void H5Out::write_array(const std::string& name, const std::vector<std::uint8_t>& v,
                        const std::vector<std::size_t>& dims) {
  std::vector<hsize_t> d(dims.begin(), dims.end());
  write_raw(name, H5T_NATIVE_UINT8, v.data(), static_cast<int>(d.size()), d.data());
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
  if (checksums_) attr(kChecksumCountAttr, checksummed_);
  // The file is flushed here: a full disk shows now. The handle is gone either way (closing it
  // again would crash HDF5), and so is the half-written temp file.
  errno = 0;
  const herr_t rc = H5Fclose(file_);
  const int err = errno;
  file_ = -1;
  if (rc < 0) {
    std::remove(tmp_.c_str());
    throw write_error(tmp_, err);
  }
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

std::vector<std::size_t> H5In::dims(const std::string& name) const {
  hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw std::runtime_error(path_ + ": no dataset " + name);
  hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> d(static_cast<std::size_t>(std::max(rank, 0)));
  if (rank > 0) H5Sget_simple_extent_dims(space, d.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return std::vector<std::size_t>(d.begin(), d.end());
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

namespace {
// The datasets below a group, by full path (H5Lvisit: hard links only, so each once).
herr_t collect_dataset(hid_t group, const char* name, const H5L_info_t* info, void* out) {
  if (info->type != H5L_TYPE_HARD) return 0;
  const hid_t obj = H5Oopen(group, name, H5P_DEFAULT);
  if (obj < 0) return -1;
  if (H5Iget_type(obj) == H5I_DATASET)
    static_cast<std::vector<std::string>*>(out)->push_back(std::string("/") + name);
  H5Oclose(obj);
  return 0;
}
}  // namespace

std::optional<std::string> H5In::checksum_fault() const {
  std::vector<std::string> sets;
  if (H5Lvisit(file_, H5_INDEX_NAME, H5_ITER_INC, collect_dataset, &sets) < 0)
    return "its datasets cannot be listed";
  std::int64_t counted = 0;
  for (const auto& name : sets) {
    if (!has_attr(H5Out::kChecksumAttr, name)) continue;
    ++counted;
    const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    if (set < 0) return "dataset " + name + " cannot be opened";
    const hid_t ftype = H5Dget_type(set), space = H5Dget_space(set);
    const hid_t mem = H5Tget_native_type(ftype, H5T_DIR_ASCEND);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::vector<char> raw(n > 0 ? std::size_t(n) * H5Tget_size(mem) : 0);
    const bool read =
        raw.empty() || H5Dread(set, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) >= 0;
    H5Tclose(mem);
    H5Tclose(ftype);
    H5Sclose(space);
    H5Dclose(set);
    if (!read) return "dataset " + name + " cannot be read";
    const std::uint64_t h = checksum64(raw.data(), raw.size());
    std::int64_t v;
    std::memcpy(&v, &h, sizeof v);
    if (v != attr_int(H5Out::kChecksumAttr, name)) return "dataset " + name + " fails its checksum";
  }
  if (has_checksums() && counted != attr_int(H5Out::kChecksumCountAttr))
    return std::to_string(counted) + " datasets carry a checksum, " +
           std::to_string(attr_int(H5Out::kChecksumCountAttr)) + " were written";
  return std::nullopt;
}

bool H5In::has_attr(const std::string& name, const std::string& object) const {
  return H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::uint64_t checksum64(const void* data, std::size_t bytes) {
  const auto* b = static_cast<const unsigned char*>(data);
  std::uint64_t h = 1469598103934665603ull;
  std::size_t k = 0;
  for (; k + 8 <= bytes; k += 8) {
    std::uint64_t w;
    std::memcpy(&w, b + k, 8);
    h = (h ^ w) * 1099511628211ull;
  }
  for (; k < bytes; ++k) h = (h ^ b[k]) * 1099511628211ull;
  return h;
}

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  {
    errno = 0;
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (f) {
      f << content;
      f.flush();
    }
    if (!f) {
      const int err = errno;
      f.close();
      std::remove(tmp.c_str());
      throw write_error(tmp, err);
    }
  }
  rename_into_place(tmp, path);
}

}  // namespace lbdem
