#include "formats/physical_values.hpp"

#include "formats/input_error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace impulse::formats {

namespace {

std::string eigenvalues_text(const Eigen::Vector3d& values) {
    return number_text(values[0]) + ", " + number_text(values[1]) + ", " + number_text(values[2]);
}

std::string range_words(double lowest, double highest) {
    return number_text(lowest) + " to " + number_text(highest);
}

}  // namespace

double require_size(double value, const std::string& path) {
    if (!(value >= smallest_size && value <= largest_size))
        throw InputError(path, "must be from " + range_words(smallest_size, largest_size) +
                                   " (the engine multiplies sizes and masses together; outside this range the "
                                   "products overflow or vanish), got " +
                                   number_text(value));
    return value;
}

double require_size_or_zero(double value, const std::string& path) {
    if (value == 0.0) return value;
    if (!(value >= smallest_size && value <= largest_size))
        throw InputError(path, "must be 0 or from " + range_words(smallest_size, largest_size) +
                                   " (the engine multiplies sizes and masses together; outside this range the "
                                   "products overflow or vanish), got " +
                                   number_text(value));
    return value;
}

Vec3 require_lengths(const Vec3& v, const std::string& path) {
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(v[i]) <= largest_length))
            throw InputError(json_path_index(path, static_cast<std::size_t>(i)),
                             "must be from -" + number_text(largest_length) + " to " + number_text(largest_length) +
                                 " (the engine squares lengths and multiplies them with inertia; beyond this the "
                                 "products overflow), got " +
                                 number_text(v[i]));
    return v;
}

void require_inertia_entries(const Mat3& m, const std::string& path) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const double x = std::abs(m(r, c));
            if (x != 0.0 && !(x >= smallest_inertia && x <= largest_inertia))
                throw InputError(
                    json_path_index(json_path_index(path, static_cast<std::size_t>(r)), static_cast<std::size_t>(c)),
                    "must be 0 or from " + range_words(smallest_inertia, largest_inertia) +
                        " in size (the inertia of a body of 1e-30 to 1e30 kg and m), got " + number_text(m(r, c)));
        }
}

Quat unit_quaternion(const Quat& q, const std::string& path) {
    const double norm = q.norm();
    if (!(std::abs(norm - 1.0) <= unit_tolerance))
        throw InputError(
            path, "must be a unit quaternion [w, x, y, z] (length 1 within 1e-6), got length " + number_text(norm));
    return std::abs(norm - 1.0) > unit_rounding ? q.normalized() : q;
}

Vec3 nonzero_direction(const Vec3& n, const std::string& path) {
    require_lengths(n, path);
    const double length = n.norm();
    if (!(length > 1e-12)) throw InputError(path, "must not be zero");
    return std::abs(length - 1.0) > unit_rounding ? Vec3(n / length) : n;
}

void require_unit_vector(const Vec3& n, const std::string& path) {
    const double length = n.norm();
    if (!(std::abs(length - 1.0) <= unit_tolerance))
        throw InputError(path, "must be a unit vector (length 1 within 1e-6), got length " + number_text(length));
}

void require_orthonormal(const Mat3& m, const std::string& path) {
    const double off = (m.transpose() * m - Mat3::Identity()).cwiseAbs().maxCoeff();
    if (!(off <= unit_tolerance))
        throw InputError(path,
                         "must have unit columns at right angles (within 1e-6); its columns' dot products "
                         "are off by up to " +
                             number_text(off));
}

void require_symmetric(const Mat3& m, const std::string& path) {
    const double scale = std::max(1.0, m.cwiseAbs().maxCoeff());
    if (!((m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale))
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

}  // namespace impulse::formats
