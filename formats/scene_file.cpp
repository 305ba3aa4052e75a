#include "formats/scene_file.hpp"

#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/physical_values.hpp"
#include "formats/schemas.hpp"
#include "formats/settings_json.hpp"
#include "formats/suggest.hpp"
#include "math/rotation.hpp"
#include "world/world.hpp"

#include <cmath>
#include <map>
#include <sstream>

namespace impulse::formats {

namespace {

Quat read_orientation(const json& body, const std::string& path) {
    if (body.contains("orientation") && body.contains("orientation_deg"))
        throw InputError(json_path_child(path, "orientation_deg"), "give orientation or orientation_deg, not both");
    if (body.contains("orientation_deg")) return orientation_from_euler_xyz_degrees(read_vec3(body["orientation_deg"]));
    if (!body.contains("orientation")) return Quat::Identity();
    return unit_quaternion(read_quat(body["orientation"]), json_path_child(path, "orientation"));
}

std::optional<Shape> read_shape(const json& body, const std::string& path) {
    if (!body.contains("shape")) return std::nullopt;
    const json& shape = body["shape"];
    const std::string shape_path = json_path_child(path, "shape");
    const std::string type = shape["type"].get<std::string>();
    const char* size_key = type == "sphere" ? "radius" : "half_size";
    const char* other_key = type == "sphere" ? "half_size" : "radius";
    if (!shape.contains(size_key))
        throw InputError(json_path_child(shape_path, size_key), "missing (a " + type + " needs a " + size_key + ")");
    if (shape.contains(other_key))
        throw InputError(json_path_child(shape_path, other_key), "does not belong to a " + type);
    if (type == "sphere")
        return Sphere{require_size(shape["radius"].get<double>(), json_path_child(shape_path, "radius"))};
    const Vec3 half_size = read_vec3(shape["half_size"]);
    for (int i = 0; i < 3; ++i)
        require_size(half_size[i],
                     json_path_index(json_path_child(shape_path, "half_size"), static_cast<std::size_t>(i)));
    return Box{half_size};
}

// Given inertia overrides the shape's; without either, an immovable body cannot turn and any other is an error.
Mat3 read_inverse_inertia(const json& body, double inverse_mass, const std::optional<Shape>& shape,
                          const std::string& path) {
    if (body.contains("inertia") && body.contains("inverse_inertia"))
        throw InputError(json_path_child(path, "inverse_inertia"), "give inertia or inverse_inertia, not both");
    if (body.contains("inverse_inertia")) {
        const Mat3 m = read_mat3(body["inverse_inertia"]);
        require_inertia_entries(m, json_path_child(path, "inverse_inertia"));
        check_inverse_inertia(m, json_path_child(path, "inverse_inertia"));
        return m;
    }
    if (body.contains("inertia")) {
        const Mat3 inertia = read_mat3(body["inertia"]);
        require_inertia_entries(inertia, json_path_child(path, "inertia"));
        const Mat3 inverse = inverse_of_inertia(inertia, json_path_child(path, "inertia"));
        require_inertia_entries(inverse, json_path_child(path, "inertia"));
        return inverse;
    }
    if (shape) return solid_inverse_inertia(*shape, inverse_mass);
    if (inverse_mass == 0.0) return Mat3::Zero();  // immovable: nothing turns it either
    throw InputError(path, "needs inertia, inverse_inertia or shape: a body with finite mass must resist rotation");
}

std::string read_material_name(const json& j, const std::map<std::string, Material>& materials,
                               const std::string& path) {
    const std::string name = j.value("material", default_material);
    if (materials.count(name)) return name;
    std::vector<std::string> known;
    for (const auto& [key, value] : materials) known.push_back(key);
    const std::optional<std::string> guess = closest_name(name, known);
    throw InputError(json_path_child(path, "material"),
                     "no material named \"" + name + "\"" + (guess ? " (did you mean \"" + *guess + "\"?)" : ""));
}

RigidBody read_body(const json& j, const std::optional<Shape>& shape, const std::string& path) {
    RigidBody body;
    const auto vec_or_zero = [&j](const char* key) { return j.contains(key) ? read_vec3(j[key]) : Vec3::Zero(); };
    body.position = require_lengths(vec_or_zero("position"), json_path_child(path, "position"));
    body.orientation = read_orientation(j, path);
    body.velocity = vec_or_zero("velocity");
    body.angular_velocity = vec_or_zero("angular_velocity");
    body.last_frame_acceleration = vec_or_zero("last_frame_acceleration");
    if (j.contains("mass") && j.contains("inverse_mass"))
        throw InputError(json_path_child(path, "inverse_mass"), "give mass or inverse_mass, not both");
    body.inverse_mass =
        j.contains("inverse_mass")
            ? require_size_or_zero(j["inverse_mass"].get<double>(), json_path_child(path, "inverse_mass"))
        : j.contains("mass") ? 1.0 / require_size(j["mass"].get<double>(), json_path_child(path, "mass"))
                             : 1.0;
    body.inverse_inertia_body = read_inverse_inertia(j, body.inverse_mass, shape, path);
    return body;
}

int read_body_reference(const json& ref, const std::vector<std::string>& names, const std::string& path) {
    if (ref.is_null()) return world_body;
    if (ref.is_string()) {
        const std::string name = ref.get<std::string>();
        for (std::size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return static_cast<int>(i);
        const std::optional<std::string> guess = closest_name(name, names);
        throw InputError(path, "no body named \"" + name + "\"" + (guess ? " (did you mean \"" + *guess + "\"?)" : ""));
    }
    const auto index = ref.get<long long>();
    if (index < 0 || index >= static_cast<long long>(names.size()))
        throw InputError(path, "no body with index " + std::to_string(index) + " (the scene has " +
                                   std::to_string(names.size()) + (names.size() == 1 ? " body" : " bodies") +
                                   ", numbered from 0)");
    return static_cast<int>(index);
}

Contact read_contact(const json& j, const std::vector<std::string>& names, const std::string& path) {
    Contact c;
    const std::string bodies_path = json_path_child(path, "bodies");
    for (std::size_t i = 0; i < 2; ++i)
        c.bodies[i] = read_body_reference(j["bodies"][i], names, json_path_index(bodies_path, i));
    if (c.bodies[0] == world_body && c.bodies[1] == world_body)
        throw InputError(bodies_path, "at least one must be a body (both are the world)");
    if (c.bodies[0] == c.bodies[1])
        throw InputError(bodies_path, "a body cannot touch itself (both are \"" +
                                          names[static_cast<std::size_t>(c.bodies[0])] + "\")");
    c.point = require_lengths(read_vec3(j["point"]), json_path_child(path, "point"));
    c.normal = nonzero_direction(read_vec3(j["normal"]), json_path_child(path, "normal"));
    c.penetration = j.value("penetration", 0.0);
    if (!(std::abs(c.penetration) <= largest_length))
        throw InputError(json_path_child(path, "penetration"), "must be from -" + number_text(largest_length) + " to " +
                                                                   number_text(largest_length) + ", got " +
                                                                   number_text(c.penetration));
    c.restitution = j.value("restitution", 0.0);
    c.friction = j.value("friction", 0.0);
    return c;
}

std::map<std::string, Material> read_materials(const json& document) {
    std::map<std::string, Material> materials{{default_material, Material{}}};
    if (!document.contains("materials")) return materials;
    for (const auto& [name, j] : document["materials"].items()) {
        Material m;
        m.restitution = j.value("restitution", m.restitution);
        m.friction = j.value("friction", m.friction);
        materials[name] = m;
    }
    return materials;
}

std::optional<Ground> read_ground(const json& document, const std::map<std::string, Material>& materials) {
    if (!document.contains("ground")) return std::nullopt;
    const json& j = document["ground"];
    Ground ground;
    if (j.contains("normal")) ground.plane.normal = nonzero_direction(read_vec3(j["normal"]), "ground.normal");
    ground.plane.offset = j.value("offset", 0.0);
    if (!(std::abs(ground.plane.offset) <= largest_length))
        throw InputError("ground.offset", "must be from -" + number_text(largest_length) + " to " +
                                              number_text(largest_length) + ", got " +
                                              number_text(ground.plane.offset));
    ground.material = read_material_name(j, materials, "ground");
    return ground;
}

}  // namespace

Scene read_scene(const json& document, const std::optional<std::string>& preset_override) {
    if (document.is_object() && document.contains("settings"))
        refuse_renamed_settings(document["settings"], "settings");
    validate_scene_document(document);
    Scene c;
    c.materials = read_materials(document);
    c.ground = read_ground(document, c.materials);
    const json& bodies = document["bodies"];
    std::map<std::string, std::size_t> first_with_name;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const std::string path = json_path_index("bodies", i);
        const std::string name = bodies[i].value("name", "body" + std::to_string(i));
        const auto [at, inserted] = first_with_name.emplace(name, i);
        if (!inserted)
            throw InputError(json_path_child(path, "name"),
                             "\"" + name + "\" is already the name of bodies[" + std::to_string(at->second) + "]");
        c.body_names.push_back(name);
        c.shapes.push_back(read_shape(bodies[i], path));
        c.bodies.push_back(read_body(bodies[i], c.shapes.back(), path));
        c.body_materials.push_back(read_material_name(bodies[i], c.materials, path));
    }
    if (document.contains("contacts")) {
        const json& contacts = document["contacts"];
        for (std::size_t i = 0; i < contacts.size(); ++i)
            c.contacts.push_back(read_contact(contacts[i], c.body_names, json_path_index("contacts", i)));
    }
    if (document.contains("gravity")) c.world.gravity = read_vec3(document["gravity"]);
    read_settings(c, document.contains("settings") ? &document["settings"] : nullptr, "settings", preset_override);
    return c;
}

Scene read_scene_text(std::string_view text, const std::optional<std::string>& preset_override) {
    return read_scene(parse_json_text(text), preset_override);
}

json scene_json(const Scene& c, bool with_settings) {
    json out = json::object();
    out["format"] = "impulse-lab-scene";
    out["gravity"] = vec3_json(c.world.gravity);
    if (c.ground)
        out["ground"] = {{"normal", vec3_json(c.ground->plane.normal)},
                         {"offset", c.ground->plane.offset},
                         {"material", c.ground->material}};
    json materials = json::object();
    for (const auto& [name, m] : c.materials)
        materials[name] = {{"restitution", m.restitution}, {"friction", m.friction}};
    out["materials"] = materials;
    json bodies = json::array();
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
        const RigidBody& b = c.bodies[i];
        json body = {{"name", c.body_names[i]}};
        if (const auto& shape = c.shapes[i]) {
            if (const auto* sphere = std::get_if<Sphere>(&*shape))
                body["shape"] = {{"type", "sphere"}, {"radius", sphere->radius}};
            else
                body["shape"] = {{"type", "box"}, {"half_size", vec3_json(std::get<Box>(*shape).half_size)}};
        }
        body["material"] = c.body_materials[i];
        body["position"] = vec3_json(b.position);
        body["orientation"] = quat_json(b.orientation);
        body["velocity"] = vec3_json(b.velocity);
        body["angular_velocity"] = vec3_json(b.angular_velocity);
        body["inverse_mass"] = b.inverse_mass;
        body["inverse_inertia"] = mat3_json(b.inverse_inertia_body);
        body["last_frame_acceleration"] = vec3_json(b.last_frame_acceleration);
        bodies.push_back(body);
    }
    out["bodies"] = bodies;
    json contacts = json::array();
    const auto reference = [&c](int body) {
        return body == world_body ? json(nullptr) : json(c.body_names[static_cast<std::size_t>(body)]);
    };
    for (const Contact& contact : c.contacts) {
        contacts.push_back({
            {"bodies", json::array({reference(contact.bodies[0]), reference(contact.bodies[1])})},
            {"point", vec3_json(contact.point)},
            {"normal", vec3_json(contact.normal)},
            {"penetration", contact.penetration},
            {"restitution", contact.restitution},
            {"friction", contact.friction},
        });
    }
    out["contacts"] = contacts;
    if (with_settings) out["settings"] = settings_json(c.settings, c.world);
    return out;
}

ContactBudgetError contact_budget_error(int frame) {
    return ContactBudgetError("frame " + std::to_string(frame),
                              "the bodies' shapes touch in more than " + std::to_string(max_contacts_per_frame) +
                                  " contacts, more than a frame may resolve (are many bodies piled at one point?)");
}

}  // namespace impulse::formats
