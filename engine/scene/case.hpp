#pragma once
// A case: bodies without shapes, explicit contacts between them, and the settings to resolve them with.
// Enough to study one contact without collision detection.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "resolver/settings.hpp"

#include <string>
#include <vector>

namespace impulse {

struct Case {
    std::vector<std::string> body_names;  // one per body, unique
    std::vector<RigidBody> bodies;
    std::vector<Contact> contacts;  // as given (a world-first contact is swapped when prepared)
    ResolverSettings settings;

    bool operator==(const Case&) const = default;
};

}  // namespace impulse
