#include "resolver/resolver.hpp"

#include "methods/soft_step.hpp"
#include "resolver/phases.hpp"
#include "resolver/prepared_contact.hpp"

namespace impulse {

ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings, Recorder& recorder, int frame,
                                   ContactMemory* memory) {
    // Soft step integrates the bodies itself, sub-step by sub-step, so it takes the whole frame: here, with no
    // gravity, it moves the bodies by their velocities over settings.duration while it resolves the contacts.
    if (settings.velocity_method == VelocityMethod::soft_step)
        return solve_soft_step(bodies, contacts, settings, SoftStepForces{}, recorder, frame, memory);

    const std::vector<MassProperties> mass = mass_properties(bodies);
    recorder.begin_frame(frame, bodies, mass);
    std::vector<PreparedContact> prepared = prepare_contacts(contacts, bodies, mass, settings);
    recorder.contacts_prepared(prepared);

    ResolutionSummary summary;
    if (settings.phase_order == PhaseOrder::positions_first) {
        summary.position = resolve_positions(bodies, prepared, settings, recorder);
        summary.velocity = resolve_velocities(bodies, prepared, settings, recorder, memory);
    } else {
        summary.velocity = resolve_velocities(bodies, prepared, settings, recorder, memory);
        summary.position = resolve_positions(bodies, prepared, settings, recorder);
    }
    recorder.end_frame(bodies);
    return summary;
}

ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings) {
    Recorder nobody;
    return resolve_contacts(bodies, contacts, settings, nobody);
}

}  // namespace impulse
