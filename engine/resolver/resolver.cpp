#include "resolver/resolver.hpp"

#include "methods/method_table.hpp"
#include "preparation/prepared_contact.hpp"

#include <algorithm>

namespace impulse {

using Clock = std::chrono::steady_clock;

ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings, Recorder& recorder, const FrameSetup& setup) {
    auto start = Clock::now();
    const std::vector<MassProperties> mass = mass_properties(bodies);
    recorder.begin_frame(setup.frame, bodies, mass);
    const bool keeping = recorder.keeps_frame();
    const MethodRow<VelocityMethod>& velocities = method_row(settings.velocity_method);
    const MethodRow<PositionMethod>& positions = method_row(position_method_in_effect(settings));
    // Steps 4 and 5 in full when a method reads them or the recorder shows them.
    const Preparation preparation =
        keeping ? Preparation::steps_1_to_5 : std::max(velocities.preparation, positions.preparation);
    std::pmr::vector<PreparedContact> prepared(setup.scratch);
    prepare_contacts(contacts, bodies, mass, settings, prepared, preparation);
    if (keeping) recorder.contacts_prepared({contacts, prepared, bodies, mass, settings});
    StageTimes unwatched;  // where the times go when nobody asked for them
    StageTimes& times = setup.times ? *setup.times : unwatched;
    times.prepare += seconds_since(start);

    FrameContext context{bodies,      prepared,     mass,         settings,      recorder,  keeping,
                         setup.touch, setup.memory, setup.forces, setup.scratch, setup.stop};
    const auto run = [&](const auto& method, Phase phase, double& seconds) {
        start = Clock::now();
        const PhaseOutcome outcome = method.solve(context);
        seconds += seconds_since(start);
        recorder.end_phase(phase, outcome);
        return outcome;
    };
    ResolutionSummary summary;
    // A method that owns the whole step runs after an empty position phase, whatever the phase order.
    if (settings.phase_order == PhaseOrder::positions_first || velocities.scope == MethodScope::whole_step) {
        summary.position = run(positions, Phase::position, times.position);
        if (!context.cut_short) summary.velocity = run(velocities, Phase::velocity, times.velocity);
    } else {
        summary.velocity = run(velocities, Phase::velocity, times.velocity);
        if (!context.cut_short) summary.position = run(positions, Phase::position, times.position);
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
