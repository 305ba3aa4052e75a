#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a long command (`run`): the handler only notes the signal, which the
// command checks between frames and before it writes its files; it then throws Interrupted, the files it had
// staged are removed as the stack unwinds, and cli.cpp prints one line and exits 128 + the signal (130 for
// Ctrl-C). The note is the program's one global: a signal handler can reach nothing else.

#include <csignal>

namespace impulse::cli {

struct Interrupted {
    int signal;  // SIGINT or SIGTERM
};

// Installs the handler for SIGINT and SIGTERM while it lives (and forgets any earlier signal); restores the
// handlers it replaced when it ends.
class InterruptHandler {
public:
    InterruptHandler();
    ~InterruptHandler();
    InterruptHandler(const InterruptHandler&) = delete;
    InterruptHandler& operator=(const InterruptHandler&) = delete;

private:
    struct sigaction previous_interrupt_ {};
    struct sigaction previous_terminate_ {};
};

// Throws Interrupted if a signal arrived since the handler was installed.
void throw_if_interrupted();

}  // namespace impulse::cli
