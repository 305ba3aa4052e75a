#include "memory/contact_recycling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace impulse {

namespace {

// Detection's order: the ground's pairs first, by body, then the pairs (a, b) by a, then b.
bool comes_before(const BodyPair& x, const BodyPair& y) {
    return std::tuple(x.b != world_body, x.a, x.b) < std::tuple(y.b != world_body, y.a, y.b);
}

}  // namespace

void ContactRecycling::begin_frame(const RecyclingSettings& settings, std::span<const RigidBody> bodies,
                                   std::span<const std::optional<Shape>> shapes) {
    settings_ = settings;
    bodies_ = bodies;
    shapes_ = shapes;
    const double half_angle = 0.5 * settings.angle * std::numbers::pi / 180.0;
    cos_squared_half_angle_ = std::cos(half_angle) * std::cos(half_angle);
    next_.clear();
    cursor_ = 0;
    recycled_pairs_ = 0;
}

ContactRecycling::Pose ContactRecycling::pose_of(int body) const {
    if (body == world_body) return {};
    const RigidBody& b = bodies_[static_cast<std::size_t>(body)];
    return {b.position, b.orientation};
}

double ContactRecycling::reach_of(int body) const {
    if (body == world_body) return 0.0;
    const std::optional<Shape>& shape = shapes_[static_cast<std::size_t>(body)];
    return shape ? bounding_radius(*shape) : 0.0;
}

bool ContactRecycling::may_keep(const KeptPair& kept) const {
    const std::array<Pose, 2> now{pose_of(kept.pair.a), pose_of(kept.pair.b)};
    // Neither body turned more than the angle since detection: q . q_detected = cos(theta / 2), squared for the
    // double cover (q and -q are one turn).
    for (int i = 0; i < 2; ++i) {
        const double cos_half = now[i].orientation.dot(kept.pose[i].orientation);
        if (!(cos_half * cos_half > cos_squared_half_angle_)) return false;
    }
    // The pair's relative pose, body 1 seen from body 0 (from the world for the ground, so a body turning about its
    // own centre does not swing the world's origin round with it).
    const int frame = kept.pair.b == world_body ? 1 : 0;
    const auto relative = [frame](const std::array<Pose, 2>& pose) {
        const Quat to_frame = pose[frame].orientation.conjugate();
        return Pose{to_frame * (pose[1 - frame].position - pose[frame].position),
                    to_frame * pose[1 - frame].orientation};
    };
    const Pose then = relative(kept.pose), at = relative(now);
    const double moved = (at.position - then.position).norm();
    if (!(moved < settings_.distance)) return false;
    // The relative turn's arc at the farthest a shape reaches: 2 |sin(theta_r / 2)| reach, within what is left.
    const Quat turn = then.orientation.conjugate() * at.orientation;
    const double arc = 2.0 * turn.vec().norm() * std::max(reach_of(kept.pair.a), reach_of(kept.pair.b));
    return arc < settings_.distance - moved;
}

void ContactRecycling::append_recycled(const KeptPair& kept, std::vector<Contact>& out) {
    // Each body's move and turn since detection (the world's: none).
    std::array<Vec3, 2> position{Vec3::Zero(), Vec3::Zero()};
    std::array<Mat3, 2> turn{Mat3::Identity(), Mat3::Identity()};
    const std::array<int, 2> ids{kept.pair.a, kept.pair.b};
    for (int i = 0; i < 2; ++i) {
        if (ids[i] == world_body) continue;
        const Pose now = pose_of(ids[i]);
        position[i] = now.position;
        turn[i] = (now.orientation * kept.pose[i].orientation.conjugate()).toRotationMatrix();
    }
    const auto slot_of = [&ids](int body) { return body == ids[0] ? 0 : 1; };
    for (std::uint32_t k = kept.first; k < kept.first + kept.count; ++k) {
        const KeptContact& kc = next_.contacts[k];
        Contact c = kc.contact;
        // Per body: where its anchor is now, x_i + R_i a_i, for the penetration, and the point the solver pushes
        // at, x_i + a_i: the anchor carried by the body's move but kept in the axes it was detected in (Box3D's
        // anchors are the solver's lever arms unchanged, as within a step). The world's anchor is the point itself.
        std::array<Vec3, 2> anchor_now{c.point, c.point};
        std::array<Vec3, 2> pushed_at{c.point, c.point};
        for (int s = 0; s < 2; ++s) {
            if (c.bodies[s] == world_body) continue;
            const int i = slot_of(c.bodies[s]);
            anchor_now[s] = position[i] + turn[i] * kc.anchor[s];
            pushed_at[s] = position[i] + kc.anchor[s];
        }
        // p = p_detected - n . (q_0 - q_1): the anchors coincided when detected.
        c.penetration = kc.contact.penetration - c.normal.dot(anchor_now[0] - anchor_now[1]);
        c.point = pushed_at[0];
        if (c.bodies[1] != world_body) c.body1_point = pushed_at[1];
        out.push_back(c);
    }
}

void ContactRecycling::pass_before(const std::optional<BodyPair>& pair, std::vector<Contact>& out) {
    while (cursor_ < last_.pairs.size() && (!pair || comes_before(last_.pairs[cursor_].pair, *pair))) {
        const KeptPair& kept = last_.pairs[cursor_++];
        // Not handed this frame (their bounds apart): kept while they may be, their points now apart (p < 0).
        recycle_if_may(kept, out);
    }
}

bool ContactRecycling::recycle_if_may(const KeptPair& kept, std::vector<Contact>& out) {
    if (!may_keep(kept)) return false;
    KeptPair& copy = next_.pairs.emplace_back(kept);
    copy.first = static_cast<std::uint32_t>(next_.contacts.size());
    next_.contacts.insert(next_.contacts.end(), last_.contacts.begin() + kept.first,
                          last_.contacts.begin() + kept.first + kept.count);
    append_recycled(copy, out);
    ++recycled_pairs_;
    return true;
}

bool ContactRecycling::recycle(BodyPair pair, std::vector<Contact>& out) {
    pass_before(pair, out);
    if (cursor_ == last_.pairs.size() || !(last_.pairs[cursor_].pair == pair)) return false;
    // Moved too far: tested afresh, and what the test finds is kept instead.
    return recycle_if_may(last_.pairs[cursor_++], out);
}

void ContactRecycling::keep(BodyPair pair, std::span<const Contact> found) {
    if (found.empty()) return;
    KeptPair& kept = next_.pairs.emplace_back();
    kept.pair = pair;
    kept.pose = {pose_of(pair.a), pose_of(pair.b)};
    kept.first = static_cast<std::uint32_t>(next_.contacts.size());
    kept.count = static_cast<std::uint32_t>(found.size());
    for (const Contact& c : found) {
        KeptContact& k = next_.contacts.emplace_back();
        k.contact = c;
        for (int s = 0; s < 2; ++s) k.anchor[s] = c.point - pose_of(c.bodies[s]).position;  // a_i = q - x_i
    }
}

void ContactRecycling::end_frame(std::vector<Contact>& out) {
    pass_before(std::nullopt, out);
    std::swap(last_, next_);
    next_.clear();
}

void ContactRecycling::clear() {
    last_.clear();
    next_.clear();
    cursor_ = 0;
}

}  // namespace impulse
