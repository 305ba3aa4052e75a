#include "cli/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace impulse::cli {

namespace {

volatile std::sig_atomic_t received_signal = 0;  // 0: none yet
std::atomic<bool> stop{false};                   // the engine's stop flag: set with the note
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only store to a lock-free atomic");

extern "C" void note_signal(int signal) {
    received_signal = signal;
    stop.store(true, std::memory_order_relaxed);
}

}  // namespace

InterruptHandler::InterruptHandler() {
    received_signal = 0;
    stop.store(false, std::memory_order_relaxed);
    struct sigaction action {};
    action.sa_handler = note_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // reads and writes in progress carry on; the frame loop checks the note
    sigaction(SIGINT, &action, &previous_interrupt_);
    sigaction(SIGTERM, &action, &previous_terminate_);
}

InterruptHandler::~InterruptHandler() {
    sigaction(SIGINT, &previous_interrupt_, nullptr);
    sigaction(SIGTERM, &previous_terminate_, nullptr);
}

std::optional<int> interrupt_received() {
    if (const int signal = received_signal) return signal;
    return std::nullopt;
}

void forget_interrupt() {
    received_signal = 0;
    stop.store(false, std::memory_order_relaxed);
}

const std::atomic<bool>& stop_requested() {
    return stop;
}

void throw_if_interrupted() {
    if (const int signal = received_signal) throw Interrupted{signal};
}

const char* signal_name(int signal) {
    return signal == SIGTERM ? "SIGTERM" : "SIGINT";
}

}  // namespace impulse::cli
