#include "resolver/resolver.hpp"

#include "methods/method_table.hpp"
#include "preparation/prepared_contact.hpp"
#include "preparation/row_preparation.hpp"

namespace impulse {

ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings, Recorder& recorder, int frame,
                                   ContactMemory* memory, const Forces& forces, std::pmr::memory_resource* scratch,
                                   const std::atomic<bool>* stop) {
    const std::vector<MassProperties> mass = mass_properties(bodies);
    recorder.begin_frame(frame, bodies, mass);
    const MethodRow<VelocityMethod>& velocities = method_row(settings.velocity_method);
    const MethodRow<PositionMethod>& positions = method_row(position_method_in_effect(settings));
    const ContactsRead read[2] = {velocities.contacts, positions.contacts};
    const auto reads = [&read](ContactsRead what) { return read[0] == what || read[1] == what; };
    // Steps 1-5 in full, with every intermediate, are for the recorder and for the methods that read them (the
    // book's); when neither asks, only what the rows read is prepared, by the same functions, and nothing is
    // kept that nobody reads (1.2 kB a contact to write and read back).
    std::vector<PreparedContact> prepared;
    std::pmr::vector<RowPreparation> rows(scratch);
    if (recorder.wants_updates() || reads(ContactsRead::prepared)) {
        prepared = prepare_contacts(contacts, bodies, mass, settings);
        recorder.contacts_prepared(prepared);
        if (reads(ContactsRead::rows) || reads(ContactsRead::rows_and_velocity)) {
            rows.reserve(prepared.size());
            for (const PreparedContact& c : prepared) rows.push_back(row_preparation(c));
        }
    } else {
        prepare_rows(contacts, bodies, settings, reads(ContactsRead::rows_and_velocity), rows);
    }

    FrameContext context{bodies, prepared, rows, mass, settings, recorder, memory, forces, scratch, stop};
    ResolutionSummary summary;
    // A method that owns the whole step runs after an empty position phase, whatever the phase order.
    if (settings.phase_order == PhaseOrder::positions_first || velocities.scope == MethodScope::whole_step) {
        summary.position = positions.solve(context);
        if (!context.cut_short) summary.velocity = velocities.solve(context);
    } else {
        summary.velocity = velocities.solve(context);
        if (!context.cut_short) summary.position = positions.solve(context);
    }
    summary.cut_short = context.cut_short;
    recorder.end_frame(bodies);
    return summary;
}

ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings) {
    Recorder nobody;
    return resolve_contacts(bodies, contacts, settings, nobody);
}

}  // namespace impulse
