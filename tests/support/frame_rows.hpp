#pragma once
// A frame's accumulating rows as a row solver builds them (methods/contact_rows.hpp): a shipped scene run through the
// world for some frames, its contacts detected and prepared, one ContactRow per contact that can move, in detection's
// order, and the solver bodies they read. The tests of the solve orders (graph colouring, wide records) start here.

#include "methods/contact_rows.hpp"
#include "preparation/prepared_contact.hpp"
#include "world/world.hpp"

#include <memory_resource>
#include <vector>

namespace impulse::test {

struct FrameRows {
    std::vector<ContactRow> rows;
    std::vector<SolverBody> bodies;   // velocities and mass as the frame begins
    std::vector<double> penetration;  // each row's p0
};

inline FrameRows frame_rows(const Scene& scene, int frames) {
    World world(scene);
    for (int frame = 0; frame < frames; ++frame) world.step();
    const Detection detection = detect_contacts(scene, world.bodies());
    const std::vector<MassProperties> mass = mass_properties(world.bodies());
    std::pmr::vector<PreparedContact> prepared;
    prepare_contacts(detection.contacts, world.bodies(), mass, scene.settings, prepared);
    FrameRows frame;
    const std::pmr::vector<SolverBody> bodies = solver_bodies(world.bodies(), mass);
    frame.bodies.assign(bodies.begin(), bodies.end());
    for (const PreparedContact& p : prepared) {
        if (!can_move(p)) continue;
        ContactRow row;
        row.basis = Mat3::Identity();
        row.anchor = {Vec3::Zero(), Vec3::Zero()};
        fill_contact_row(row, p, frame.bodies.data());
        frame.rows.push_back(row);
        frame.penetration.push_back(p.penetration);
    }
    return frame;
}

}  // namespace impulse::test
