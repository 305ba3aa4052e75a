#include "record/trace.hpp"

#include <algorithm>

namespace impulse {

bool TraceFilter::records_contact(int contact) const {
    return !contacts || std::find(contacts->begin(), contacts->end(), contact) != contacts->end();
}

BodyState state_of(const RigidBody& body) {
    return {body.position, body.orientation, body.velocity, body.angular_velocity};
}

}  // namespace impulse
