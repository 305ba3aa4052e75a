// What the inspector shows at the cursor, rebuilt from the recording alone: each contact's bookkeeping and
// status (replayed from the recorded updates), the bodies before and after the cursor's item (replayed from
// the recorded moves and impulses, bit for bit), the phase plots, and the derivation table with its CSV.

#include "model/derivation_view.hpp"
#include "model/navigator.hpp"
#include "model/replay.hpp"
#include "model/session.hpp"

#include "support/navigator_places.hpp"
#include "support/opened.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace impulse;
using namespace impulse::model;

namespace {

using test::opened;
using test::relaxed;
using test::stack_run;

Trace with_settings(const std::string& name, std::vector<std::string> settings) {
    OpenOptions options;
    options.settings = std::move(settings);
    return opened(name, options);
}

// Every item of every stage, at its first step.
std::vector<Cursor> every_item(const Trace& trace) {
    std::vector<Cursor> items;
    for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f)
        for (Stage stage : stages(trace.frames[static_cast<std::size_t>(f)]))
            for (int i = 0; i < item_count(trace.frames[static_cast<std::size_t>(f)], stage); ++i)
                items.push_back({f, stage, i, 0});
    return items;
}

const ContactRow& row_for(const std::vector<ContactRow>& rows, int contact) {
    const auto found =
        std::find_if(rows.begin(), rows.end(), [contact](const ContactRow& r) { return r.contact == contact; });
    REQUIRE(found != rows.end());
    return *found;
}

// The bodies an iteration's chosen contact moves or changes the speed of (the world never moves).
std::vector<int> movable_bodies(const FrameRecord& frame, int contact) {
    std::vector<int> bodies;
    for (int b : preparation_of(frame, contact)->bodies)
        if (b != world_body) bodies.push_back(b);
    return bodies;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t end = text.find('\n'); end != std::string::npos; end = text.find('\n', start)) {
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
}

bool starts_with(const std::string& text, const std::string& prefix) {
    return text.rfind(prefix, 0) == 0;
}

}  // namespace

TEST_CASE("contact rows in the preparation and at the first phase's iteration 0 are the values as prepared") {
    for (const char* name : {"cases/ruler", "cases/three_objects", "cases/sliding_box"}) {
        CAPTURE(name);
        const Trace trace = opened(name);
        const FrameRecord& frame = trace.frames[0];
        const Stage first_phase = stages(frame)[1];
        for (const Cursor& at : {Cursor{0, Stage::preparation, 0, 0}, Cursor{0, first_phase, 0, 0}}) {
            const std::vector<ContactRow> rows = contact_rows(trace, at);
            REQUIRE(rows.size() == frame.contacts.size());
            for (std::size_t i = 0; i < rows.size(); ++i) {
                CHECK(rows[i].contact == frame.contacts[i].contact);
                CHECK(rows[i].prepared == &frame.contacts[i]);
                CHECK(rows[i].penetration == frame.contacts[i].penetration);
                CHECK(rows[i].desired_delta_velocity == frame.contacts[i].desired_terms.desired_delta_velocity);
                CHECK(rows[i].impulse_so_far == Vec3::Zero());
            }
        }
    }
}

TEST_CASE("the chosen contact's row holds exactly the value its iteration compared with the epsilon") {
    // The resolver picks the contact by its bookkeeping value at that moment; the replay rebuilds that value
    // from the recorded updates alone, so the two are the same double.
    for (const Trace& trace :
         {opened("cases/sliding_box"), opened("cases/three_objects"), stack_run(), relaxed("deep_plank"),
          with_settings("cases/deep_corner", {"position_method=relaxation"})}) {
        for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f) {
            const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
            for (const PositionIteration& it : frame.position.iterations) {
                CAPTURE(it.iteration);
                const auto rows = contact_rows(trace, {f, Stage::position, it.iteration, 0});
                CHECK(row_for(rows, it.contact).penetration == it.penetration);
                CHECK(row_for(rows, it.contact).status == ContactStatus::chosen);
            }
            for (const VelocityIteration& it : frame.velocity.iterations) {
                CAPTURE(it.iteration);
                const auto rows = contact_rows(trace, {f, Stage::velocity, it.iteration, 0});
                CHECK(row_for(rows, it.contact).desired_delta_velocity == it.desired_delta_velocity);
                CHECK(row_for(rows, it.contact).status == ContactStatus::chosen);
            }
        }
    }
}

TEST_CASE("every contact's row at an iteration is the value its first update in that iteration started from") {
    // An update records the value before and after; the first update of a contact within an iteration starts
    // from the bookkeeping as the earlier iterations left it, which is what the rows must show.
    for (const Trace& trace : {opened("cases/sliding_box"), stack_run(), relaxed("deep_plank")}) {
        for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f) {
            const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
            for (const PositionIteration& it : frame.position.iterations) {
                const auto rows = contact_rows(trace, {f, Stage::position, it.iteration, 0});
                std::vector<int> seen;
                for (const PenetrationUpdate& u : it.updates) {
                    if (std::find(seen.begin(), seen.end(), u.contact) != seen.end()) continue;
                    seen.push_back(u.contact);
                    CHECK(row_for(rows, u.contact).penetration == u.before);
                }
                REQUIRE_FALSE(seen.empty());
            }
            for (const VelocityIteration& it : frame.velocity.iterations) {
                const auto rows = contact_rows(trace, {f, Stage::velocity, it.iteration, 0});
                std::vector<int> seen;
                for (const VelocityUpdate& u : it.updates) {
                    if (std::find(seen.begin(), seen.end(), u.contact) != seen.end()) continue;
                    seen.push_back(u.contact);
                    CHECK(row_for(rows, u.contact).desired_delta_velocity == u.desired_delta_velocity_before);
                }
                REQUIRE_FALSE(seen.empty());
            }
        }
    }
}

TEST_CASE("the impulse so far sums the impulses of the velocity iterations before the cursor") {
    const Trace trace = opened("cases/sliding_box");
    const std::vector<VelocityIteration>& its = trace.frames[0].velocity.iterations;
    // Iterations 0, 2 and 4 chose contact 0; at iteration 5 its impulse so far is the sum of those three.
    REQUIRE(its[0].contact == 0);
    REQUIRE(its[2].contact == 0);
    REQUIRE(its[4].contact == 0);
    const Vec3 expected = its[0].resolution->impulse_terms.impulse_world +
                          its[2].resolution->impulse_terms.impulse_world +
                          its[4].resolution->impulse_terms.impulse_world;
    CHECK(row_for(contact_rows(trace, {0, Stage::velocity, 5, 0}), 0).impulse_so_far == expected);
    // Contact 2 was never chosen.
    CHECK(row_for(contact_rows(trace, {0, Stage::velocity, 6, 0}), 2).impulse_so_far == Vec3::Zero());
}

TEST_CASE("exactly one contact is chosen at an iteration and none in the preparation") {
    for (const Trace& trace : {opened("cases/sliding_box"), stack_run()}) {
        for (const Cursor& c : every_item(trace)) {
            const std::vector<ContactRow> rows = contact_rows(trace, c);
            const auto chosen = std::count_if(rows.begin(), rows.end(),
                                              [](const ContactRow& r) { return r.status == ContactStatus::chosen; });
            CHECK(chosen == (c.stage == Stage::preparation ? 0 : 1));
        }
    }
}

TEST_CASE("a contact waits while its value is above the phase's epsilon and is below ε at or under it") {
    for (const Trace& trace : {opened("cases/sliding_box"), stack_run(), relaxed("deep_plank")}) {
        const ResolverSettings& s = trace.scene.settings;
        for (const Cursor& c : every_item(trace)) {
            // The preparation is judged against the phase that runs first: positions for the book preset.
            const bool position = c.stage == Stage::position || c.stage == Stage::preparation;
            for (const ContactRow& r : contact_rows(trace, c)) {
                if (r.status == ContactStatus::chosen) continue;
                const double value = position ? r.penetration : r.desired_delta_velocity;
                const double epsilon = position ? s.position_epsilon : s.velocity_epsilon;
                CHECK(r.status == (value > epsilon ? ContactStatus::waiting : ContactStatus::below_epsilon));
            }
        }
    }
}

TEST_CASE("three objects: a contact once resolved is below ε while the next still waits") {
    // Three bodies close on the ground at 2 m/s with restitution 0.5: each contact asks for
    // dv = (1 + 0.5) 2 = 3 m/s, and each impulse touches only its own body. Once resolved, contact 0
    // separates at 1 m/s and step 5 re-run on it gives -(1 + 0.5) 1 = -1.5 m/s. At iteration 1 contact 1 is
    // chosen and contact 2 still asks for its 3 m/s.
    const Trace trace = opened("cases/three_objects");
    const std::vector<ContactRow> rows = contact_rows(trace, {0, Stage::velocity, 1, 0});
    REQUIRE(rows.size() == 3);
    CHECK(rows[0].status == ContactStatus::below_epsilon);
    CHECK(rows[0].desired_delta_velocity == doctest::Approx(-1.5).epsilon(1e-12));
    CHECK(rows[1].status == ContactStatus::chosen);
    CHECK(rows[2].status == ContactStatus::waiting);
    CHECK(rows[2].desired_delta_velocity == 3.0);
    CHECK(status_name(rows[0].status) == "below ε");
    CHECK(status_name(rows[1].status) == "chosen");
    CHECK(status_name(rows[2].status) == "waiting");
}

TEST_CASE("a value equal to the epsilon is below ε, and the preparation is judged by the phase that runs first") {
    // Velocities first, with the velocity epsilon at the 3 m/s every contact asks for: nothing is above it,
    // so no iteration runs and every contact is below ε in the preparation.
    const Trace at = with_settings("cases/three_objects", {"phase_order=velocities_first", "velocity_epsilon=3"});
    REQUIRE(at.frames[0].velocity.iterations.empty());
    for (const ContactRow& r : contact_rows(at, {0, Stage::preparation, 0, 0}))
        CHECK(r.status == ContactStatus::below_epsilon);
    // Just under 3 m/s, they wait.
    const Trace under =
        with_settings("cases/three_objects", {"phase_order=velocities_first", "velocity_epsilon=2.999"});
    for (const ContactRow& r : contact_rows(under, {0, Stage::preparation, 0, 0}))
        CHECK(r.status == ContactStatus::waiting);
    // Positions first (the book): the same preparation is judged by penetration 0 against 0.01, below ε.
    for (const ContactRow& r : contact_rows(opened("cases/three_objects"), {0, Stage::preparation, 0, 0}))
        CHECK(r.status == ContactStatus::below_epsilon);
}

TEST_CASE("the bodies after a frame's last item are the frame's recorded end state, bit for bit") {
    for (const Trace& trace : {opened("cases/ruler"), opened("cases/sliding_box"), opened("cases/three_objects"),
                               opened("cases/two_body_oblique"), stack_run(), relaxed("deep_plank"),
                               with_settings("cases/ruler", {"phase_order=velocities_first"}),
                               with_settings("cases/ruler", {"orientation_update=exact"}),
                               with_settings("cases/deep_corner", {"position_method=velocity_based"}),
                               stack_run({"preset=sweep"}), stack_run({"preset=pgs"}), stack_run({"preset=pgs_split"}),
                               with_settings("cases/deep_corner", {"preset=pgs_split"})}) {
        for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f) {
            const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
            const Stage last = stages(frame).back();
            REQUIRE(last != Stage::preparation);
            const BodiesAtCursor bodies = bodies_at(trace, {f, last, item_count(frame, last) - 1, 0});
            CHECK(bodies.exact);
            CHECK(bodies.after == frame.bodies_after);
        }
    }
}

TEST_CASE("in the preparation nothing has moved yet") {
    const Trace trace = opened("cases/sliding_box");
    const BodiesAtCursor bodies = bodies_at(trace, {0, Stage::preparation, 2, 1});
    CHECK(bodies.exact);
    CHECK(bodies.before == trace.frames[0].bodies_before);
    CHECK(bodies.after == trace.frames[0].bodies_before);
    CHECK(bodies.moved.empty());
}

TEST_CASE("each item starts from the state the item before it left, across the two phases") {
    for (const Trace& trace : {opened("cases/ruler"), stack_run(), relaxed("deep_plank")}) {
        const std::vector<Cursor> items = every_item(trace);
        for (std::size_t i = 1; i < items.size(); ++i) {
            if (items[i].frame != items[i - 1].frame) continue;
            CAPTURE(describe(trace, items[i]));
            CHECK(bodies_at(trace, items[i]).before == bodies_at(trace, items[i - 1]).after);
        }
    }
}

TEST_CASE("moved lists the movable bodies of the chosen contact") {
    // The ruler against the ground: only the ruler (body 0).
    const Trace ruler = opened("cases/ruler");
    CHECK(bodies_at(ruler, {0, Stage::position, 0, 0}).moved == std::vector<int>{0});
    CHECK(bodies_at(ruler, {0, Stage::velocity, 0, 0}).moved == std::vector<int>{0});
    // Two bodies meeting obliquely: both.
    CHECK(bodies_at(opened("cases/two_body_oblique"), {0, Stage::velocity, 0, 0}).moved == std::vector<int>{0, 1});
    // The stack: a ground contact moves one box, a box-box contact two.
    const Trace stack = stack_run();
    for (int f = 0; f < 3; ++f)
        for (int i = 0; i < item_count(stack.frames[static_cast<std::size_t>(f)], Stage::velocity); ++i) {
            const Cursor c{f, Stage::velocity, i, 0};
            CHECK(bodies_at(stack, c).moved ==
                  movable_bodies(stack.frames[static_cast<std::size_t>(f)], contact_at(stack, c)));
        }
    // Only those change: every other body is the same before and after.
    const BodiesAtCursor b = bodies_at(stack, {1, Stage::velocity, 0, 0});
    for (std::size_t body = 0; body < b.before.size(); ++body)
        if (std::find(b.moved.begin(), b.moved.end(), static_cast<int>(body)) == b.moved.end())
            CHECK(b.before[body] == b.after[body]);
}

TEST_CASE("with a contact filter the bodies are exact only until an unrecorded derivation") {
    // Recording contact 0 of three objects: iteration 0 (contact 0) has its impulse, iterations 1 and 2
    // (contacts 1 and 2) do not.
    OpenOptions options;
    options.record = {"contacts=0"};
    const Trace trace = opened("cases/three_objects", options);
    const FrameRecord& frame = trace.frames[0];
    REQUIRE(frame.velocity.iterations.size() == 3);
    REQUIRE(frame.velocity.iterations[0].resolution.has_value());
    REQUIRE_FALSE(frame.velocity.iterations[1].resolution.has_value());

    const BodiesAtCursor first = bodies_at(trace, {0, Stage::velocity, 0, 0});
    CHECK(first.exact);
    CHECK(first.moved == std::vector<int>{0});
    CHECK(first.before == frame.bodies_before);
    CHECK(first.after != frame.bodies_before);

    // Iteration 1's own impulse is missing: what it did cannot be shown.
    const BodiesAtCursor second = bodies_at(trace, {0, Stage::velocity, 1, 0});
    CHECK_FALSE(second.exact);
    CHECK(second.after == frame.bodies_after);
    CHECK(second.moved.empty());

    // Iteration 2 follows a missing one: the frame's start and end.
    const BodiesAtCursor third = bodies_at(trace, {0, Stage::velocity, 2, 0});
    CHECK_FALSE(third.exact);
    CHECK(third.before == frame.bodies_before);
    CHECK(third.after == frame.bodies_after);

    // Only contact 0 has a row; the iterations that chose an unrecorded contact show none chosen.
    const std::vector<ContactRow> rows = contact_rows(trace, {0, Stage::velocity, 1, 0});
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].contact == 0);
    CHECK(rows[0].status == ContactStatus::below_epsilon);
}

TEST_CASE("a phase's curve is the value each iteration picked, with the phase's epsilon") {
    const Trace ruler = opened("cases/ruler");
    const std::vector<PhaseCurve> curves = phase_curves(ruler.frames[0]);
    REQUIRE(curves.size() == 2);
    // The ruler: 0.02 m deep, closing at 3 m/s with restitution 0.5 -> desired delta v 4.5 m/s (see the case).
    CHECK(curves[0].stage == Stage::position);
    CHECK(curves[0].worst == std::vector<double>{0.02});
    CHECK(curves[0].epsilon == 0.01);
    CHECK(curves[1].stage == Stage::velocity);
    CHECK(curves[1].worst == std::vector<double>{4.5});
    CHECK(curves[1].epsilon == 0.01);

    const Trace box = opened("cases/sliding_box");
    const std::vector<PhaseCurve> box_curves = phase_curves(box.frames[0]);
    REQUIRE(box_curves.size() == 1);  // 1 mm deep: below the position epsilon, no position phase
    CHECK(box_curves[0].stage == Stage::velocity);
    REQUIRE(box_curves[0].worst.size() == box.frames[0].velocity.iterations.size());
    for (std::size_t i = 0; i < box_curves[0].worst.size(); ++i)
        CHECK(box_curves[0].worst[i] == box.frames[0].velocity.iterations[i].desired_delta_velocity);
}

TEST_CASE("the derivation view holds the item's rows up to the current step, the current step's marked changed") {
    const Trace trace = opened("cases/ruler");
    const Cursor at{0, Stage::velocity, 0, 3};  // impulse
    const std::vector<explain::StepTable> tables = step_tables(trace, at);
    const DerivationView view = derivation_view(trace, at);
    CHECK(view.where == "frame 0 · velocity phase · iteration 0 · contact 0 · impulse");
    CHECK(view.step == "impulse");
    CHECK(view.step_title == tables[3].title);
    CHECK(view.step_index == 3);
    CHECK(view.step_count == 6);
    std::size_t expected_rows = 0;
    for (int i = 0; i <= 3; ++i) expected_rows += tables[static_cast<std::size_t>(i)].rows.size();
    REQUIRE(view.rows.size() == expected_rows);
    std::size_t n = 0;
    for (int i = 0; i <= 3; ++i)
        for (const explain::Row& r : tables[static_cast<std::size_t>(i)].rows) {
            const ViewRow& v = view.rows[n++];
            CHECK(v.step == tables[static_cast<std::size_t>(i)].step);
            CHECK(v.row.quantity == r.quantity);
            CHECK(v.row.value == r.value);
            CHECK(v.changed == (i == 3));
        }
    // At the first step everything shown is new.
    const DerivationView first = derivation_view(trace, {0, Stage::preparation, 0, 0});
    REQUIRE_FALSE(first.rows.empty());
    for (const ViewRow& r : first.rows) CHECK(r.changed);
}

TEST_CASE("world vectors carry their contact coordinates and contact vectors their world coordinates") {
    const Trace trace = opened("cases/ruler");
    // Steps 2-4 of the prepared contact: relative_position and point_velocity are world vectors,
    // contact_velocity is in contact coordinates; the basis table has no vector to convert.
    const DerivationView prepared = derivation_view(trace, {0, Stage::preparation, 0, 3});
    for (const ViewRow& r : prepared.rows) {
        CAPTURE(r.row.quantity);
        if (starts_with(r.row.quantity, "relative_position") || starts_with(r.row.quantity, "point_velocity"))
            CHECK(starts_with(r.row.other_frame, "contact ("));
        else if (r.row.quantity == "contact_velocity")
            CHECK(starts_with(r.row.other_frame, "world ("));
        else if (r.step == "basis")
            CHECK(r.row.other_frame.empty());
    }
    const DerivationView impulse = derivation_view(trace, {0, Stage::velocity, 0, 3});
    bool saw_world = false, saw_contact = false;
    for (const ViewRow& r : impulse.rows) {
        if (r.row.quantity == "impulse_world") saw_world = starts_with(r.row.other_frame, "contact (");
        if (r.row.quantity == "impulse") saw_contact = starts_with(r.row.other_frame, "world (");
    }
    CHECK(saw_world);
    CHECK(saw_contact);
}

TEST_CASE("the derivation CSV has a header and one line per row, quoting commas and quotes") {
    // A view written by hand: a plain row, a vector (commas), a matrix (lines joined by "; ") and a quote.
    DerivationView view;
    view.rows.push_back({"impulse",
                         {"impulse_model", "frictionless", "", "", "which model", "", "impulse_model", "frictionless"},
                         false});
    view.rows.push_back({"impulse",
                         {"impulse_world", "(0, 1.5, 0) N s", "C g", "(14.2)", "the impulse", "contact (1.5, 0, 0)",
                          "impulse_world", "(0, 1.5000000000000002, 0) N s"},
                         true});
    view.rows.push_back({"basis",
                         {"basis", "[1, 0, 0]\n[0, 1, 0]\n[0, 0, 1]", "", "", "the \"basis\" matrix", "", "basis",
                          "[1, 0, 0]; [0, 1, 0]; [0, 0, 1]"},
                         true});
    CHECK(derivation_csv(view) ==
          "step,quantity,value,exact,other_frame,formula,equation,meaning,changed\n"
          "impulse,impulse_model,frictionless,frictionless,,,,which model,no\n"
          "impulse,impulse_world,\"(0, 1.5, 0) N s\",\"(0, 1.5000000000000002, 0) N s\",\"contact (1.5, 0, 0)\",C g,"
          "(14.2),the impulse,yes\n"
          "basis,basis,\"[1, 0, 0]; [0, 1, 0]; [0, 0, 1]\",\"[1, 0, 0]; [0, 1, 0]; [0, 0, 1]\",,,,\"the \"\"basis\"\" "
          "matrix\",yes\n");
}

TEST_CASE("the CSV of a real view has one line per row and no line broken by a matrix") {
    const Trace trace = opened("cases/sliding_box");
    // The preparation's basis (a matrix) and a friction impulse (the delta velocity matrix).
    for (const Cursor& at : {Cursor{0, Stage::preparation, 0, 4}, Cursor{0, Stage::velocity, 0, 3}}) {
        const DerivationView view = derivation_view(trace, at);
        const std::vector<std::string> lines = lines_of(derivation_csv(view));
        REQUIRE(lines.size() == view.rows.size() + 1);
        CHECK(lines[0] == "step,quantity,value,exact,other_frame,formula,equation,meaning,changed");
        for (std::size_t i = 0; i < view.rows.size(); ++i) {
            CHECK(starts_with(lines[i + 1], view.rows[i].step + "," + view.rows[i].row.quantity + ","));
            CHECK(lines[i + 1].ends_with(view.rows[i].changed ? ",yes" : ",no"));
        }
    }
    const DerivationView basis = derivation_view(trace, {0, Stage::preparation, 0, 0});
    const std::string csv = derivation_csv(basis);
    CHECK(csv.find("]; [") != std::string::npos);
}
