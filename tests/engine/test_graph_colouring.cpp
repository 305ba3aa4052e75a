// Soft step's solve order by graph colouring (methods/graph_colouring.hpp, soft_step.order = colours): Box3D's rules
// for the colours, the order they give, and a coloured soft step that records what it ran and runs as unrecorded.

#include "formats/settings_json.hpp"
#include "formats/scene_file.hpp"
#include "formats/input_error.hpp"
#include "methods/graph_colouring.hpp"
#include "preparation/prepared_contact.hpp"
#include "support/frame_rows.hpp"
#include "support/simulate.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <memory_resource>
#include <numeric>
#include <set>
#include <vector>

using namespace impulse;

namespace {

// `count` points of the pair (a, b); b = -1 the world.
void add_pair(std::vector<ContactRow>& rows, int a, int b, int count = 1) {
    for (int k = 0; k < count; ++k) {
        ContactRow row;  // only the bodies matter to the colouring
        row.basis = Mat3::Identity();
        row.anchor = {Vec3::Zero(), Vec3::Zero()};
        row.contact = static_cast<int>(rows.size());
        row.body = {a, b};
        rows.push_back(row);
    }
}

std::vector<SolverBody> moving_bodies(int count) {
    std::vector<SolverBody> bodies(static_cast<std::size_t>(count));
    for (SolverBody& b : bodies) {
        b.mass.inverse_mass = 1.0;
        b.mass.inverse_inertia_world = Mat3::Identity();
    }
    return bodies;
}

std::vector<std::array<int, 2>> pairs_of(const std::vector<ContactRow>& rows) {
    std::vector<std::array<int, 2>> pairs;
    for (const ContactRow& row : rows) pairs.push_back(row.body);
    return pairs;
}

std::vector<int> colours_of(const std::vector<ContactRow>& rows, const std::vector<SolverBody>& bodies) {
    const std::pmr::vector<int> c = pair_colours(pairs_of(rows), bodies, std::pmr::new_delete_resource());
    return {c.begin(), c.end()};
}

// The order of the visits: order[k] is the row visited k-th, the inverse of colour_slots.
std::vector<std::uint32_t> order_of(const std::vector<ContactRow>& rows, const std::vector<SolverBody>& bodies) {
    const std::pmr::vector<std::uint32_t> slots = colour_slots(pairs_of(rows), bodies, std::pmr::new_delete_resource());
    std::vector<std::uint32_t> order(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) order[slots[r]] = static_cast<std::uint32_t>(r);
    return order;
}

}  // namespace

TEST_CASE("a chain's pairs alternate between the first two colours, its ground pair takes the last") {
    // Box3D's constraint graph: moving pairs the lowest colour neither body has, static pairs from colour 22 down.
    std::vector<ContactRow> rows;
    add_pair(rows, 0, -1, 4);  // box 0 on the ground, four points
    add_pair(rows, 0, 1, 4);
    add_pair(rows, 1, 2, 4);
    add_pair(rows, 2, 3, 4);
    const std::vector<SolverBody> bodies = moving_bodies(4);
    const std::vector<int> colours = colours_of(rows, bodies);
    const std::vector<int> expected{22, 22, 22, 22, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0};
    CHECK(colours == expected);
    // Colour by colour, detection's order within one, a pair's points together and in their order.
    const std::vector<std::uint32_t> order = order_of(rows, bodies);
    const std::vector<std::uint32_t> want{4, 5, 6, 7, 12, 13, 14, 15, 8, 9, 10, 11, 0, 1, 2, 3};
    CHECK(order == want);
}

TEST_CASE("a body of infinite mass and inertia counts as static, like the world") {
    std::vector<ContactRow> rows;
    add_pair(rows, 0, 1);
    add_pair(rows, 2, 1);
    std::vector<SolverBody> bodies = moving_bodies(3);
    bodies[1].mass.inverse_mass = 0.0;
    bodies[1].mass.inverse_inertia_world = Mat3::Zero();
    // Two static pairs of different moving bodies: both take colour 22, as if body 1 were the ground.
    CHECK(colours_of(rows, bodies) == std::vector<int>{22, 22});
    // A body that cannot translate but can turn still takes a colour of its own.
    bodies[1].mass.inverse_inertia_world = Mat3::Identity();
    CHECK(colours_of(rows, bodies) == std::vector<int>{0, 1});
}

TEST_CASE("a body with more neighbours than moving colours sends the rest to the overflow, visited first") {
    std::vector<ContactRow> rows;
    for (int other = 1; other <= 22; ++other) add_pair(rows, 0, other);
    const std::vector<SolverBody> bodies = moving_bodies(23);
    const std::vector<int> colours = colours_of(rows, bodies);
    for (int k = 0; k < 20; ++k) CHECK(colours[static_cast<std::size_t>(k)] == k);
    CHECK(colours[20] == -1);
    CHECK(colours[21] == -1);
    const std::vector<std::uint32_t> order = order_of(rows, bodies);
    CHECK(order[0] == 20);
    CHECK(order[1] == 21);
    CHECK(order[2] == 0);
}

TEST_CASE("on a pyramid a colour's pairs share no moving body, each row is visited once, its slot sorts it by colour") {
    const test::FrameRows frame = test::frame_rows(test::shipped_under("pyramid_20", "soft_step_coloured"), 30);
    const std::vector<ContactRow>& rows = frame.rows;
    const std::vector<SolverBody>& bodies = frame.bodies;
    REQUIRE(rows.size() > 100);
    const std::vector<int> colours = colours_of(rows, bodies);
    // Each colour's pairs: a moving body in at most one of them.
    std::vector<std::set<std::array<int, 2>>> pairs(24);
    for (std::size_t r = 0; r < rows.size(); ++r) {
        REQUIRE(colours[r] >= 0);  // the pyramid needs few colours: nothing overflows
        pairs[static_cast<std::size_t>(colours[r])].insert(rows[r].body);
    }
    for (const std::set<std::array<int, 2>>& colour : pairs) {
        std::multiset<int> used;
        for (const std::array<int, 2>& pair : colour)
            for (const int b : pair)
                if (b >= 0) used.insert(b);
        for (const int b : used) CHECK(used.count(b) == 1);
    }
    std::vector<std::uint32_t> order = order_of(rows, bodies);
    for (std::size_t k = 1; k < order.size(); ++k) CHECK(colours[order[k - 1]] <= colours[order[k]]);
    // The slots a method builds its rows in (from each row's bodies alone): colour by colour, detection's order
    // within a colour, as a stable sort of the rows by colour puts them.
    const std::pmr::vector<std::uint32_t> slots = colour_slots(pairs_of(rows), bodies, std::pmr::new_delete_resource());
    std::vector<std::uint32_t> by_colour(rows.size());
    std::iota(by_colour.begin(), by_colour.end(), 0u);
    std::stable_sort(by_colour.begin(), by_colour.end(),
                     [&colours](std::uint32_t a, std::uint32_t b) { return colours[a] < colours[b]; });
    REQUIRE(slots.size() == rows.size());
    std::size_t misplaced = 0;
    for (std::size_t k = 0; k < by_colour.size(); ++k)
        if (slots[by_colour[k]] != k) ++misplaced;
    CHECK(misplaced == 0);
    std::sort(order.begin(), order.end());
    std::vector<std::uint32_t> every(rows.size());
    std::iota(every.begin(), every.end(), 0u);
    CHECK(order == every);
}

TEST_CASE("a coloured soft step visits a stack's box pairs before its ground pair, recorded or not, bit for bit") {
    const Scene scene = test::shipped_under("stack_3", "soft_step_coloured");
    CHECK(scene.settings.soft_step.order == SolveOrder::colours);
    Trace trace;
    const std::vector<RigidBody> traced = test::simulate(scene, 60, &trace);
    CHECK(test::simulate(scene, 60) == traced);
    // Frame 59's first solve sweep: the ground's contacts come last (colour 22), the boxes' pairs before them.
    const FrameRecord& frame = trace.frames.back();
    std::vector<int> sweep;
    for (const VelocityIteration& v : frame.velocity.iterations)
        if (v.sweep && v.sweep->substep == 0 && v.sweep->pass == 0 && v.sweep->stage == SolverStage::solve)
            sweep.push_back(v.contact);
    REQUIRE(sweep.size() == static_cast<std::size_t>(frame.contact_count));
    const auto on_ground = [&frame](int contact) {
        for (const ContactPreparation& c : frame.contacts)
            if (c.contact == contact) return c.bodies[1] == world_body;
        return false;
    };
    const auto first_ground = std::find_if(sweep.begin(), sweep.end(), on_ground);
    REQUIRE(first_ground != sweep.end());
    CHECK(std::all_of(first_ground, sweep.end(), on_ground));
    CHECK(first_ground != sweep.begin());
    // The order changes the answer: the same scene in detection's order ends elsewhere.
    Scene in_order = scene;
    in_order.settings.soft_step.order = SolveOrder::contacts;
    CHECK(test::simulate(in_order, 60) != traced);
}

TEST_CASE("soft_step.order reads and writes by name, only when it is not contacts, and names the field when wrong") {
    ResolverSettings s = *preset("soft_step_recycled");
    CHECK_FALSE(formats::settings_json(s, WorldSettings{})["soft_step"].contains("order"));
    s.soft_step.order = SolveOrder::colours;
    CHECK(formats::settings_json(s, WorldSettings{})["soft_step"]["order"] == "colours");
    Scene scene = test::shipped("stack_3");
    formats::apply_setting(scene, "soft_step.order=colours", "--set");
    CHECK(scene.settings.soft_step.order == SolveOrder::colours);
    try {
        formats::apply_setting(scene, "soft_step.order=colors", "--set");
        FAIL("a wrong name was read");
    } catch (const formats::InputError& e) {
        CHECK(std::string(e.what()).find("soft_step.order") != std::string::npos);
        CHECK(std::string(e.what()).find("did you mean \"colours\"") != std::string::npos);
    }
    // The preset is soft_step_recycled solved in colours, nothing else.
    ResolverSettings coloured = *preset("soft_step_coloured");
    CHECK(coloured.soft_step.order == SolveOrder::colours);
    coloured.preset = "soft_step_recycled";
    coloured.soft_step.order = SolveOrder::contacts;
    CHECK(coloured == *preset("soft_step_recycled"));
    // And soft_step_wide is soft_step_coloured in wide records.
    ResolverSettings wide = *preset("soft_step_wide");
    CHECK(wide.soft_step.order == SolveOrder::wide);
    CHECK(formats::settings_json(wide, WorldSettings{})["soft_step"]["order"] == "wide");
    formats::apply_setting(scene, "soft_step.order=wide", "--set");
    CHECK(scene.settings.soft_step.order == SolveOrder::wide);
    wide.preset = "soft_step_coloured";
    wide.soft_step.order = SolveOrder::colours;
    CHECK(wide == *preset("soft_step_coloured"));
}
