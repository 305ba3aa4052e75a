#pragma once
// Contact recycling (Box3D, Catto 2026: physics_world.c's collide task, "inspired by persistent contact manifolds
// ... but allows larger relative motion and has fewer tuning parameters"). A pair's contacts, as its pair test
// found them, are kept from frame to frame while the pair has moved little since: the normal, the features (so
// the contact memory's keys, and warm starting, find them again) and each body's own anchor, the contact point
// relative to that body's centre when it was detected (a_i = q - x_i, world axes). A kept contact's penetration
// is found again from the anchors, as soft step finds it between sub-steps (Box3D: "keep anchors but update
// separation, same as sub-stepping; this eliminates jitter"):
//   q_i = x_i + R_i a_i                  each body's anchor now, R_i its turn since detection;
//   p   = p_detected - n . (q_0 - q_1)   (q_0 = q_1 when detected, so p changes only as the anchors part).
// The solver pushes each body at x_i + a_i: its anchor carried by the body's move, in the axes it was detected
// in (Box3D's manifold anchors are the solver's lever arms unchanged; the soft step keeps its lever arms within a
// frame the same way). Measured on stack_20 (soft step, N = 4 and 8): lever arms turned with the bodies,
// x_i + R_i a_i, collapse the stack at 5.45 s; kept as detected, it stands (docs/bench.md).
// A stack whose pair test would pick a slightly different face or clip a slightly different polygon each frame
// (the normal tilting, points appearing and vanishing as a box rocks) keeps one manifold instead, and the solver
// converges on it over frames; with recycling off, Box3D's stack_20, box_stack_40 and mass_ratio_1000 collapse
// as ours do (docs/bench.md).
//
// When a pair may be kept (Box3D's test, a conservative advancement): neither body turned more than `angle` since
// detection, and the relative move d of body 1 in body 0's frame (the world's frame for the ground) with the turn's
// arc at the shapes' reach stays within the distance,
//   d + 2 |sin(theta_r / 2)| max(reach_0, reach_1) < distance,
// theta_r the relative turn and reach a shape's bounding radius. Past it the pair is tested afresh and what the
// test finds is kept instead. A kept pair whose bounds no longer overlap is still recycled while it may be: its
// points have separated (p < 0), which the soft step treats as speculative.
//
// Detection hands the pairs in increasing order, the ground's first (body order), then the pairs (i, j); the
// kept pairs are held in that order, so one cursor walks them beside the detection and a frame's recycling is a
// merge, with no lookup.
//
// A kept pair's contacts do not change while it is recycled, so they stay where they were stored: a frame's list of
// kept pairs points into one store of kept contacts, and only a pair tested afresh adds to it. (Copied into a new
// list every frame, the large pyramid's 59,800 kept contacts were 11 MB moved a frame and the second frame's list
// grew from empty.) The store is compacted when what no pair points to any more outweighs what they do.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "settings/settings.hpp"
#include "shapes/shape.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

// A pair as detection hands it: bodies (a, b), a < b, or (a, world_body) for the ground.
struct BodyPair {
    int a = 0;
    int b = world_body;

    bool operator==(const BodyPair&) const = default;
};

class ContactRecycling {
public:
    // Starts a frame's detection over the bodies where they are now (`shapes` beside them).
    void begin_frame(const RecyclingSettings& settings, std::span<const RigidBody> bodies,
                     std::span<const std::optional<Shape>> shapes);

    // Pair `pair`, about to be tested (pairs come in detection's order): when it was kept and may still be,
    // appends its kept contacts brought up to date to `out` and returns true (the pair test is skipped). Kept pairs
    // before it that detection did not hand this frame are recycled (or forgotten) first.
    bool recycle(BodyPair pair, std::vector<Contact>& out);

    // The contacts the pair test just found for `pair` (none: nothing is kept), with the bodies where they are now.
    void keep(BodyPair pair, std::span<const Contact> found);

    // Ends the frame's detection: the kept pairs after the last one handed are recycled or forgotten, and what this
    // frame kept is what the next one may recycle.
    void end_frame(std::vector<Contact>& out);

    // About `pairs` pairs with `contacts` contacts to be handed this frame. When nothing is kept yet (the first
    // frame, which keeps every pair it tests), the lists make room for them at once instead of regrowing, copying,
    // as they fill; otherwise they already have the room. A hint: it changes nothing kept.
    void expect(std::size_t pairs, std::size_t contacts);

    void clear();  // nothing kept: the next frame detects every pair afresh

    int recycled_pairs() const { return recycled_pairs_; }  // this frame's, so far
    std::size_t kept_pairs() const { return last_.size(); }

private:
    // A body's pose (the world's: the identity).
    struct Pose {
        Vec3 position = Vec3::Zero();
        Quat orientation = Quat::Identity();
    };
    // A contact as detected, but for its point q, which the anchors hold (the world's anchor, x = 0, is q itself).
    struct KeptContact {
        std::array<int, 2> bodies{};
        Vec3 normal;
        double penetration = 0.0;  // when detected
        double restitution = 0.0;
        double friction = 0.0;
        ContactOrigin origin{};
        std::array<Vec3, 2> anchor{};  // a_i = q - x_i per body of `bodies`, world axes when detected
    };
    struct KeptPair {
        BodyPair pair;
        std::array<Quat, 2> orientation;  // of pair.a and pair.b when detected
        // What may_keep compares every frame, made once when the pair is kept: body 1 seen from body 0 when detected
        // (their relative pose) and the farther of the two shapes' reach.
        Pose relative;
        double reach = 0.0;
        std::uint32_t first = 0;  // its contacts in `contacts_`
        std::uint32_t count = 0;
    };

    Pose pose_of(int body) const;
    double reach_of(int body) const;
    Pose relative_pose(const KeptPair& kept, const std::array<Pose, 2>& pose) const;
    bool may_keep(const KeptPair& kept) const;
    // When it may be kept: put in what this frame keeps (its contacts and poses those of its detection, left where
    // they are) and its contacts, brought up to date, appended to `out`.
    bool recycle_if_may(const KeptPair& kept, std::vector<Contact>& out);
    void append_recycled(const KeptPair& kept, std::vector<Contact>& out) const;
    // Kept pairs before `pair` (all of them: nullopt) that detection did not hand: recycled while they may be.
    void pass_before(const std::optional<BodyPair>& pair, std::vector<Contact>& out);
    void compact();

    RecyclingSettings settings_;
    std::span<const RigidBody> bodies_;
    std::span<const std::optional<Shape>> shapes_;
    double cos_squared_half_angle_ = 1.0;  // the angle test as Box3D makes it, on q . q_detected
    std::vector<KeptContact> contacts_;    // every kept pair's contacts, and those no pair points to any more
    std::vector<KeptContact> compacted_;   // compact()'s destination, its room kept
    std::size_t next_contacts_ = 0;        // how many contacts next_'s pairs point to
    std::vector<KeptPair> last_;           // what the last frame kept, in detection's order: this frame may recycle it
    std::vector<KeptPair> next_;           // what this frame keeps
    std::size_t cursor_ = 0;               // the first of last_ not yet passed
    int recycled_pairs_ = 0;
};

}  // namespace impulse
