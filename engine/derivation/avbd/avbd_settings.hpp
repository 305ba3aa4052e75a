#pragma once
// What a user chooses for AVBD (Giles, Diaz and Yuksel, "Augmented Vertex Block Descent", SIGGRAPH 2025): the
// iteration count and the four numbers of its augmented Lagrangian. The derivation steps of derivation/avbd/
// read them; settings/settings.hpp carries them in ResolverSettings::avbd. beta, k_min and k_max are per kilogram: a
// contact uses them times the mass of the lighter body it holds (derivation/avbd/mass_scaled_penalty.hpp), so the
// numbers tuned on 1 kg boxes hold a 10^6 kg box as they hold a 1 kg one.

namespace impulse {

struct AvbdSettings {
    int iterations = 10;           // primal sweeps over the bodies per frame, each followed by a dual update
    double alpha = 0.99;           // stabilisation: a frame removes 1 - alpha of the penetration it began with
    double beta = 1.0e6;           // N/m^2 per kg: stiffness ramp, k += m beta |C| after an iteration (Eq. 16)
    double gamma = 0.99;           // warm-start decay of lambda and k from last frame (Eq. 19)
    double stiffness_min = 1.0e4;  // N/m per kg (1/s^2): m times it is a new contact's k, and a remembered one's floor
    double stiffness_max = 1.0e9;  // N/m per kg (1/s^2): m times it is the ceiling of k (Eqs. 16, 19)
    double slop = 0.001;  // m: the penetration a contact's constraint allows, so a resting contact stays touching
                          // (and detected) frame after frame (the demo's collision margin)
    // The reference demo's alternative to alpha: alpha = 1 in the iterations (no correction, so no velocity from
    // it), then one more primal sweep with alpha = 0 after the velocities are taken, which moves the bodies out of
    // the penetration without giving them speed. Last frame's lambda is then kept whole (only k decays).
    bool post_stabilize = true;

    bool operator==(const AvbdSettings&) const = default;
};

}  // namespace impulse
