#pragma once
// Damaging a checkpoint on disk the way a storage fault would, for the resume tests.
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include <hdf5.h>

namespace lbdem::test {

/// Flips one bit (bit 40 of the first 8-byte element) of `dataset` in `file`, in place.
inline void flip_bit(const std::string& file, const std::string& dataset) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
  REQUIRE(d >= 0);
  const hid_t space = H5Dget_space(d);
  std::vector<std::uint64_t> v(std::size_t(H5Sget_simple_extent_npoints(space)));
  REQUIRE(!v.empty());
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  v[0] ^= std::uint64_t(1) << 40;
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
}

}  // namespace lbdem::test
