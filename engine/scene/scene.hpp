#pragma once
// A scene: bodies (with collision shapes or without), their materials, the ground, gravity, contacts written
// by hand, and the settings to simulate and resolve them with. A case is a scene whose contacts are written
// out, to study them without collision detection.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "settings/settings.hpp"
#include "shapes/shape.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impulse {

struct Material {
    double restitution = 0.0;  // c, combined per contact by the larger of the two
    double friction = 0.5;     // mu, combined per contact as sqrt(mu_0 mu_1)

    bool operator==(const Material&) const = default;
};

// The material of a contact between two materials: restitution max(c0, c1) (the bouncier surface decides, as in
// Box2D), friction sqrt(mu0 mu1) (either surface being frictionless makes the contact frictionless).
Material combine(const Material& a, const Material& b);

inline const std::string default_material = "default";

struct Ground {
    HalfSpace plane{};
    std::string material = default_material;

    bool operator==(const Ground&) const = default;
};

struct WorldSettings {
    Vec3 gravity = {0.0, -9.81, 0.0};  // m/s^2
    int frames = 600;                  // frames `run` simulates (10 s at the default 1/60 s)
    double linear_damping = 1.0;       // share of the velocity kept per second (v *= d^dt); 1 = none
    double angular_damping = 1.0;      // likewise for angular velocity

    bool operator==(const WorldSettings&) const = default;
};

struct Scene {
    std::vector<std::string> body_names;  // one per body, unique
    std::vector<RigidBody> bodies;
    std::vector<std::optional<Shape>> shapes;   // per body; empty = no collision shape
    std::vector<std::string> body_materials;    // per body, a key of `materials`
    std::map<std::string, Material> materials;  // always holds "default"
    std::optional<Ground> ground;               // absent = no ground
    std::vector<Contact> contacts;              // written by hand (a world-first contact is swapped when prepared)
    ResolverSettings settings;                  // settings.duration is the frame's duration (the step size)
    WorldSettings world;

    bool operator==(const Scene&) const = default;
};

}  // namespace impulse
