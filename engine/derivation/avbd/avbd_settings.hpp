#pragma once
// What a user chooses for AVBD (Giles, Diaz and Yuksel, "Augmented Vertex Block Descent", SIGGRAPH 2025): the
// iteration count and the four numbers of its augmented Lagrangian. The derivation steps of derivation/avbd/
// read them; settings/settings.hpp carries them in ResolverSettings::avbd.

namespace impulse {

struct AvbdSettings {
    int iterations = 10;           // primal sweeps over the bodies per frame, each followed by a dual update
    double alpha = 0.99;           // stabilisation: a frame removes 1 - alpha of the penetration it began with
    double beta = 1.0e6;           // N/m^2: stiffness ramp, k += beta |C| after an iteration (Eq. 16)
    double gamma = 0.99;           // warm-start decay of lambda and k from last frame (Eq. 19)
    double stiffness_min = 1.0e4;  // N/m: a new contact's k, and the floor of a remembered one (Eq. 19)
    double stiffness_max = 1.0e9;  // N/m: the ceiling of k (Eq. 16)
    double slop = 0.001;  // m: the penetration a contact's constraint allows, so a resting contact stays touching
                          // (and detected) frame after frame (the demo's collision margin)
    // The reference demo's alternative to alpha: alpha = 1 in the iterations (no correction, so no velocity from
    // it), then one more primal sweep with alpha = 0 after the velocities are taken, which moves the bodies out of
    // the penetration without giving them speed. Last frame's lambda is then kept whole (only k decays).
    bool post_stabilize = true;

    bool operator==(const AvbdSettings&) const = default;
};

}  // namespace impulse
