#pragma once
// The recorder is a sink the resolver reports to. The default does nothing, so resolving unobserved costs
// nothing beyond the derivation values the resolver computes anyway; the maths never knows whether it is
// being watched.

#include "body/rigid_body.hpp"
#include "record/iteration_records.hpp"
#include "preparation/prepared_contact.hpp"

#include <span>

namespace impulse {

class Recorder {
public:
    virtual ~Recorder() = default;

    // Whether this frame's iterations are kept: then iterations carry their lists of updates to other contacts
    // (an allocation per iteration, skipped when nobody listens), and the sweeping methods run their recorded
    // loop, which builds a record per visit; otherwise their lean loop, with the same arithmetic.
    virtual bool wants_updates() const { return false; }

    virtual void begin_frame(int /*frame*/, std::span<const RigidBody> /*bodies*/,
                             std::span<const MassProperties> /*mass*/) {}
    // Steps 1-5 of every contact, in full. Always called when wants_updates() is true; otherwise only when a
    // method of the frame reads the full preparation (the accumulating methods read only their rows' values).
    virtual void contacts_prepared(std::span<const PreparedContact> /*contacts*/) {}
    virtual void position_iteration(const PositionIteration& /*iteration*/) {}
    virtual void velocity_iteration(const VelocityIteration& /*iteration*/) {}
    // A sweeping method that does not report each visit (wants_updates() is false: nobody keeps them) reports
    // once per phase the contacts of its last visits, in the order it made them, so a listener can still tell
    // which contact last changed each body (world/non_finite_check.hpp).
    virtual void contacts_visited(std::span<const int> /*contacts*/) {}
    virtual void end_phase(Phase /*phase*/, const PhaseOutcome& /*outcome*/) {}
    virtual void end_frame(std::span<const RigidBody> /*bodies*/) {}
};

}  // namespace impulse
