#include "core/sim/parallel.h"

#include <vector>

#ifdef RESECT_HAVE_OPENMP
#include <omp.h>
#endif

namespace resect {

int resolveThreadCount(int requested) {
#ifdef RESECT_HAVE_OPENMP
    return requested > 0 ? requested : omp_get_max_threads();
#else
    return requested > 0 ? requested : 1; // run one after another: same results, no speed-up
#endif
}

void parallelRun(int threads, const std::function<void(int)>& body) {
    if (threads <= 1) {
        body(0);
        return;
    }
#ifdef RESECT_HAVE_OPENMP
#pragma omp parallel for num_threads(threads) schedule(static, 1)
#endif
    for (int t = 0; t < threads; ++t)
        body(t);
}

double parallelSum(int threads, std::int64_t count,
                   const std::function<double(std::int64_t, std::int64_t)>& body) {
    if (threads <= 1)
        return body(0, count);
    std::vector<double> partial(static_cast<std::size_t>(threads), 0.0);
    parallelRun(threads, [&](int t) {
        partial[t] = body(chunkBegin(count, threads, t), chunkBegin(count, threads, t + 1));
    });
    double sum = 0;
    for (double p : partial)
        sum += p;
    return sum;
}

} // namespace resect
