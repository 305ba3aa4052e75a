#pragma once
// The conventions of docs/design.md in JSON: vectors [x, y, z], quaternions [w, x, y, z], matrices row-major
// [[row0], [row1], [row2]], per-body values [body0, body1] with null for the world. The readers assume the
// value already passed its schema (right types and lengths).

#include "math/types.hpp"

#include <nlohmann/json.hpp>

namespace impulse::formats {

using json = nlohmann::ordered_json;  // keys stay in the order written

json vec3_json(const Vec3& v);
json quat_json(const Quat& q);
json mat3_json(const Mat3& m);
Vec3 read_vec3(const json& j);
Quat read_quat(const json& j);  // as stored, not normalised
Mat3 read_mat3(const json& j);

template <typename T, typename Write>
json per_body_json(const PerBody<T>& values, Write write) {
    json out = json::array();
    for (const auto& v : values) out.push_back(v ? write(*v) : json(nullptr));
    return out;
}

template <typename T, typename Read>
PerBody<T> read_per_body(const json& j, Read read) {
    PerBody<T> out;
    for (std::size_t i = 0; i < 2; ++i)
        if (!j.at(i).is_null()) out[i] = read(j.at(i));
    return out;
}

inline json number_json(double v) {
    return v;
}
inline double read_number(const json& j) {
    return j.get<double>();
}

}  // namespace impulse::formats
