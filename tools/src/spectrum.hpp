#pragma once
// One-sided power spectral density of a uniformly sampled signal by FFTW's real-to-complex DFT.
//
// Each segment of N samples is detrended (least-squares line), multiplied by the periodic
// ("DFT-even") Hann window w_n = ½(1 − cos 2πn/N) (Harris 1978, Proc. IEEE 66, 51) and
// transformed, X_k = Σ_n w_n x_n e^{−2πikn/N}. The PSD is scaled as in Heinzel, Rüdiger & Schilling
// (2002, "Spectrum and spectral density estimation by the DFT", PSD = 2|X_k|²/(f_s S₂)):
//
//   S_k = c_k Δt |X_k|² / S₂,   S₂ = Σ_n w_n²,   c_k = 1 at k = 0 and k = N/2, else 2,
//
// in [unit²/Hz] at f_k = k / (N Δt), k = 0..⌊N/2⌋. Dividing by S₂ is the window's power
// correction (S₂ → 3N/8 for Hann: the window keeps 3/8 of a stationary signal's power), so that
// Σ_k S_k Δf = Σ_n (w_n x_n)² / S₂ exactly (Parseval), whose expectation is the variance of x.
// With several segments (Welch 1967, 50 % overlap) the segment spectra are averaged.
#include <cstddef>
#include <span>
#include <vector>

namespace lbdem::tools {

struct Spectrum {
  double df = 0;                  // frequency step 1 / (N Δt) [Hz]
  std::vector<double> frequency;  // [Hz]
  std::vector<double> psd;        // one-sided [unit²/Hz]
  std::size_t segment = 0;        // samples per segment N
  std::size_t segments = 0;       // segments averaged
};

/// x minus its least-squares straight line in the sample index.
std::vector<double> detrend_linear(std::span<const double> x);
/// Periodic Hann window of length n.
std::vector<double> hann_periodic(std::size_t n);
/// Σ_n (w_n x_n)² / Σ_n w_n² of the detrended segment: what Σ_k S_k Δf equals by Parseval.
double windowed_variance(std::span<const double> x);

/// PSD of x sampled every dt [s], averaged over `segments` Hann-windowed segments with 50 %
/// overlap (1: a single periodogram of the whole signal). Needs at least 4 samples per segment.
Spectrum one_sided_psd(std::span<const double> x, double dt, std::size_t segments = 1);

/// Frequency of the largest S_k with k >= 1 (the k = 0 bin holds only what detrending left).
double peak_frequency(const Spectrum& s);

}  // namespace lbdem::tools
