// Contact generation over random boxes: swap symmetry and soundness of every contact
// (rapidcheck, 1000+ cases each; the broad phase against brute force is test_broad_phase.cpp).

#include "collision/collision.hpp"
#include "support/property.hpp"
#include "support/random_contacts.hpp"

#include <algorithm>
#include <cmath>

using namespace impulse;
using namespace impulse::test;

namespace {

Placement at(const Vec3& position, const Quat& orientation = Quat::Identity()) {
    return {position, orientation.toRotationMatrix()};
}

}  // namespace

TEST_CASE("swapping the two bodies flips every normal and keeps the points, depths and features") {
    check_property("box-box swap", [] {
        const Placement a = at(any_vector(0.6), any_orientation());
        const Placement b = at(any_vector(0.6), any_orientation());
        const Box ba{Vec3(*in_range(0.1, 0.6), *in_range(0.1, 0.6), *in_range(0.1, 0.6))};
        const Box bb{Vec3(*in_range(0.1, 0.6), *in_range(0.1, 0.6), *in_range(0.1, 0.6))};
        std::vector<Contact> forward, backward;
        box_and_box(ba, a, 0, bb, b, 1, forward);
        box_and_box(bb, b, 1, ba, a, 0, backward);
        RC_ASSERT(forward.size() == backward.size());
        for (const Contact& f : forward) {
            const bool matched = std::any_of(backward.begin(), backward.end(), [&](const Contact& g) {
                return (f.point - g.point).norm() < 1e-9 && (f.normal + g.normal).norm() < 1e-9 &&
                       std::abs(f.penetration - g.penetration) < 1e-9 && f.origin.features[0] == g.origin.features[1] &&
                       f.origin.features[1] == g.origin.features[0];
            });
            RC_ASSERT(matched);
        }
    });
}

TEST_CASE("swapping two boxes with the same centre still flips the normal, for face and edge contacts") {
    // Regression: with no centre-to-centre direction, an edge axis's sign flipped twice under a swap.
    check_property("box-box swap, same centre", [] {
        const Vec3 centre = any_vector(1.0);
        const Placement a = at(centre, any_orientation());
        const Placement b = at(centre, any_orientation());
        const Box ba{Vec3(*in_range(0.05, 1.0), *in_range(0.05, 0.2), *in_range(0.05, 0.2))};
        const Box bb{Vec3(*in_range(0.05, 1.0), *in_range(0.05, 0.2), *in_range(0.05, 0.2))};
        std::vector<Contact> forward, backward;
        box_and_box(ba, a, 0, bb, b, 1, forward);
        box_and_box(bb, b, 1, ba, a, 0, backward);
        RC_ASSERT(!forward.empty());
        RC_ASSERT(forward.size() == backward.size());
        RC_ASSERT((forward[0].normal + backward[0].normal).norm() < 1e-9);
    });
}

TEST_CASE("overlapping boxes always touch, and no contact is deeper than the boxes overlap along its normal") {
    check_property("box-box contacts are sound", [] {
        const Placement a = at(any_vector(0.6), any_orientation());
        const Placement b = at(any_vector(0.6), any_orientation());
        const Box ba{Vec3(*in_range(0.1, 0.6), *in_range(0.1, 0.6), *in_range(0.1, 0.6))};
        const Box bb{Vec3(*in_range(0.1, 0.6), *in_range(0.1, 0.6), *in_range(0.1, 0.6))};
        std::vector<Contact> out;
        box_and_box(ba, a, 0, bb, b, 1, out);
        RC_ASSERT(out.size() <= 4);
        // One box's centre inside the other: they certainly overlap.
        const auto inside = [](const Vec3& point, const Placement& p, const Box& box) {
            return ((p.rotation.transpose() * (point - p.position)).cwiseAbs() - box.half_size).maxCoeff() < 0.0;
        };
        if (inside(a.position, b, bb) || inside(b.position, a, ba)) RC_ASSERT(!out.empty());
        const auto radius = [](const Placement& p, const Box& box, const Vec3& n) {
            return (p.rotation.transpose() * n).cwiseAbs().dot(box.half_size);
        };
        for (const Contact& c : out) {
            RC_ASSERT(std::abs(c.normal.norm() - 1.0) < 1e-12);
            RC_ASSERT(c.normal.dot(a.position - b.position) >= -1e-12);  // from body 1 towards body 0
            // Along its normal the boxes overlap by r_a + r_b - |between . n|; no point is deeper than that.
            const double overlap =
                radius(a, ba, c.normal) + radius(b, bb, c.normal) - std::abs((a.position - b.position).dot(c.normal));
            RC_ASSERT(c.penetration >= 0.0);
            RC_ASSERT(c.penetration <= overlap + 1e-9);
            // The point is inside (or on) both boxes grown by half the depth.
            for (const auto& [p, box] : {std::pair{&a, ba}, std::pair{&b, bb}}) {
                const Vec3 local = p->rotation.transpose() * (c.point - p->position);
                RC_ASSERT((local.cwiseAbs() - box.half_size).maxCoeff() <= 0.5 * c.penetration + 1e-9);
            }
        }
    });
}

TEST_CASE("the screened separating-axis test gives the contacts of the test on every axis, to the bit") {
    // Random pairs, near touching as well as deep and apart, and pairs turned to within a rounding of a face or an
    // edge being parallel: where the screen's estimates and the exact overlaps are closest to deciding otherwise.
    check_property(
        "box_and_box == box_and_box_every_axis",
        [] {
            const double spread = *in_range(0.05, 1.2);
            Placement a = at(any_vector(spread), any_orientation());
            Placement b = at(any_vector(spread), any_orientation());
            const Box ba{Vec3(*in_range(0.1, 0.6), *in_range(0.1, 0.6), *in_range(0.1, 0.6))};
            Box bb{Vec3(*in_range(0.1, 0.6), *in_range(0.1, 0.6), *in_range(0.1, 0.6))};
            const int kind = *rc::gen::inRange(0, 3);
            if (kind == 1) {
                // b turned from a by a tiny angle about one of a's axes: faces and edges all but parallel.
                const double tiny = std::pow(10.0, -*in_range(3.0, 12.0));
                b.rotation =
                    a.rotation * Eigen::AngleAxisd(tiny, Vec3::Unit(*rc::gen::inRange(0, 3))).toRotationMatrix();
            } else if (kind == 2) {
                // A stack: the same box, turned as a, resting on it or sunk a little, offset along one face. Faces of
                // both boxes overlap equally: the tie the body order breaks.
                bb = ba;
                b.rotation = a.rotation;
                const int up = *rc::gen::inRange(0, 3);
                b.position = a.position + a.rotation.col(up) * (2.0 * ba.half_size[up] - *in_range(0.0, 0.01)) +
                             a.rotation.col((up + 1) % 3) * *in_range(-0.1, 0.1);
            }
            for (const auto& [first, second] : {std::pair{0, 1}, std::pair{1, 0}}) {
                std::vector<Contact> screened, every_axis;
                box_and_box(ba, a, first, bb, b, second, screened);
                box_and_box_every_axis(ba, a, first, bb, b, second, every_axis);
                RC_ASSERT(screened.size() == every_axis.size());
                for (std::size_t k = 0; k < screened.size(); ++k) {
                    RC_ASSERT(screened[k].normal == every_axis[k].normal);
                    RC_ASSERT(screened[k].point == every_axis[k].point);
                    RC_ASSERT(screened[k].penetration == every_axis[k].penetration);
                    RC_ASSERT(screened[k].origin == every_axis[k].origin);
                }
            }
        },
        10000);
}
