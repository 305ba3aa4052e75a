// No position phase (`position_method = none`): nothing moves the bodies apart but their velocities. That is
// how Baumgarte stabilisation works (settings `baumgarte`: step 5 gains the position bias
// beta max(penetration - slop, 0) / h, so the velocity solve separates the bodies a little faster than the
// bounce asks and the next frames' integration carries them apart), and how a method that owns the whole step
// (soft step, whose soft contact pushes) runs. The phase is recorded empty, so a trace still shows both phases.

#include "methods/method.hpp"

namespace impulse {

PhaseOutcome no_positions(FrameContext& /*frame*/) {
    // Nothing to do and nothing left undone.
    return {.iteration_limit = 0, .iterations_used = 0, .stop = StopReason::resolved};
}

}  // namespace impulse
