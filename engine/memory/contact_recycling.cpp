#include "memory/contact_recycling.hpp"

#include <algorithm>
#include <cassert>
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
    next_contacts_ = 0;
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

ContactRecycling::Pose ContactRecycling::relative_pose(const KeptPair& kept, const std::array<Pose, 2>& pose) const {
    // Body 1 seen from body 0 (from the world for the ground, so a body turning about its own centre does not swing
    // the world's origin round with it).
    const int frame = kept.pair.b == world_body ? 1 : 0;
    const Quat to_frame = pose[frame].orientation.conjugate();
    return {to_frame * (pose[1 - frame].position - pose[frame].position), to_frame * pose[1 - frame].orientation};
}

bool ContactRecycling::may_keep(const KeptPair& kept) const {
    const std::array<Pose, 2> now{pose_of(kept.pair.a), pose_of(kept.pair.b)};
    // Neither body turned more than the angle since detection: q . q_detected = cos(theta / 2), squared for the
    // double cover (q and -q are one turn).
    for (int i = 0; i < 2; ++i) {
        const double cos_half = now[i].orientation.dot(kept.orientation[i]);
        if (!(cos_half * cos_half > cos_squared_half_angle_)) return false;
    }
    const Pose& then = kept.relative;
    const Pose at = relative_pose(kept, now);
    const double moved = (at.position - then.position).norm();
    if (!(moved < settings_.distance)) return false;
    // The relative turn's arc at the farthest a shape reaches: 2 |sin(theta_r / 2)| reach, within what is left.
    const Quat turn = then.orientation.conjugate() * at.orientation;
    const double arc = 2.0 * turn.vec().norm() * kept.reach;
    return arc < settings_.distance - moved;
}

void ContactRecycling::append_recycled(const KeptPair& kept, std::vector<Contact>& out) const {
    // Each body's move and turn since detection (the world's: none).
    std::array<Vec3, 2> position{Vec3::Zero(), Vec3::Zero()};
    std::array<Mat3, 2> turn{Mat3::Identity(), Mat3::Identity()};
    const std::array<int, 2> ids{kept.pair.a, kept.pair.b};
    for (int i = 0; i < 2; ++i) {
        if (ids[i] == world_body) continue;
        const RigidBody& body = bodies_[static_cast<std::size_t>(ids[i])];
        position[i] = body.position;
        turn[i] = (body.orientation * kept.orientation[i].conjugate()).toRotationMatrix();
    }
    const auto slot_of = [&ids](int body) { return body == ids[0] ? 0 : 1; };
    for (std::uint32_t k = kept.first; k < kept.first + kept.count; ++k) {
        const KeptContact& kc = contacts_[k];
        // Per body: where its anchor is now, x_i + R_i a_i, for the penetration, and the point the solver pushes
        // at, x_i + a_i: the anchor carried by the body's move but kept in the axes it was detected in (Box3D's
        // anchors are the solver's lever arms unchanged, as within a step). The world's anchor is the point itself.
        std::array<Vec3, 2> anchor_now{kc.anchor};
        std::array<Vec3, 2> pushed_at{kc.anchor};
        for (int s = 0; s < 2; ++s) {
            if (kc.bodies[s] == world_body) continue;
            const int i = slot_of(kc.bodies[s]);
            anchor_now[s] = position[i] + turn[i] * kc.anchor[s];
            pushed_at[s] = position[i] + kc.anchor[s];
        }
        // Made whole in place (not made empty and then assigned: 60,000 contacts a frame on the large pyramid).
        out.push_back({.bodies = kc.bodies,
                       .point = pushed_at[0],
                       .normal = kc.normal,
                       // p = p_detected - n . (q_0 - q_1): the anchors coincided when detected.
                       .penetration = kc.penetration - kc.normal.dot(anchor_now[0] - anchor_now[1]),
                       .restitution = kc.restitution,
                       .friction = kc.friction,
                       .origin = kc.origin,
                       .body1_point = kc.bodies[1] != world_body ? std::optional(pushed_at[1]) : std::nullopt});
    }
}

void ContactRecycling::pass_before(const std::optional<BodyPair>& pair, std::vector<Contact>& out) {
    while (cursor_ < last_.size() && (!pair || comes_before(last_[cursor_].pair, *pair))) {
        const KeptPair& kept = last_[cursor_++];
        // Not handed this frame (their bounds apart): kept while they may be, their points now apart (p < 0).
        recycle_if_may(kept, out);
    }
}

bool ContactRecycling::recycle_if_may(const KeptPair& kept, std::vector<Contact>& out) {
    if (!may_keep(kept)) return false;
    next_.push_back(kept);  // its contacts stay where they are in the store
    next_contacts_ += kept.count;
    append_recycled(kept, out);
    ++recycled_pairs_;
    return true;
}

bool ContactRecycling::recycle(BodyPair pair, std::vector<Contact>& out) {
    pass_before(pair, out);
    if (cursor_ == last_.size() || !(last_[cursor_].pair == pair)) return false;
    // Moved too far: tested afresh, and what the test finds is kept instead.
    return recycle_if_may(last_[cursor_++], out);
}

void ContactRecycling::keep(BodyPair pair, std::span<const Contact> found) {
    if (found.empty()) return;
    KeptPair& kept = next_.emplace_back();
    kept.pair = pair;
    const std::array<Pose, 2> pose{pose_of(pair.a), pose_of(pair.b)};
    kept.orientation = {pose[0].orientation, pose[1].orientation};
    kept.relative = relative_pose(kept, pose);
    kept.reach = std::max(reach_of(pair.a), reach_of(pair.b));
    kept.first = static_cast<std::uint32_t>(contacts_.size());
    kept.count = static_cast<std::uint32_t>(found.size());
    next_contacts_ += found.size();
    for (const Contact& c : found) {
        assert(!c.body1_point);  // a contact a pair test found: both bodies touched at q
        contacts_.push_back(
            {.bodies = c.bodies,
             .normal = c.normal,
             .penetration = c.penetration,
             .restitution = c.restitution,
             .friction = c.friction,
             .origin = c.origin,
             // a_i = q - x_i (the world's: q - 0 = q, exactly)
             .anchor = {c.point - pose_of(c.bodies[0]).position, c.point - pose_of(c.bodies[1]).position}});
    }
}

void ContactRecycling::end_frame(std::vector<Contact>& out) {
    pass_before(std::nullopt, out);
    std::swap(last_, next_);
    next_.clear();
    // Pairs tested afresh leave their old contacts behind in the store: once those are as many as the kept ones,
    // copying the kept ones out (once) costs less than carrying the rest on.
    if (contacts_.size() > 2 * next_contacts_) compact();
    next_contacts_ = 0;
}

void ContactRecycling::compact() {
    compacted_.clear();
    for (KeptPair& kept : last_) {
        const auto from = contacts_.begin() + kept.first;
        kept.first = static_cast<std::uint32_t>(compacted_.size());
        compacted_.insert(compacted_.end(), from, from + kept.count);
    }
    std::swap(contacts_, compacted_);
}

void ContactRecycling::expect(std::size_t pairs, std::size_t contacts) {
    if (!last_.empty()) return;  // the lists have grown to what the frames keep
    next_.reserve(next_.size() + pairs);
    last_.reserve(next_.capacity());  // the next frame's list, once this one's is swapped in
    contacts_.reserve(contacts_.size() + contacts);
}

void ContactRecycling::clear() {
    last_.clear();
    next_.clear();
    contacts_.clear();
    next_contacts_ = 0;
    cursor_ = 0;
}

}  // namespace impulse
