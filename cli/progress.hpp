#pragma once
// A one-line progress bar for long runs: shown only on a terminal, only once a run has taken more than a
// second, redrawn at most ten times a second, and cleared when the run ends.

#include <chrono>
#include <ostream>

namespace impulse::cli {

class ProgressBar {
public:
    ProgressBar(std::ostream* terminal, int total) : terminal_(terminal), total_(total) {}
    ~ProgressBar() { finish(); }
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void update(int done);
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    std::ostream* terminal_;
    int total_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_drawn_{};
    bool shown_ = false;
};

}  // namespace impulse::cli
