#include "derivation/avbd/contact_constraint.hpp"

namespace impulse {

ConstraintJacobian constraint_jacobian(const Basis& basis, const std::array<Vec3, 2>& relative_position) {
    return {{basis.normal(), basis.tangent1(), basis.tangent2()}, relative_position};
}

Vec6 constraint_gradient(const ConstraintJacobian& jacobian, int row, int body_slot) {
    const double s = body_sign(body_slot);
    const Vec3& u = jacobian.axis[static_cast<std::size_t>(row)];
    Vec6 g;
    g << s * u, s * jacobian.relative_position[static_cast<std::size_t>(body_slot)].cross(u);  // s_i (u, r_i x u)
    return g;
}

}  // namespace impulse
