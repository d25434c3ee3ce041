#pragma once
// Particle distribution functions, structure of arrays, direction-major: f_q of storage cell n is
// slot data[q * stride + n] (waLBerla fzyx, FluidX3D index_f). Each direction's array starts on a
// 64-byte boundary; one array serves the in-place AA update (stream_collide.hpp).
//
// Precision: double, or float (single). The kernel moves 2 x 19 populations per cell update and,
// where the lattice leaves the cache, is memory-bound (stream_collide.hpp); float halves that
// traffic. Float slots hold the shifted value f_q - w_q (the rest equilibrium at rho = 1
// subtracted; Skordos 1993, Phys. Rev. E 48, 4823; Lehmann, Krause, Amati, Sega, Harting & Gekle
// 2022, Phys. Rev. E 106, 015308, "DDF shifting"): f_q - w_q is of the order of w_q times the
// density and velocity deviations, so the 24-bit mantissa resolves those deviations instead of
// spending its bits on the constant w_q. The kernel computes on the shifted slots as they are, in
// float (cell.hpp, kShifted); everything else (boundaries, moments for output, set-up) reads and
// writes the population f_q in double through PopulationCodec, the one place that converts.
// Double slots hold f_q itself. w_q = w_qbar, so a slot keeps the same shift whichever of the pair
// q, qbar the AA pattern stores in it.
#include "core/types.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/grid.hpp"

#include <cstdlib>
#include <memory>
#include <new>
#include <string_view>

namespace lbdem::lbm {

/// The gas's precision: double (the reference) or single, where the populations, the kernel's
/// per-cell fields and its arithmetic are float (lattice_fields.hpp, cell.hpp).
enum class Precision { float64, float32 };

inline std::string_view to_string(Precision p) {
  return p == Precision::float64 ? "double" : "single";
}

template <class T>
struct PopulationCodec;

template <>
struct PopulationCodec<double> {
  static double load(double slot, int) { return slot; }
  static double store(double f, int) { return f; }
};

template <>
struct PopulationCodec<float> {
  static double load(float slot, int q) { return double(slot) + kW[q]; }
  static float store(double f, int q) { return float(f - kW[q]); }
};

template <class T>
class PdfField {
 public:
  using value_type = T;
  using Codec = PopulationCodec<T>;

  explicit PdfField(const Grid& g) : grid_(g), stride_(padded_stride(g.storage_cells())) {
    const std::size_t bytes = std::size_t(stride_) * kQ * sizeof(T);
    data_.reset(static_cast<T*>(std::aligned_alloc(64, bytes)));
    if (!data_) throw std::bad_alloc();
  }

  const Grid& grid() const { return grid_; }
  Index stride() const { return stride_; }
  /// Raw slots of direction q (encoded: load/store convert).
  T* dir(int q) { return data_.get() + q * stride_; }
  const T* dir(int q) const { return data_.get() + q * stride_; }
  /// The population in slot q of storage cell n, decoded.
  double get(int q, Index n) const { return Codec::load(data_[q * stride_ + n], q); }
  void set(int q, Index n, double f) { data_[q * stride_ + n] = Codec::store(f, q); }
  Index size() const { return kQ * stride_; }
  /// All kQ * stride raw slots (checkpoints: widened to double and narrowed back, exactly).
  const T* data() const { return data_.get(); }
  T* data() { return data_.get(); }

 private:
  // A multiple of 64 bytes keeps every direction aligned; the extra 64 bytes make sure the
  // arrays are never a whole multiple of 4 KiB apart, where the 19 concurrent streams would alias
  // in L1 (4K aliasing).
  static constexpr Index kLine = Index(64 / sizeof(T));
  static Index padded_stride(Index n) { return (n + kLine - 1) / kLine * kLine + kLine; }

  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  Grid grid_;
  Index stride_;
  std::unique_ptr<T[], Free> data_;
};

}  // namespace lbdem::lbm
