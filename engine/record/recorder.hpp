#pragma once
// The recorder is a sink the resolver and the methods report to. The default keeps nothing, and then nothing is
// reported but the frame's start and end: a method makes no call per visit, and the maths never knows whether it
// is being watched.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "preparation/prepared_contact.hpp"
#include "record/iteration_records.hpp"
#include "record/visits.hpp"
#include "settings/settings.hpp"

#include <span>

namespace impulse {

// A frame's contacts as resolution begins: as detected, as prepared, and what they were prepared from.
struct PreparedFrame {
    std::span<const Contact> detected;
    std::span<const PreparedContact> prepared;
    std::span<const RigidBody> bodies;
    std::span<const MassProperties> mass;
    const ResolverSettings& settings;
};

class Recorder {
public:
    virtual ~Recorder() = default;

    virtual void begin_frame(int /*frame*/, std::span<const RigidBody> /*bodies*/,
                             std::span<const MassProperties> /*mass*/) {}
    // Whether the frame begun is kept: then the resolver reports its contacts as prepared and the methods every
    // visit; otherwise neither.
    virtual bool keeps_frame() const { return false; }
    virtual void contacts_prepared(const PreparedFrame& /*frame*/) {}
    virtual void position_visit(const PositionVisit& /*visit*/) {}
    virtual void velocity_visit(const VelocityVisit& /*visit*/) {}
    // AVBD's visits (record/avbd_records.hpp): a body's primal update, a contact's dual update.
    virtual void body_visit(const SweepPlace& /*place*/, const BodyVisitRecord& /*visit*/) {}
    virtual void dual_visit(const SweepPlace& /*place*/, const DualUpdateRecord& /*update*/) {}
    virtual void end_phase(Phase /*phase*/, const PhaseOutcome& /*outcome*/) {}
    virtual void end_frame(std::span<const RigidBody> /*bodies*/) {}
};

}  // namespace impulse
