#include "cli/interrupt.hpp"

#include <csignal>

namespace impulse::cli {

namespace {

volatile std::sig_atomic_t received_signal = 0;  // 0: none yet

extern "C" void note_signal(int signal) {
    received_signal = signal;
}

}  // namespace

InterruptHandler::InterruptHandler() {
    received_signal = 0;
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
}

void throw_if_interrupted() {
    if (const int signal = received_signal) throw Interrupted{signal};
}

const char* signal_name(int signal) {
    return signal == SIGTERM ? "SIGTERM" : "SIGINT";
}

}  // namespace impulse::cli
