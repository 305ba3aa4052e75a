#include "cli/deferred_signals.hpp"

#include <ctime>
#include <pthread.h>

namespace impulse::cli {

namespace {

bool is_pending(int signal) {
    sigset_t pending;
    sigemptyset(&pending);
    ::sigpending(&pending);
    return sigismember(&pending, signal) == 1;
}

}  // namespace

void DeferredSignals::hold() {
    sigset_t held;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    sigaddset(&held, SIGPIPE);
    Held h{};
    pthread_sigmask(SIG_BLOCK, &held, &h.previous);
    h.pipe_pending_before = is_pending(SIGPIPE);
    held_.push_back(h);
}

void DeferredSignals::release() {
    if (held_.empty()) return;
    const Held h = held_.back();
    held_.pop_back();
    // A SIGPIPE a write in place caused was answered by EPIPE already: take it back before the mask is restored.
    if (!h.pipe_pending_before && is_pending(SIGPIPE) && !sigismember(&h.previous, SIGPIPE)) {
        sigset_t pipe_signal;
        sigemptyset(&pipe_signal);
        sigaddset(&pipe_signal, SIGPIPE);
        const timespec now{0, 0};
        ::sigtimedwait(&pipe_signal, nullptr, &now);
    }
    pthread_sigmask(SIG_SETMASK, &h.previous, nullptr);
}

bool DeferredSignals::pending() const {
    return is_pending(SIGINT) || is_pending(SIGTERM);
}

void install_deferred_signals() {
    static DeferredSignals policy;
    formats::set_write_interruptions(&policy);
}

}  // namespace impulse::cli
