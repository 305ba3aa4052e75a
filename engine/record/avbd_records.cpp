#include "record/avbd_records.hpp"

#include "record/trace.hpp"

namespace impulse {

VelocityIteration body_visit_iteration(int iteration, const SweepPlace& place, const BodyVisitRecord& visit,
                                       const TraceFilter& filter) {
    VelocityIteration it{};
    it.iteration = iteration;
    // Every solved body has a contact (methods/avbd.cpp solves no other), so its first is its iteration's contact.
    it.contact = visit.gathered.empty() ? 0 : visit.gathered.front().contact;
    it.sweep = place;
    BodyVisitRecord& kept = it.body_visit.emplace(visit);
    if (filter.contacts)
        std::erase_if(kept.gathered,
                      [&filter](const AvbdContactRows& c) { return !filter.records_contact(c.contact); });
    return it;
}

VelocityIteration dual_update_iteration(int iteration, const SweepPlace& place, const DualUpdateRecord& update,
                                        const TraceFilter& filter) {
    VelocityIteration it{};
    it.iteration = iteration;
    it.contact = update.rows.contact;
    it.sweep = place;
    if (filter.records_contact(update.rows.contact)) it.dual_update = update;
    return it;
}

}  // namespace impulse
