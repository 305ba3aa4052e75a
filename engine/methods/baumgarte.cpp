// Baumgarte stabilisation: no position phase at all. Instead of moving the bodies, each contact's velocity
// target gains the position bias beta max(penetration - slop, 0) / h (methods/position_bias.hpp), so the
// velocity solve makes the bodies separate a little faster than the bounce asks and the next frames'
// integration carries them apart. It is cheap and needs no geometry after the solve, but the bias is real
// velocity: it adds kinetic energy (a deep contact pops apart) and, with a large factor, jitter. Which
// velocity method carries the bias:
//   projected_gauss_seidel  target normal velocity = restitution target + bias (Catto's sequential impulses)
//   worst_first, sequential_sweep  the bias is added to the desired delta v at preparation and again each time
//                            the bookkeeping re-evaluates step 5, so the book's impulse delivers it as well
// Every velocity iteration of these methods records the bias as `position_bias`.

#include "resolver/phases.hpp"

namespace impulse {

PhaseOutcome baumgarte_positions(const ResolverSettings& /*settings*/, Recorder& recorder) {
    // Nothing to do and nothing left undone: the phase is recorded empty so a trace still shows both phases.
    const PhaseOutcome outcome{.iteration_limit = 0, .iterations_used = 0, .stop = StopReason::resolved};
    recorder.end_phase(Phase::position, outcome);
    return outcome;
}

}  // namespace impulse
