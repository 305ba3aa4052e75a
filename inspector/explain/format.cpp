#include "explain/format.hpp"

#include <cmath>
#include <cstdio>

namespace impulse::explain {

std::string number(double v) {
    // Rounding noise below 1e-12 of the value's scale would only distract; print an exact zero as 0.
    if (v == 0.0) return "0";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::string vector(const Vec3& v) {
    return "(" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + ")";
}

std::string matrix_rows(const Mat3& m) {
    std::string out;
    for (int r = 0; r < 3; ++r) {
        if (r > 0) out += '\n';
        out += "[" + number(m(r, 0)) + ", " + number(m(r, 1)) + ", " + number(m(r, 2)) + "]";
    }
    return out;
}

std::string quaternion(const Quat& q) {
    return "[" + number(q.w()) + ", " + number(q.x()) + ", " + number(q.y()) + ", " + number(q.z()) + "]";
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
