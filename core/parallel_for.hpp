#pragma once
// A parallel loop whose body may throw. An exception may not leave an OpenMP region (the runtime
// calls std::terminate), so each iteration's is caught, and after the loop the one of the lowest
// index is rethrown: the same error, with the same message, for any thread count. For many small
// items that each call a large out-of-line kernel, see core/thread_ranges.hpp instead.
#include <cstddef>
#include <exception>
#include <limits>

namespace lbdem {

/// f(i) for i in [0, n), on the OpenMP threads when n >= min_parallel.
template <class F>
void parallel_for(std::size_t n, std::size_t min_parallel, F&& f) {
  std::size_t first_bad = std::numeric_limits<std::size_t>::max();
  std::exception_ptr error;
#pragma omp parallel for schedule(static) if (n >= min_parallel)
  for (std::size_t i = 0; i < n; ++i) {
    try {
      f(i);
    } catch (...) {
#pragma omp critical(lbdem_parallel_for_error)
      if (i < first_bad) first_bad = i, error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace lbdem
