// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An exception must not leave an OpenMP parallel region (the runtime then calls std::terminate):
// each iteration runs inside FirstError::run, which keeps the first exception and lets the other
// iterations skip their work; after the loop, rethrow() reports it on the calling thread.
#include <atomic>
#include <exception>
#include <mutex>

namespace lc {

class FirstError {
public:
    template <class Body>
    void run(Body&& body) noexcept {
        if (failed_.load(std::memory_order_relaxed)) return;
        try {
            body();
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!first_) first_ = std::current_exception();
            failed_.store(true, std::memory_order_relaxed);
        }
    }
    bool failed() const { return failed_.load(std::memory_order_relaxed); }
    void rethrow() const {
        if (first_) std::rethrow_exception(first_);
    }

private:
    std::atomic<bool> failed_{false};
    std::mutex mutex_;
    std::exception_ptr first_;
};

}  // namespace lc
