// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A one-line progress bar on stderr, redrawn only when the percentage changes; with an
// estimate of the time left once a few percent are done (long renders and animations).
#include <chrono>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace lc::cli {

class ProgressBar {
public:
    explicit ProgressBar(bool enabled, std::string label = "")
        : enabled_(enabled), tty_(::isatty(2)), label_(std::move(label)), start_(std::chrono::steady_clock::now()) {}
    void operator()(double f) {
        if (!enabled_) return;
        const int pct = static_cast<int>(100 * f);
        if (pct == last_) return;
        const std::string eta = timeLeft(f);
        if (!tty_) {  // logs: a line every 10 %
            if (pct / 10 != last_ / 10 || last_ < 0)
                std::fprintf(stderr, "%sprogress %3d%%%s\n", label_.c_str(), pct, eta.c_str());
            last_ = pct;
            return;
        }
        last_ = pct;
        const int filled = pct * 40 / 100;
        std::fprintf(stderr, "\r%s[%.*s%*s] %3d%%%s   ", label_.c_str(), filled,
                     "########################################", 40 - filled, "", pct, eta.c_str());
        if (pct == 100) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }

private:
    // ", 1 min 20 s left" from the rate so far; empty until 2 % are done or when finished.
    std::string timeLeft(double f) const {
        if (f < 0.02 || f >= 1) return "";
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const long left = static_cast<long>(elapsed * (1 - f) / f + 0.5);
        char buf[64];
        if (left >= 3600)
            std::snprintf(buf, sizeof buf, ", %ld h %02ld min left", left / 3600, left / 60 % 60);
        else if (left >= 60)
            std::snprintf(buf, sizeof buf, ", %ld min %02ld s left", left / 60, left % 60);
        else
            std::snprintf(buf, sizeof buf, ", %ld s left", left);
        return buf;
    }

    bool enabled_, tty_;
    std::string label_;
    std::chrono::steady_clock::time_point start_;
    int last_ = -1;
};

}  // namespace lc::cli
