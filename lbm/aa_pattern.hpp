#pragma once
// The AA pattern (Bailey, Myre, Walsh, Lilja & Saar 2009, ICPP; Wittmann et al. 2013, Comput.
// Math. Appl. 65, 924): one PDF array, updated in place, two alternating step kinds.
//   even step (state natural -> swapped): cell x reads f_q from its own slot q and writes the
//     post-collision f_q* to its own slot qbar. No neighbour is touched.
//   odd step (state swapped -> natural): cell x reads f_q from slot qbar of x - c_q (where the
//     even step left it) and writes f_q* to slot q of x + c_q, i.e. streamed.
// Each slot is read and written by one cell only, so there are no races and no second array; a
// slot's cache line is written right after it was read, so there is no write-allocate traffic:
// 19 loads + 19 stores = 304 B per cell update in double (152 B in float), the roofline minimum.
//
// In either state the post-streaming population f_q(x) is readable: natural: slot q of x;
// swapped: slot qbar of x - c_q. read_pointers() gives those addresses for a run of a row, so the
// kernel and the moment fields read through the same function.
#include "core/types.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/grid.hpp"
#include "lbm/pdf_field.hpp"

namespace lbdem::lbm {

enum class AaState {
  natural,  // f_q(x) in slot q of x; the next step is an even one
  swapped,  // f_q(x) in slot qbar of x - c_q; the next step is an odd one
};

/// in[q] + i is the address of f_q of cell (x0 + i, y, z) for i in the x range of x0 (grid.hpp);
/// the slot is encoded (PdfField<T>::Codec::load(in[q][i], q) is f_q).
template <class T>
void read_pointers(const PdfField<T>& pdf, AaState s, int x0, int y, int z, const T* (&in)[kQ]) {
  const Grid& g = pdf.grid();
  const Index n0 = g.index(x0, y, z);
  if (s == AaState::natural) {
    for (int q = 0; q < kQ; ++q) in[q] = pdf.dir(q) + n0;
  } else {
    // x - c_q = x + c_qbar.
    const auto& off = g.neighbor_offsets(x0, y, z);
    for (int q = 0; q < kQ; ++q) in[q] = pdf.dir(opposite(q)) + n0 + off[opposite(q)];
  }
}

/// out[q] + i is where a step that starts in state s stores the post-collision f_q* of cell
/// (x0 + i, y, z): own slot qbar on an even step, slot q of x + c_q on an odd one.
template <class T>
void write_pointers(PdfField<T>& pdf, AaState s, int x0, int y, int z, T* (&out)[kQ]) {
  const Grid& g = pdf.grid();
  const Index n0 = g.index(x0, y, z);
  if (s == AaState::natural) {
    for (int q = 0; q < kQ; ++q) out[q] = pdf.dir(opposite(q)) + n0;
  } else {
    const auto& off = g.neighbor_offsets(x0, y, z);
    for (int q = 0; q < kQ; ++q) out[q] = pdf.dir(q) + n0 + off[q];
  }
}

inline AaState after_step(AaState s) {
  return s == AaState::natural ? AaState::swapped : AaState::natural;
}

}  // namespace lbdem::lbm
