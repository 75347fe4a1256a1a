#pragma once
// Splits a loop over n items into `threads` contiguous chunks, chunk k run by thread k
// (k = 0 on the calling thread). The split depends only on n and threads, so a filter
// step that gives chunk k its own random generator is reproducible whatever the
// scheduling. Threads are started per call: at the filter's rate (tens of Hz) the cost,
// tens of microseconds, is far below one update's ray casting (milliseconds).
#include <cstddef>
#include <functional>

namespace fleetmap::localization {

// fn(k, begin, end) for each chunk k in [0, threads); returns when all are done. The
// first exception thrown by a chunk is rethrown here. Called from inside a chunk, it runs
// as one chunk on the calling thread: the threads are busy already.
void parallel_for(int threads, size_t n, const std::function<void(int, size_t, size_t)>& fn);

}  // namespace fleetmap::localization
