#include "explain/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse::explain {

std::string number(double v, double scale) {
    if (v == 0.0 || std::abs(v) < noise_fraction * scale) return "0";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::string vector(const Vec3& v, double scale) {
    scale = std::max(scale, v.cwiseAbs().maxCoeff());
    return "(" + number(v.x(), scale) + ", " + number(v.y(), scale) + ", " + number(v.z(), scale) + ")";
}

std::string matrix_rows(const Mat3& m, double scale) {
    scale = std::max(scale, m.cwiseAbs().maxCoeff());
    std::string out;
    for (int r = 0; r < 3; ++r) {
        if (r > 0) out += '\n';
        out += "[" + number(m(r, 0), scale) + ", " + number(m(r, 1), scale) + ", " + number(m(r, 2), scale) + "]";
    }
    return out;
}

std::string quaternion(const Quat& q) {
    // A unit quaternion: its scale is 1.
    return "[" + number(q.w(), 1.0) + ", " + number(q.x(), 1.0) + ", " + number(q.y(), 1.0) + ", " +
           number(q.z(), 1.0) + "]";
}

std::string exact(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

std::string exact(const Vec3& v) {
    return "(" + exact(v.x()) + ", " + exact(v.y()) + ", " + exact(v.z()) + ")";
}

std::string exact(const Mat3& m) {
    std::string out;
    for (int r = 0; r < 3; ++r) {
        if (r > 0) out += "; ";
        out += "[" + exact(m(r, 0)) + ", " + exact(m(r, 1)) + ", " + exact(m(r, 2)) + "]";
    }
    return out;
}

std::string percent(double share) {
    char text[32];
    // %.3g would switch to an exponent from 1000 on; a share that large is shown whole.
    std::snprintf(text, sizeof text, std::abs(share) < 1000.0 ? "%.3g" : "%.0f", share);
    return text;
}

std::string with_unit(std::string value, std::string_view unit) {
    if (!unit.empty()) {
        // A matrix's unit goes after its last row.
        value += ' ';
        value += unit;
    }
    return value;
}

}  // namespace impulse::explain
