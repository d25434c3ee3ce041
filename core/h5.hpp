#pragma once
// Thin RAII layer over the HDF5 C API. H5Out writes to "<path>.tmp" and renames it over <path> on
// commit(), so a reader (or a resumed run) never sees a half-written file.
#include "core/types.hpp"

#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lbdem {

class H5Out {
 public:
  explicit H5Out(std::string path);
  ~H5Out();
  H5Out(const H5Out&) = delete;
  H5Out& operator=(const H5Out&) = delete;

  void group(const std::string& name);
  void write(const std::string& name, const std::vector<double>& v);
  void write(const std::string& name, const std::vector<Vec3>& v);  // N x 3
  void write(const std::string& name, const std::vector<std::int64_t>& v);
  void write(const std::string& name, const std::vector<std::int32_t>& v);
  void write(const std::string& name, const std::vector<std::uint8_t>& v);
  void write_matrix(const std::string& name, const std::vector<double>& v, std::size_t rows,
                    std::size_t cols);
  /// Row-major array of any rank (last dimension fastest).
  void write_array(const std::string& name, const std::vector<double>& v,
                   const std::vector<std::size_t>& dims);
  void write_array(const std::string& name, const std::vector<std::uint8_t>& v,
                   const std::vector<std::size_t>& dims);
  void attr(const std::string& name, double v, const std::string& object = "/");
  void attr(const std::string& name, std::int64_t v, const std::string& object = "/");
  void attr(const std::string& name, const std::string& v, const std::string& object = "/");
  void external_link(const std::string& name, const std::string& file, const std::string& object);
  /// From here on every dataset written carries a checksum of its bytes (attribute
  /// kChecksumAttr), and the file the count of them (kChecksumCountAttr, at commit): what
  /// H5In::checksum_fault verifies (checkpoints: a bit flipped on disk, a file cut short).
  void checksum_datasets() { checksums_ = true; }
  /// Closes the file and renames it into place.
  void commit();

  static constexpr const char* kChecksumAttr = "checksum_fnv1a64";
  static constexpr const char* kChecksumCountAttr = "checksummed_datasets";

 private:
  void write_raw(const std::string& name, hid_t type, const void* data, int rank,
                 const hsize_t* dims);
  std::string path_, tmp_;
  hid_t file_ = -1;
  bool checksums_ = false;
  std::int64_t checksummed_ = 0;
};

class H5In {
 public:
  explicit H5In(const std::string& path);
  ~H5In();
  H5In(const H5In&) = delete;
  H5In& operator=(const H5In&) = delete;

  bool has(const std::string& name) const;
  /// A dataset's dimensions, slowest first, without reading it.
  std::vector<std::size_t> dims(const std::string& name) const;
  std::vector<double> doubles(const std::string& name) const;
  std::vector<Vec3> vec3s(const std::string& name) const;
  std::vector<std::int64_t> int64s(const std::string& name) const;
  std::vector<std::int32_t> int32s(const std::string& name) const;
  std::vector<std::uint8_t> uint8s(const std::string& name) const;
  double attr_double(const std::string& name, const std::string& object = "/") const;
  std::int64_t attr_int(const std::string& name, const std::string& object = "/") const;
  std::string attr_string(const std::string& name, const std::string& object = "/") const;
  bool has_attr(const std::string& name, const std::string& object = "/") const;
  /// Whether the file was written with H5Out::checksum_datasets.
  bool has_checksums() const { return has_attr(H5Out::kChecksumCountAttr); }
  /// nullopt if every dataset with a checksum matches it and their count is the one written;
  /// else which dataset fails (reads every such dataset whole).
  std::optional<std::string> checksum_fault() const;

 private:
  std::size_t read_raw(const std::string& name, hid_t type, std::vector<char>& out,
                       std::size_t elem) const;
  std::string path_;
  hid_t file_ = -1;
};

/// FNV-1a over 8-byte words (then the bytes left over): the checksum of H5Out::checksum_datasets.
std::uint64_t checksum64(const void* data, std::size_t bytes);

/// Writes text to <path>.tmp and renames it over <path> (atomic on POSIX).
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace lbdem
