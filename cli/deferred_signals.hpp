#pragma once
// The program's policy for interruptions while files are written (the formats layer asks for it through
// formats::WriteInterruptions and knows no signals itself): SIGINT and SIGTERM are held back, in this thread, while a
// set of files is staged and renamed into place, so Ctrl-C takes effect once every file is whole and no
// temporary is left; SIGPIPE is held back too, so a FIFO's reader that goes away is an error (EPIPE) rather than
// the end of the program between two files of a set, and a SIGPIPE so raised is taken back.

#include "formats/atomic_file.hpp"

#include <csignal>
#include <vector>

namespace impulse::cli {

class DeferredSignals final : public formats::WriteInterruptions {
public:
    void hold() override;
    void release() override;
    bool pending() const override;

private:
    struct Held {
        sigset_t previous;         // the mask before this hold
        bool pipe_pending_before;  // a SIGPIPE that was waiting already is not this hold's to take back
    };
    std::vector<Held> held_;
};

// Makes DeferredSignals the process's policy (once; cli::run calls it, so the program and in-process tests agree).
void install_deferred_signals();

}  // namespace impulse::cli
