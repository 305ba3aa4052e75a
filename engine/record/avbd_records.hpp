#pragma once
// AVBD's visits (methods/avbd.cpp) as a trace records them. AVBD works on bodies, not contacts: a sweep visits every
// body, which gathers its contacts' forces into a 6x6 block and moves by the block's solution (the primal update);
// then every contact's lambda and stiffness are updated (the dual update). Each of the two is an iteration of the
// velocity phase: a body visit (`body`, the contacts it gathered, its block and its move) or a contact's dual update
// (its constraint, force, and new lambda and k). The words are in formats/word_table.hpp; docs/methods.md derives
// them.
//
// What the method reports (plain numbers, when the recorder keeps the frame) and the records built from it are the
// same structs: the record is the report with the sweep's place and its number in the phase (record/trace_recorder).

#include "derivation/avbd/contact_force.hpp"
#include "derivation/avbd/dual_update.hpp"
#include "derivation/avbd/implicit_euler.hpp"

#include <vector>

namespace impulse {

// A contact's rows as a visit read them: the values of derivation/avbd/contact_constraint.hpp and contact_force.hpp.
struct AvbdContactRows {
    int contact = 0;
    int slot = 0;                    // in a body visit: which of the contact's bodies the visited body is (0 or 1)
    Vec3 constraint = Vec3::Zero();  // C* (m), contact coordinates
    Stiffness stiffness;             // k_n, k_t (N/m) the force is computed with
    Vec3 lambda = Vec3::Zero();      // lambda (N) the force is computed with
    Vec3 force = Vec3::Zero();       // F = clamp(lambda - k C*) (N), contact coordinates
    double friction = 0.0;           // mu, which bounds F's tangential part

    bool operator==(const AvbdContactRows&) const = default;
};

// The primal update of one body (Eqs. 4-6, 13, 17).
struct BodyVisitRecord {
    int body = 0;
    std::vector<AvbdContactRows> gathered;  // its contacts, in contact order, as its block read them
    Mat6 block_matrix = Mat6::Zero();       // H = M/h^2 + sum k J J^T
    Vec6 block_force = Vec6::Zero();        // f = M/h^2 (y - x) + sum F J
    Displacement position_change;           // delta x = H^-1 f
    Displacement displacement;              // x - x-, the body's move since the frame began, after this visit

    bool operator==(const BodyVisitRecord&) const = default;
};

// The dual update of one contact (Eqs. 11, 16): its force at the bodies' new positions becomes its lambda.
struct DualUpdateRecord {
    AvbdContactRows rows;   // before the update: the lambda and k the force used
    DualVariables updated;  // lambda <- F; k <- min(k + beta |C*|, k_max) where the row is inside its bounds

    bool operator==(const DualUpdateRecord&) const = default;
};

}  // namespace impulse
