#include "shapes/shape.hpp"

namespace impulse {

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

Mat3 solid_inverse_inertia(const Shape& shape, double inverse_mass) {
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere_inverse_inertia(inverse_mass, sphere->radius);
    return box_inverse_inertia(inverse_mass, std::get<Box>(shape).half_size);
}

double bounding_radius(const Shape& shape) {
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->radius;
    return std::get<Box>(shape).half_size.norm();
}

Vec3 box_vertex(const Vec3& h, int vertex) {
    return {(vertex & 1) ? -h.x() : h.x(), (vertex & 2) ? -h.y() : h.y(), (vertex & 4) ? -h.z() : h.z()};
}

int box_face(int axis, bool negative) {
    return 2 * axis + (negative ? 1 : 0);
}

int box_edge(int axis, const std::array<int, 3>& negative) {
    const int first = axis == 0 ? 1 : 0, second = axis == 2 ? 1 : 2;  // the other two axes, in axis order
    return 4 * axis + negative[static_cast<std::size_t>(first)] + 2 * negative[static_cast<std::size_t>(second)];
}

}  // namespace impulse
