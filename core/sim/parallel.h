#pragma once
// Fork-join parallelism for the simulation kernels (OpenMP when the build has it, else serial).
//
// Work is always split into `threads` contiguous chunks with a fixed partition, and partial
// sums are combined in thread order, so a result depends only on the thread count, never on
// scheduling: the same input and thread count give bit-identical results. (Callers may use
// fewer threads than asked for small inputs, threadsFor; that too depends only on the input.)

#include <algorithm>
#include <cstdint>
#include <functional>

namespace resect {

/// `requested` if > 0, else the OpenMP default (the number of cores; 1 without OpenMP).
int resolveThreadCount(int requested);

/// The threads to use for `work` items: at most `threads`, and fewer when a thread would get
/// less than `grain` items (fork-join costs microseconds, and far more on a loaded machine).
inline int threadsFor(int threads, std::int64_t work, std::int64_t grain) {
    if (grain <= 0)
        return threads;
    const std::int64_t useful = work / grain;
    return static_cast<int>(std::max<std::int64_t>(1, std::min<std::int64_t>(threads, useful)));
}

/// Chunk t of [0, count) split into `threads` parts: [count * t / threads, count * (t+1) /
/// threads).
inline std::int64_t chunkBegin(std::int64_t count, int threads, int t) {
    return count * t / threads;
}

/// Runs body(t) for t = 0 .. threads-1, in parallel (inline when threads == 1). Each t runs
/// exactly once, on whichever thread OpenMP grants (a nested call, or a smaller team, runs
/// several t on one thread), so bodies must not wait for each other.
void parallelRun(int threads, const std::function<void(int)>& body);

/// body(begin, end) on `threads` contiguous chunks of [0, count); returns the sum of the
/// chunks' results in chunk order (deterministic for a given thread count).
double parallelSum(int threads, std::int64_t count,
                   const std::function<double(std::int64_t, std::int64_t)>& body);

} // namespace resect
