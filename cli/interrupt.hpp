#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a long command (`run`): the handler only notes the signal, which the
// command checks between frames (and the engine within one, through stop_requested) and before it writes its
// files. `run` then stops, prints the summary of the
// frames done and (with --keep-partial) writes them; a command that cannot use what it did throws Interrupted,
// the files it had staged are removed as the stack unwinds, and cli.cpp prints one line. Either way the exit
// code is 128 + the signal (130 for Ctrl-C, 143 for SIGTERM). The note is the program's one global: a signal
// handler can reach nothing else.

#include <atomic>
#include <csignal>
#include <optional>

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

// The signal that arrived since the handler was installed (or since forget_interrupt), if one did.
std::optional<int> interrupt_received();
// Set by the same signals, for a world to stop within a frame (World::set_stop_flag): a frame of
// `--set velocity_iterations=100000000` ran on for minutes after Ctrl-C. Cleared with the note.
const std::atomic<bool>& stop_requested();
// Forgets a signal already acted on, so that a second one can be told from it.
void forget_interrupt();
// Throws Interrupted if a signal arrived since the handler was installed (or since forget_interrupt).
void throw_if_interrupted();

// "SIGINT" or "SIGTERM".
const char* signal_name(int signal);

}  // namespace impulse::cli
