#include "formats/json_values.hpp"

namespace impulse::formats {

json vec3_json(const Vec3& v) {
    return json::array({v.x(), v.y(), v.z()});
}

json quat_json(const Quat& q) {
    return json::array({q.w(), q.x(), q.y(), q.z()});
}

json mat3_json(const Mat3& m) {
    json rows = json::array();
    for (int r = 0; r < 3; ++r) rows.push_back(json::array({m(r, 0), m(r, 1), m(r, 2)}));
    return rows;
}

Vec3 read_vec3(const json& j) {
    return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

Quat read_quat(const json& j) {
    return Quat(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>(), j.at(3).get<double>());
}

Mat3 read_mat3(const json& j) {
    Mat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m(r, c) = j.at(r).at(c).get<double>();
    return m;
}

}  // namespace impulse::formats
