#pragma once
// The penalty parameters one contact uses: AVBD's settings beta, k_min and k_max are per kilogram, and a contact
// takes them times the mass of the lighter body it holds,
//   m = min(m_0, m_1)   over the bodies that translate (the world, a static body: no mass, left out)
//   beta = m beta/kg,   k_min = m k_min/kg,   k_max = m k_max/kg
// and 1 kg when neither body translates (the settings taken as they are).
//
// Why scale at all. The paper's k is a stiffness in N/m, and its numbers (beta in [1, 1000], per the reference demo
// savant117/avbd-demo2d's solver.cpp, which notes that the best choice "will depend on the length, mass, and
// constraint function scales (ie units) of your simulation"; the demo's beta 1e5, k_min 1, k_max 1e9) were chosen
// for its scenes, boxes of about a kilogram. A body's block is H = M/h^2 + sum k J J^T (Eqs. 5, 6): how far one
// iteration takes a contact towards its force depends on k against m/h^2 (the cube on the ground in docs/methods.md:
// the error shrinks by M/(M + K) an iteration). Fixed in N/m, the same k is stiff for a 1 kg box and nothing for a
// 10^6 kg one, whose contacts start 10^6 times too soft and ramp 10^6 times too slowly (Jolt's heavy_on_light fell
// through in a third of a second). Per kilogram, k/(m/h^2) is what it was at 1 kg, and a scene with every mass times
// s moves as it did: k, lambda, F, H and f all scale by s, the move H^-1 f does not.
//
// Why the lighter body's. A contact's own mass is the reduced mass mu = m_0 m_1 / (m_0 + m_1), the inverse of the
// chapter's velocity change per unit impulse along the normal without the turning terms (step 3): k/mu is the
// square of the contact's natural frequency, so k per kg of mu is a frequency the masses do not change, as soft step
// sets its springs. The lighter mass is mu to within a factor of 2 (mu <= min <= 2 mu), exactly mu on the world, and
// 1 for two 1 kg bodies, where mu (0.5) would halve the stiffness of every box on a box and change every 1 kg scene
// the settings were tuned on. The heavier mass (mu times 1 + m_heavy/m_light) makes the lighter body's block all
// contact: measured, it set stack_ratio_1024 ringing at 0.5 m/s to the end of a 10 s run (10 iterations), took
// two_spheres' momentum error from 0.22 to 0.42 at N = 1 (6.8e-5 against 1.6e-7 at 32) and mass_ratio_1000's drift
// 1.5 to 2.2 times up at N = 1 and 2 (impulse-lab bench, avbd); the lighter mass leaves those three as they were
// (their light bodies weigh 1 kg), holds heavy_on_light from N = 1 (2.0 cm; 2 mm from N = 16) and stack_ratio_1024
// from N = 8, both at rest after 10 s. docs/methods.md ("Penalty per kilogram") has the figures, and what it costs:
// a stack doubling from 1 kg to 1024 kg rings at 10 iterations, as it does under mu (tests/engine/test_avbd.cpp).

#include "derivation/avbd/avbd_settings.hpp"

#include <array>

namespace impulse {

struct PenaltyParameters {
    double mass = 1.0;           // m (kg): the lighter translating body of the contact's two
    double beta = 0.0;           // N/m^2: the stiffness ramp, k += beta |C| after an iteration (Eq. 16)
    double stiffness_min = 0.0;  // N/m: a new contact's k, and the floor of a remembered one (Eq. 19)
    double stiffness_max = 0.0;  // N/m: the ceiling of k (Eqs. 16, 19)

    bool operator==(const PenaltyParameters&) const = default;
};

// `mass`: each body's mass (kg), 0 for the world and for a body that cannot translate (inverse mass 0).
PenaltyParameters mass_scaled_penalty(const AvbdSettings& settings, const std::array<double, 2>& mass);

}  // namespace impulse
