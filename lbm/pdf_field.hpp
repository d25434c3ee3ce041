#pragma once
// Particle distribution functions, structure of arrays, direction-major: f_q of storage cell n is
// data[q * stride + n] (waLBerla fzyx, FluidX3D index_f). Each direction's array starts on a
// 64-byte boundary; one array serves the in-place AA update (stream_collide.hpp).
#include "core/types.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/grid.hpp"

#include <cstdlib>
#include <memory>
#include <new>

namespace lbdem::lbm {

class PdfField {
 public:
  explicit PdfField(const Grid& g) : grid_(g), stride_(padded_stride(g.storage_cells())) {
    const std::size_t bytes = std::size_t(stride_) * kQ * sizeof(double);
    data_.reset(static_cast<double*>(std::aligned_alloc(64, bytes)));
    if (!data_) throw std::bad_alloc();
  }

  const Grid& grid() const { return grid_; }
  Index stride() const { return stride_; }
  double* dir(int q) { return data_.get() + q * stride_; }
  const double* dir(int q) const { return data_.get() + q * stride_; }
  double& at(int q, Index n) { return data_[q * stride_ + n]; }
  double at(int q, Index n) const { return data_[q * stride_ + n]; }
  /// All kQ * stride values (for bitwise comparisons and checkpoints).
  const double* data() const { return data_.get(); }
  double* data() { return data_.get(); }
  Index size() const { return kQ * stride_; }

 private:
  // A multiple of 8 doubles keeps every direction 64-byte aligned; the extra 8 make sure the
  // arrays are never a whole multiple of 4 KiB apart, where the 19 concurrent streams would alias
  // in L1 (4K aliasing).
  static Index padded_stride(Index n) { return (n + 7) / 8 * 8 + 8; }

  struct Free {
    void operator()(double* p) const { std::free(p); }
  };
  Grid grid_;
  Index stride_;
  std::unique_ptr<double[], Free> data_;
};

}  // namespace lbdem::lbm
