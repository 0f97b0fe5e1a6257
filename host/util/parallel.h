// Host-side data parallelism: a loop split into chunks run on every core.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace tsis {

// Threads for host loops: the hardware's, at least one.
inline unsigned hostThreads() {
    return std::max(1u, std::thread::hardware_concurrency());
}

// Calls body(begin, end) over [0, count) in chunks of at most `chunk`, from
// `threads` threads (the caller's among them; at least one). Chunks are
// handed out in order, so results written per index do not depend on the
// thread count. `body` must not throw.
template <typename Body>
void parallelFor(size_t count, size_t chunk, const Body& body, size_t threads = hostThreads()) {
    chunk = std::max<size_t>(chunk, 1);
    const size_t chunks = (count + chunk - 1) / chunk;
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t c; (c = next.fetch_add(1)) < chunks;)
            body(c * chunk, std::min(count, (c + 1) * chunk));
    };
    const size_t helpers =
        std::min<size_t>(std::max<size_t>(threads, 1), chunks) - (chunks > 0 ? 1 : 0);
    std::vector<std::thread> pool;
    for (size_t t = 0; t < helpers; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}

}  // namespace tsis
