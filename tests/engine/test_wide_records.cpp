// Soft step's wide records (methods/wide_records.hpp, soft_step.order = wide): four pairs of a colour side by side,
// one in each lane, give each pair the numbers it gets alone, and keeping the visits for the recorder changes none.
// (The preset soft_step_wide runs in every test that takes each preset: recorded and unrecorded runs bit for bit,
// the textbook checks, the browser's traces.)

#include "methods/graph_colouring.hpp"
#include "methods/soft_step.hpp"
#include "methods/wide_records.hpp"
#include "support/frame_rows.hpp"
#include "support/simulate.hpp"

#include <doctest/doctest.h>

#include <array>
#include <memory_resource>
#include <vector>

using namespace impulse;

namespace {

struct WideOutcome {
    std::vector<Axes> totals;
    std::vector<double> most_pushed;
    std::vector<Vec3> world;  // g = C lambda, as the memory keeps it
    std::vector<SolverBody> bodies;
    std::vector<WideVisit> kept;  // the last sweep's visits, when kept
};

std::vector<std::array<int, 2>> pairs_of(const test::FrameRows& frame) {
    std::vector<std::array<int, 2>> pair;
    for (const ContactRow& row : frame.rows) pair.push_back(row.body);
    return pair;
}

// The records of the frame's rows (in colour order, with their `colour`), each row placed as soft step places it.
// (Made where they are kept: the records own their points' storage, once.)
struct PlacedRecords {
    WideRecords records;
    PlacedRecords(const test::FrameRows& frame, std::span<const int> colour, const WideSoftness& softness)
        : records(colour, pairs_of(frame), frame.bodies, softness, std::pmr::new_delete_resource()) {
        for (std::size_t r = 0; r < frame.rows.size(); ++r) records.place(r, frame.rows[r], frame.penetration[r]);
        records.prepare();
    }
};

// One sub-step as soft step runs it: warm start, a solve sweep, the bodies moved (by their velocities over h, turned
// about a fixed axis), a relax sweep that finds p and one that does not.
WideOutcome wide_substep(const test::FrameRows& frame, std::span<const int> colour, const WideSoftness& softness,
                         double h, bool keeping) {
    PlacedRecords placed(frame, colour, softness);
    WideRecords& records = placed.records;
    WideOutcome out;
    out.bodies = frame.bodies;
    out.kept.resize(frame.rows.size());
    WideVisit* const kept = keeping ? out.kept.data() : nullptr;
    records.load(out.bodies);
    records.warm_start(kept);
    records.sweep<true, false>(kept);
    records.store(out.bodies);
    for (std::size_t b = 0; b < out.bodies.size(); ++b)
        records.track(b, out.bodies[b].velocity * h, Mat3(Eigen::AngleAxisd(0.01 * double(b % 3), Vec3::UnitY())));
    records.sweep<false, true>(kept);
    records.sweep<false, false>(kept);
    records.store(out.bodies);
    out.totals.assign(frame.rows.size(), Axes{});
    out.most_pushed.assign(frame.rows.size(), 0.0);
    out.world.assign(frame.rows.size(), Vec3::Zero());
    records.totals(out.totals, out.most_pushed, out.world);
    return out;
}

bool same_axes(const Axes& a, const Axes& b) {
    return a.n == b.n && a.t1 == b.t1 && a.t2 == b.t2;
}

// pyramid_20's rows at frame 30 in colour order, as soft step places them, with each row's colour, and the colours
// that give each pair a record of its own (`alone`).
struct ColouredRows {
    Scene scene = test::shipped_under("pyramid_20", "soft_step_wide");
    test::FrameRows frame;
    std::vector<int> colour, alone;
    double h = scene.settings.duration / scene.settings.soft_step.substeps;
    WideSoftness softness{soft_step_softness(scene.settings), scene.settings.soft_step.max_push_velocity, h};

    ColouredRows() {
        const test::FrameRows detected = test::frame_rows(scene, 30);
        std::vector<std::array<int, 2>> pairs;
        for (const ContactRow& row : detected.rows) pairs.push_back(row.body);
        const std::pmr::vector<int> colours = pair_colours(pairs, detected.bodies, std::pmr::new_delete_resource());
        const std::pmr::vector<std::uint32_t> slots = slots_of_colours(colours, std::pmr::new_delete_resource());
        frame = detected;
        colour.resize(detected.rows.size());
        for (std::size_t k = 0; k < slots.size(); ++k) {
            frame.rows[slots[k]] = detected.rows[k];
            frame.penetration[slots[k]] = detected.penetration[k];
            colour[slots[k]] = colours[k];
        }
        alone.resize(colour.size());
        for (std::size_t r = 1; r < alone.size(); ++r)
            alone[r] = alone[r - 1] + (frame.rows[r].body != frame.rows[r - 1].body || colour[r] != colour[r - 1]);
    }
    std::size_t pair_count() const { return static_cast<std::size_t>(alone.back() + 1); }
};

}  // namespace

TEST_CASE("a pair gets the same numbers in a wide record of four pairs as in one of its own, kept or not") {
    const ColouredRows coloured;
    const test::FrameRows& frame = coloured.frame;
    const std::vector<int>& colour = coloured.colour;
    const std::vector<int>& alone = coloured.alone;
    const WideSoftness& softness = coloured.softness;
    const double h = coloured.h;
    REQUIRE(frame.rows.size() > 100);
    for (const int c : colour) REQUIRE(c >= 0);  // no overflow: every pair could share a record
    const std::size_t pair_count = coloured.pair_count();
    CHECK(PlacedRecords(frame, colour, softness).records.record_count() < pair_count / 3);
    CHECK(PlacedRecords(frame, alone, softness).records.record_count() == pair_count);

    const WideOutcome four = wide_substep(frame, colour, softness, h, false);
    const WideOutcome one = wide_substep(frame, alone, softness, h, false);
    const WideOutcome kept = wide_substep(frame, colour, softness, h, true);
    std::size_t pushing = 0, sliding = 0;
    for (std::size_t r = 0; r < frame.rows.size(); ++r) {
        CAPTURE(r);
        CHECK(same_axes(four.totals[r], one.totals[r]));
        CHECK(four.most_pushed[r] == one.most_pushed[r]);
        CHECK(four.world[r] == one.world[r]);
        CHECK(four.world[r] == kept.world[r]);
        // The lanes' g is the rows' C lambda (world_impulse, in doubles) to single precision.
        const Vec3 g = world_impulse(frame.rows[r], four.totals[r]);
        CHECK((four.world[r] - g).norm() <= 1e-6 * std::max(1.0, g.norm()));
        CHECK(same_axes(four.totals[r], kept.totals[r]));
        // The visit kept is the last one: its total after is the row's.
        CHECK(same_axes(kept.kept[r].visit.after, kept.totals[r]));
        pushing += four.totals[r].n > 0.0;
        sliding += kept.kept[r].visit.sliding;
    }
    for (std::size_t b = 0; b < frame.bodies.size(); ++b) {
        CAPTURE(b);
        CHECK(four.bodies[b].velocity == one.bodies[b].velocity);
        CHECK(four.bodies[b].angular_velocity == one.bodies[b].angular_velocity);
        CHECK(four.bodies[b].velocity == kept.bodies[b].velocity);
        CHECK(four.bodies[b].angular_velocity == kept.bodies[b].angular_velocity);
    }
    // The rows did something: most push, and the turn made some slide (the projection's lanes stepped).
    CHECK(pushing > frame.rows.size() / 2);
    CHECK(sliding > frame.rows.size() / 10);
    MESSAGE("rows ", frame.rows.size(), ", pairs ", pair_count, ", pushing ", pushing, ", sliding ", sliding);
}

TEST_CASE("a record keeps its pairs' basis once where their points share one, and each point's where they do not") {
    const ColouredRows coloured;
    const WideSoftness& softness = coloured.softness;
    // A box on a box or the ground touches at a face's points, which share the face's normal and so its basis.
    const PlacedRecords shared(coloured.frame, coloured.colour, softness);
    CHECK(shared.records.basis_count() == shared.records.record_count());
    // Every point after a pair's first with its tangents turned about the normal (a basis as good, not the same):
    // each point quad then keeps its own, and a pair still gets in a record of four what it gets alone.
    test::FrameRows turned = coloured.frame;
    for (std::size_t r = 1; r < turned.rows.size(); ++r) {
        if (turned.rows[r].body != turned.rows[r - 1].body) continue;
        Mat3& basis = turned.rows[r].basis;
        const Mat3 turn(Eigen::AngleAxisd(0.3, basis.col(0)));
        basis.col(1) = turn * basis.col(1);
        basis.col(2) = turn * basis.col(2);
    }
    const PlacedRecords own(turned, coloured.colour, softness);
    CHECK(own.records.basis_count() > 3 * own.records.record_count());
    const WideOutcome four = wide_substep(turned, coloured.colour, softness, coloured.h, false);
    const WideOutcome one = wide_substep(turned, coloured.alone, softness, coloured.h, false);
    const WideOutcome before = wide_substep(coloured.frame, coloured.colour, softness, coloured.h, false);
    std::size_t moved = 0;
    for (std::size_t r = 0; r < turned.rows.size(); ++r) {
        CAPTURE(r);
        CHECK(same_axes(four.totals[r], one.totals[r]));
        CHECK(four.world[r] == one.world[r]);
        // Each point's own basis was read: the totals in turned tangents are other numbers.
        moved += !same_axes(four.totals[r], before.totals[r]);
    }
    for (std::size_t b = 0; b < turned.bodies.size(); ++b) {
        CAPTURE(b);
        CHECK(four.bodies[b].velocity == one.bodies[b].velocity);
        CHECK(four.bodies[b].angular_velocity == one.bodies[b].angular_velocity);
    }
    CHECK(moved > turned.rows.size() / 2);
}

namespace {

// Lane `lane` of four contacts' lanes, from a double.
void set_lane(Float4& to, int lane, double value) {
    to[lane] = static_cast<float>(value);
}

// K's friction entries of up to four rows over four floats, as a wide record's prepare finds them from what was
// placed: the anchors, the basis, and each body's inverse mass and world inverse inertia (zero for the world).
FrictionMatrixOf<Float4> lanes_friction_matrix(std::span<const ContactRow> rows, std::span<const SolverBody> bodies) {
    Vec3x4 anchor[2]{};
    Mat3x4 basis{};
    Float4 inverse_mass[2]{};
    SymmetricMat3x4 inverse_inertia[2]{};
    for (int lane = 0; lane < static_cast<int>(rows.size()); ++lane) {
        const ContactRow& row = rows[static_cast<std::size_t>(lane)];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) set_lane(basis.column[j].v[i], lane, row.basis(i, j));
        for (int side = 0; side < 2; ++side) {
            if (row.body[side] < 0) continue;
            const MassProperties& mass = bodies[static_cast<std::size_t>(row.body[side])].mass;
            for (int i = 0; i < 3; ++i) set_lane(anchor[side].v[i], lane, row.anchor[side][i]);
            set_lane(inverse_mass[side], lane, mass.inverse_mass);
            const Mat3& m = mass.inverse_inertia_world;
            const double e[6] = {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
            for (int k = 0; k < 6; ++k) set_lane(inverse_inertia[side].e[k], lane, e[k]);
        }
    }
    const Mat3x4 body_0 = world_delta_velocity_matrix_of<Mat3x4>(anchor[0], inverse_inertia[0], inverse_mass[0]);
    const Mat3x4 body_1 = world_delta_velocity_matrix_of<Mat3x4>(anchor[1], inverse_inertia[1], inverse_mass[1]);
    return friction_matrix<Float4>(delta_velocity_matrix_of<Mat3x4, Float4>(basis, body_0, &body_1));
}

}  // namespace

TEST_CASE("a wide record's K over four floats is the rows' K in doubles to single precision, lane by lane") {
    const Scene scene = test::shipped_under("pyramid_20", "soft_step_wide");
    const test::FrameRows frame = test::frame_rows(scene, 30);
    REQUIRE(frame.rows.size() > 100);
    std::size_t compared = 0;
    for (std::size_t first = 0; first + 4 <= frame.rows.size(); first += 4) {
        const std::span<const ContactRow> four(frame.rows.data() + first, 4);
        const FrictionMatrixOf<Float4> f = lanes_friction_matrix(four, frame.bodies);
        for (int lane = 0; lane < 4; ++lane) {
            const ContactRow& row = four[static_cast<std::size_t>(lane)];
            CAPTURE(first + static_cast<std::size_t>(lane));
            REQUIRE(row.tangent_invertible);
            CHECK(f.tangent_invertible[lane] != 0);
            const double size = std::max(std::abs(row.tangent_response[0]), std::abs(row.tangent_response[2]));
            for (int k = 0; k < 2; ++k)
                CHECK(std::abs(f.normal_to_tangent[k][lane] - row.normal_to_tangent[k]) <= 1e-6 * size);
            for (int k = 0; k < 3; ++k) {
                CHECK(std::abs(f.tangent_response[k][lane] - row.tangent_response[k]) <= 1e-6 * size);
                CHECK(std::abs(f.tangent_mass[k][lane] - row.tangent_mass[k]) <= 1e-5 * std::abs(row.tangent_mass[0]));
            }
            ++compared;
        }
    }
    MESSAGE("rows compared ", compared);
}

TEST_CASE("a K_tt that is singular is singular over four floats too, where rounding leaves it a determinant") {
    // A body that cannot translate and turns about one axis only, touching the world at a point off its centre: K_tt
    // has rank one. In the contact's axes turned by an angle that floats cannot hold exactly, the rounding of its
    // entries leaves a determinant of a few ulps; the lanes take it as singular (each tangent row on its own), as the
    // doubles do with their exact 0 in the unturned axes.
    SolverBody body;
    body.mass.inverse_mass = 0.0;
    body.mass.inverse_inertia_world = Vec3(0.0, 0.0, 0.8).asDiagonal();
    std::vector<ContactRow> rows(4);
    for (int lane = 0; lane < 4; ++lane) {
        ContactRow& row = rows[static_cast<std::size_t>(lane)];
        row.body = {0, -1};
        row.anchor = {Vec3(0.3, 0.7, -0.45), Vec3::Zero()};
        row.basis = Mat3(Eigen::AngleAxisd(0.1 + 0.37 * lane, Vec3(1.0, 2.0, 3.0).normalized()));
    }
    const FrictionMatrixOf<Float4> f = lanes_friction_matrix(rows, std::span<const SolverBody>(&body, 1));
    for (int lane = 0; lane < 4; ++lane) {
        CAPTURE(lane);
        CHECK(f.tangent_invertible[lane] == 0);
        CHECK(f.tangent_mass[1][lane] == 0.0f);
        // Each tangent row alone: its own entry's inverse.
        CHECK(f.tangent_mass[0][lane] == 1.0f / f.tangent_response[0][lane]);
    }
}
