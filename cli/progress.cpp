#include "cli/progress.hpp"

#include "cli/terminal_guard.hpp"

#include <string>

namespace impulse::cli {

void ProgressBar::update(int done) {
    if (!terminal_) return;
    const auto now = Clock::now();
    if (now - start_ < std::chrono::seconds(1) || now - last_drawn_ < std::chrono::milliseconds(100)) return;
    last_drawn_ = now;
    constexpr int width = 30;
    const int filled = total_ > 0 ? width * done / total_ : width;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = done > 0 ? elapsed * (total_ - done) / done : 0.0;
    std::ostream bar(raw_buffer(*terminal_));  // its carriage return is the program's own, not escaped
    bar << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
        << std::string(static_cast<std::size_t>(width - filled), ' ') << "] " << done << "/" << total_ << " frames, "
        << static_cast<int>(left + 0.5) << " s left " << std::flush;
    shown_ = true;
}

void ProgressBar::finish() {
    if (terminal_ && shown_) std::ostream(raw_buffer(*terminal_)) << "\r\033[K" << std::flush;
    shown_ = false;
}

}  // namespace impulse::cli
