#include "io/case_file.hpp"

#include "io/input_error.hpp"
#include "io/json_text.hpp"
#include "io/schemas.hpp"
#include "io/settings_json.hpp"
#include "io/suggest.hpp"
#include "math/rotation.hpp"

#include <cmath>
#include <map>
#include <sstream>

namespace impulse::io {

namespace {

// A stored quaternion or normal is used as it is when it is unit to rounding, so a file written by us
// reads back bit for bit; otherwise it is normalised (quaternions only within 1e-6 of unit length).
constexpr double unit_rounding = 1e-12;
constexpr double unit_quaternion_tolerance = 1e-6;

std::string eigenvalues_text(const Eigen::Vector3d& values) {
    std::ostringstream out;
    out << number_text(values[0]) << ", " << number_text(values[1]) << ", " << number_text(values[2]);
    return out.str();
}

void require_symmetric(const Mat3& m, const std::string& path) {
    const double scale = std::max(1.0, m.cwiseAbs().maxCoeff());
    if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
        throw InputError(path, "must be symmetric (row i, column j equal to row j, column i)");
}

Mat3 inverse_of_inertia(const Mat3& inertia, const std::string& path) {
    require_symmetric(inertia, path);
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(inertia);
    if (eigen.eigenvalues().minCoeff() <= 0.0)
        throw InputError(path,
                         "must be positive definite, but its eigenvalues are " + eigenvalues_text(eigen.eigenvalues()));
    return inertia.inverse();
}

void check_inverse_inertia(const Mat3& inverse_inertia, const std::string& path) {
    require_symmetric(inverse_inertia, path);
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(inverse_inertia);
    const double scale = std::max(1.0, inverse_inertia.cwiseAbs().maxCoeff());
    if (eigen.eigenvalues().minCoeff() < -1e-12 * scale)
        throw InputError(path, "must be positive semi-definite (zero = cannot rotate), but its eigenvalues are " +
                                   eigenvalues_text(eigen.eigenvalues()));
}

Quat read_orientation(const json& body, const std::string& path) {
    if (body.contains("orientation") && body.contains("orientation_deg"))
        throw InputError(json_path_child(path, "orientation_deg"), "give orientation or orientation_deg, not both");
    if (body.contains("orientation_deg")) return orientation_from_euler_xyz_degrees(read_vec3(body["orientation_deg"]));
    if (!body.contains("orientation")) return Quat::Identity();
    Quat q = read_quat(body["orientation"]);
    const double norm = q.norm();
    if (std::abs(norm - 1.0) > unit_quaternion_tolerance)
        throw InputError(
            json_path_child(path, "orientation"),
            "must be a unit quaternion [w, x, y, z] (length 1 within 1e-6), got length " + number_text(norm));
    if (std::abs(norm - 1.0) > unit_rounding) q.normalize();
    return q;
}

Mat3 read_inverse_inertia(const json& body, double inverse_mass, const std::string& path) {
    const int given =
        int(body.contains("inertia")) + int(body.contains("inverse_inertia")) + int(body.contains("shape"));
    if (given > 1) throw InputError(path, "give only one of inertia, inverse_inertia and shape (they would disagree)");
    if (body.contains("inverse_inertia")) {
        const Mat3 m = read_mat3(body["inverse_inertia"]);
        check_inverse_inertia(m, json_path_child(path, "inverse_inertia"));
        return m;
    }
    if (body.contains("inertia"))
        return inverse_of_inertia(read_mat3(body["inertia"]), json_path_child(path, "inertia"));
    if (body.contains("shape")) {
        const json& shape = body["shape"];
        const std::string shape_path = json_path_child(path, "shape");
        const std::string type = shape["type"].get<std::string>();
        const char* size_key = type == "sphere" ? "radius" : "half_size";
        const char* other_key = type == "sphere" ? "half_size" : "radius";
        if (!shape.contains(size_key))
            throw InputError(
                json_path_child(shape_path, size_key),
                std::string("missing (a ") + type + " needs a " + (type == "sphere" ? "radius" : "half_size") + ")");
        if (shape.contains(other_key))
            throw InputError(json_path_child(shape_path, other_key), "does not belong to a " + type);
        if (type == "sphere") return sphere_inverse_inertia(inverse_mass, shape["radius"].get<double>());
        const Vec3 half_size = read_vec3(shape["half_size"]);
        for (int i = 0; i < 3; ++i)
            if (!(half_size[i] > 0.0))
                throw InputError(json_path_index(json_path_child(shape_path, "half_size"), static_cast<std::size_t>(i)),
                                 "must be > 0, got " + number_text(half_size[i]));
        return box_inverse_inertia(inverse_mass, half_size);
    }
    if (inverse_mass == 0.0) return Mat3::Zero();  // immovable: nothing turns it either
    throw InputError(path, "needs inertia, inverse_inertia or shape: a body with finite mass must resist rotation");
}

RigidBody read_body(const json& j, const std::string& path) {
    RigidBody body;
    const auto vec_or_zero = [&j](const char* key) { return j.contains(key) ? read_vec3(j[key]) : Vec3::Zero(); };
    body.position = vec_or_zero("position");
    body.orientation = read_orientation(j, path);
    body.velocity = vec_or_zero("velocity");
    body.angular_velocity = vec_or_zero("angular_velocity");
    body.last_frame_acceleration = vec_or_zero("last_frame_acceleration");
    if (j.contains("mass") && j.contains("inverse_mass"))
        throw InputError(json_path_child(path, "inverse_mass"), "give mass or inverse_mass, not both");
    body.inverse_mass = j.contains("inverse_mass") ? j["inverse_mass"].get<double>()
                        : j.contains("mass")       ? 1.0 / j["mass"].get<double>()
                                                   : 1.0;
    body.inverse_inertia_body = read_inverse_inertia(j, body.inverse_mass, path);
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
        throw InputError(path, "no body with index " + std::to_string(index) + " (the case has " +
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
    c.point = read_vec3(j["point"]);
    c.normal = read_vec3(j["normal"]);
    const double length = c.normal.norm();
    if (!(length > 1e-12)) throw InputError(json_path_child(path, "normal"), "must not be zero");
    if (std::abs(length - 1.0) > unit_rounding) c.normal /= length;
    c.penetration = j.value("penetration", 0.0);
    c.restitution = j.value("restitution", 0.0);
    c.friction = j.value("friction", 0.0);
    return c;
}

}  // namespace

Mat3 sphere_inverse_inertia(double inverse_mass, double radius) {
    // I = 2/5 m r^2  =>  I^-1 = 5 / (2 m r^2) = 2.5 m^-1 / r^2
    return Mat3::Identity() * (2.5 * inverse_mass / (radius * radius));
}

Mat3 box_inverse_inertia(double inverse_mass, const Vec3& h) {
    // I_xx = m (b^2 + c^2) / 3 for half-sizes (a, b, c), and likewise about y and z.
    const Vec3 squares = h.cwiseProduct(h);
    return Vec3(3.0 * inverse_mass / (squares.y() + squares.z()), 3.0 * inverse_mass / (squares.x() + squares.z()),
                3.0 * inverse_mass / (squares.x() + squares.y()))
        .asDiagonal();
}

Case read_case(const json& document, const std::optional<std::string>& preset_override) {
    validate_case_document(document);
    Case c;
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
        c.bodies.push_back(read_body(bodies[i], path));
    }
    const json& contacts = document["contacts"];
    for (std::size_t i = 0; i < contacts.size(); ++i)
        c.contacts.push_back(read_contact(contacts[i], c.body_names, json_path_index("contacts", i)));
    c.settings =
        read_settings(document.contains("settings") ? &document["settings"] : nullptr, "settings", preset_override);
    return c;
}

Case read_case_text(std::string_view text, const std::optional<std::string>& preset_override) {
    return read_case(parse_json_text(text), preset_override);
}

json case_json(const Case& c, bool with_settings) {
    json out = json::object();
    out["format"] = "impulse-lab-case";
    json bodies = json::array();
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
        const RigidBody& b = c.bodies[i];
        bodies.push_back({
            {"name", c.body_names[i]},
            {"position", vec3_json(b.position)},
            {"orientation", quat_json(b.orientation)},
            {"velocity", vec3_json(b.velocity)},
            {"angular_velocity", vec3_json(b.angular_velocity)},
            {"inverse_mass", b.inverse_mass},
            {"inverse_inertia", mat3_json(b.inverse_inertia_body)},
            {"last_frame_acceleration", vec3_json(b.last_frame_acceleration)},
        });
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
    if (with_settings) out["settings"] = settings_json(c.settings);
    return out;
}

}  // namespace impulse::io
