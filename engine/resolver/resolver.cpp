#include "resolver/resolver.hpp"

#include "methods/method_table.hpp"
#include "resolver/prepared_contact.hpp"

namespace impulse {

ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings, Recorder& recorder, int frame,
                                   ContactMemory* memory, const Forces& forces) {
    const std::vector<MassProperties> mass = mass_properties(bodies);
    recorder.begin_frame(frame, bodies, mass);
    std::vector<PreparedContact> prepared = prepare_contacts(contacts, bodies, mass, settings);
    recorder.contacts_prepared(prepared);

    FrameContext context{bodies, prepared, mass, settings, recorder, memory, forces};
    const MethodRow<VelocityMethod>& velocities = method_row(settings.velocity_method);
    const MethodRow<PositionMethod>& positions = method_row(position_method_in_effect(settings));
    ResolutionSummary summary;
    // A method that owns the whole step runs after an empty position phase, whatever the phase order.
    if (settings.phase_order == PhaseOrder::positions_first || velocities.scope == MethodScope::whole_step) {
        summary.position = positions.solve(context);
        summary.velocity = velocities.solve(context);
    } else {
        summary.velocity = velocities.solve(context);
        summary.position = positions.solve(context);
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
