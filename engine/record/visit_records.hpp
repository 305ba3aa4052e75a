#pragma once
// The iterations of a trace, built from what the methods report of their visits (record/visits.hpp): each visit's
// derivation values, and the updates it made to the bookkeeping of every contact sharing a body. The recorder
// keeps its own copy of the bookkeeping, from the contacts as prepared, and updates it with the book's functions
// (preparation/bookkeeping.hpp): for the book's methods it is theirs to the bit, and a method that keeps none
// (projected Gauss-Seidel, the split impulse) is shown what the book's would say, in that method's terms.

#include "preparation/bookkeeping.hpp"
#include "record/iteration_records.hpp"
#include "record/recorder.hpp"
#include "record/visits.hpp"

#include <optional>
#include <vector>

namespace impulse {

class VisitRecords {
public:
    // A frame's start: its contacts as prepared are the bookkeeping's start.
    void begin(const PreparedFrame& frame);
    // A visit as an iteration of its phase (numbered by the trace recorder); the bookkeeping follows it.
    PositionIteration position_iteration(const PositionVisit& visit);
    VelocityIteration velocity_iteration(const VelocityVisit& visit);

private:
    // The split impulse's push as step 8's record: step 3's inertias, and how far it moved the contact's points.
    PositionResolution push_resolution(const PositionVisit& visit) const;
    // An accumulating method's visit as steps 5 to 7: the impulse applied is the change of its total.
    VelocityResolution row_resolution(const VelocityVisit& visit) const;
    void record_updates(const PositionChange& change, const std::array<int, 2>& moved, PositionIteration& it);
    void record_updates(const VelocityChange& change, const std::array<int, 2>& moved, DesiredFollows follows,
                        VelocityIteration& it);

    std::vector<PreparedContact> contacts_;  // the bookkeeping as the frame's iterations left it
    std::vector<double> targets_;            // per contact: the normal velocity a rigid row asks for (0: inert)
    std::vector<MassProperties> mass_;       // per body
    VelocityRefinements refinements_{};
    std::optional<ContactsByBody> by_body_;
    std::vector<int> sharing_;
};

}  // namespace impulse
