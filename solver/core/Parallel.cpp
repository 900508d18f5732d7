#include "core/Parallel.h"

#include <omp.h>

namespace wcmps {

void set_thread_count(int n) {
  omp_set_num_threads(n < 1 ? 1 : n);
}

int thread_count() {
  return omp_get_max_threads();
}

}  // namespace wcmps
