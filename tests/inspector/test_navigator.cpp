// The inspector's navigator: a trace read as frame -> stage -> item -> step, and the moves over it. Stepping
// forward visits every table once, stepping back retraces it exactly, the coarser moves land where their
// names say, and a place named by a person (--goto) or remembered across a re-run comes back to the same
// table.

#include "formats/input_error.hpp"
#include "model/navigator.hpp"
#include "model/session.hpp"

#include "support/opened.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

using namespace impulse;
using namespace impulse::model;

namespace {

using test::opened;

// Three frames of the stack: enough for moves to cross frames, small enough to walk every step.
Trace stack_run() {
    OpenOptions options;
    options.frames = 3;
    return opened("stack_3", options);
}

// A shipped case or scene with the position phase relaxed: several passes, so the same contact is chosen
// more than once. Of deep_plank only the first frame, where its plank lands on four corners.
Trace relaxed(const std::string& name) {
    OpenOptions options;
    options.settings = {"position_method=relaxation"};
    if (name == "deep_plank") options.frames = 1;
    return opened(name, options);
}

// Every place in the trace, enumerated from the recording's shape alone (frames, their stages in the order
// they ran, items, tables), without using any move.
std::vector<Cursor> every_place(const Trace& trace) {
    std::vector<Cursor> places;
    for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f) {
        const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
        std::vector<Stage> order{Stage::preparation};
        if (frame.phase_order == PhaseOrder::positions_first)
            order.insert(order.end(), {Stage::position, Stage::velocity});
        else
            order.insert(order.end(), {Stage::velocity, Stage::position});
        for (Stage stage : order) {
            const std::size_t items = stage == Stage::preparation ? frame.contacts.size()
                                      : stage == Stage::position  ? frame.position.iterations.size()
                                                                  : frame.velocity.iterations.size();
            for (int item = 0; item < static_cast<int>(items); ++item) {
                const Cursor at{f, stage, item, 0};
                const int steps = static_cast<int>(step_tables(trace, at).size());
                for (int step = 0; step < steps; ++step) places.push_back({f, stage, item, step});
            }
        }
    }
    return places;
}

std::vector<Cursor> walked_forward(const Trace& trace) {
    std::vector<Cursor> walk;
    for (std::optional<Cursor> c = first_cursor(trace); c; c = next_step(trace, *c)) {
        walk.push_back(*c);
        REQUIRE(walk.size() < 100000);  // a move that never reaches the end would loop here
    }
    return walk;
}

std::vector<Cursor> walked_back(const Trace& trace) {
    std::vector<Cursor> walk;
    for (std::optional<Cursor> c = last_cursor(trace); c; c = previous_step(trace, *c)) {
        walk.push_back(*c);
        REQUIRE(walk.size() < 100000);
    }
    return walk;
}

std::vector<std::string> table_steps(const Trace& trace, const Cursor& cursor) {
    std::vector<std::string> names;
    for (const explain::StepTable& t : step_tables(trace, cursor)) names.push_back(t.step);
    return names;
}

std::string step_at(const Trace& trace, const Cursor& cursor) {
    return step_tables(trace, cursor)[static_cast<std::size_t>(cursor.step)].step;
}

// The error resolve_goto (or parse_goto) raises for `text`; fails the test when there is none.
formats::InputError goto_error(const Trace& trace, const std::string& text) {
    try {
        resolve_goto(trace, parse_goto(text, "--goto"), "--goto");
    } catch (const formats::InputError& e) {
        return e;
    }
    FAIL("--goto " << text << " was accepted");
    return formats::InputError("", "");
}

formats::InputError parse_error(const std::string& text, const std::string& where) {
    try {
        parse_goto(text, where);
    } catch (const formats::InputError& e) {
        return e;
    }
    FAIL("\"" << text << "\" parsed");
    return formats::InputError("", "");
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("stepping forward from the first place visits every table of the ruler once, in order") {
    const Trace trace = opened("cases/ruler");
    // One contact: 5 preparation steps; one position iteration (choice, penetration_inertia, move_split,
    // position_change, updates); one velocity iteration (choice, steps 4-7, updates). 5 + 5 + 6 = 16.
    const std::vector<Cursor> walk = walked_forward(trace);
    CHECK(walk.size() == 16);
    CHECK(walk == every_place(trace));
    CHECK(walk.front() == Cursor{0, Stage::preparation, 0, 0});
    CHECK(walk.back() == Cursor{0, Stage::velocity, 0, 5});
    CHECK(walk.back() == *last_cursor(trace));
}

TEST_CASE("stepping forward through three frames of the stack visits every table once and crosses frames") {
    const Trace trace = stack_run();
    REQUIRE(trace.frames.size() == 3);
    const std::vector<Cursor> walk = walked_forward(trace);
    CHECK(walk == every_place(trace));
    CHECK(walk.back() == *last_cursor(trace));
    // Every frame is entered at its first prepared contact's first step.
    for (int f = 1; f < 3; ++f)
        CHECK(std::find(walk.begin(), walk.end(), Cursor{f, Stage::preparation, 0, 0}) != walk.end());
}

TEST_CASE("stepping back from every place returns exactly to where stepping forward came from") {
    for (const Trace& trace : {opened("cases/ruler"), stack_run()}) {
        const std::vector<Cursor> forward = walked_forward(trace);
        REQUIRE(forward.size() > 1);
        for (std::size_t i = 1; i < forward.size(); ++i) {
            CAPTURE(describe(trace, forward[i]));
            CHECK(previous_step(trace, forward[i]) == forward[i - 1]);
        }
        std::vector<Cursor> back = walked_back(trace);
        std::reverse(back.begin(), back.end());
        CHECK(back == forward);
    }
}

TEST_CASE("there is no step after the last place nor before the first") {
    for (const Trace& trace : {opened("cases/ruler"), stack_run()}) {
        CHECK_FALSE(next_step(trace, *last_cursor(trace)).has_value());
        CHECK_FALSE(previous_step(trace, *first_cursor(trace)).has_value());
        CHECK_FALSE(next_item(trace, *last_cursor(trace)).has_value());
        CHECK_FALSE(previous_item(trace, *first_cursor(trace)).has_value());
    }
}

TEST_CASE("a trace that records nothing has no first or last place") {
    Trace trace = opened("cases/ruler");
    trace.frames.clear();
    CHECK_FALSE(first_cursor(trace).has_value());
    CHECK_FALSE(last_cursor(trace).has_value());
    CHECK_FALSE(nearest_cursor(trace, Location{}).has_value());
}

TEST_CASE("a prepared contact's steps are the five of the preparation, in order") {
    const Trace trace = opened("cases/ruler");
    CHECK(table_steps(trace, {0, Stage::preparation, 0, 0}) ==
          std::vector<std::string>{"basis", "relative_position", "delta_velocity_per_unit_impulse", "contact_velocity",
                                   "desired_delta_velocity"});
}

TEST_CASE("a velocity iteration starts with its choice, then steps 4 to 7, then its updates") {
    const Trace trace = opened("cases/ruler");
    // The ruler's only contact shares its body with itself: the impulse updates its own velocity (1 update).
    REQUIRE(trace.frames[0].velocity.iterations[0].updates.size() == 1);
    CHECK(table_steps(trace, {0, Stage::velocity, 0, 0}) ==
          std::vector<std::string>{"choice", "contact_velocity", "desired_delta_velocity", "impulse", "velocity_change",
                                   "updates"});
}

TEST_CASE("a position iteration starts with its choice, then step 8's three tables, then its updates") {
    const Trace trace = opened("cases/ruler");
    CHECK(table_steps(trace, {0, Stage::position, 0, 0}) ==
          std::vector<std::string>{"choice", "penetration_inertia", "move_split", "position_change", "updates"});
}

TEST_CASE("the stages of a frame are the preparation then the phases in the order they ran, without empty ones") {
    const Trace book = opened("cases/ruler");
    CHECK(stages(book.frames[0]) == std::vector<Stage>{Stage::preparation, Stage::position, Stage::velocity});
    OpenOptions chapter;
    chapter.settings = {"phase_order=velocities_first"};
    const Trace swapped = opened("cases/ruler", chapter);
    CHECK(stages(swapped.frames[0]) == std::vector<Stage>{Stage::preparation, Stage::velocity, Stage::position});
    // Three objects touching their ground without penetration: no position iteration at all.
    const Trace three = opened("cases/three_objects");
    CHECK(stages(three.frames[0]) == std::vector<Stage>{Stage::preparation, Stage::velocity});
}

TEST_CASE("next item keeps the step of the same name when the new item has it, else goes to its first step") {
    const Trace trace = opened("cases/three_objects");
    // Preparation contact 0 at contact_velocity (step 3) -> contact 1 at the same step.
    CHECK(next_item(trace, {0, Stage::preparation, 0, 3}) == Cursor{0, Stage::preparation, 1, 3});
    // The last prepared contact at contact_velocity -> velocity iteration 0, whose contact_velocity is step 1.
    CHECK(next_item(trace, {0, Stage::preparation, 2, 3}) == Cursor{0, Stage::velocity, 0, 1});
    // At basis, which no iteration has -> the iteration's first step, its choice.
    CHECK(next_item(trace, {0, Stage::preparation, 2, 0}) == Cursor{0, Stage::velocity, 0, 0});
    // Iteration 0 at impulse (step 3) -> iteration 1 at impulse; and back.
    CHECK(next_item(trace, {0, Stage::velocity, 0, 3}) == Cursor{0, Stage::velocity, 1, 3});
    CHECK(previous_item(trace, {0, Stage::velocity, 1, 3}) == Cursor{0, Stage::velocity, 0, 3});
    // Back from iteration 0 at contact_velocity -> the last prepared contact at contact_velocity (step 3).
    CHECK(previous_item(trace, {0, Stage::velocity, 0, 1}) == Cursor{0, Stage::preparation, 2, 3});
}

TEST_CASE("next contact in a phase skips the iterations that chose the same contact") {
    // Relaxation on the deep plank's first frame picks contacts 1 3 2 0 3 1 0 2 1 3 3 1: iterations 9 and 10
    // both chose contact 3.
    const Trace trace = relaxed("deep_plank");
    const std::vector<PositionIteration>& its = trace.frames[0].position.iterations;
    REQUIRE(its.size() == 12);
    REQUIRE(its[8].contact == 1);
    REQUIRE(its[9].contact == 3);
    REQUIRE(its[10].contact == 3);
    REQUIRE(its[11].contact == 1);
    // From iteration 9 at position_change (step 3): past 10 to 11, on the same step.
    CHECK(next_contact(trace, {0, Stage::position, 9, 3}) == Cursor{0, Stage::position, 11, 3});
    CHECK(previous_contact(trace, {0, Stage::position, 10, 3}) == Cursor{0, Stage::position, 8, 3});
    // Where the next iteration chose another contact, the move is the next iteration.
    CHECK(next_contact(trace, {0, Stage::position, 0, 0}) == Cursor{0, Stage::position, 1, 0});
}

TEST_CASE("next contact leaves a phase whose remaining iterations all chose the same contact") {
    // Relaxation on the deep corner halves its one contact's 0.8 m four times: 0.8, 0.4, 0.2, 0.1, all contact
    // 0, and there is no velocity phase. So from iteration 0 there is no other contact to go to.
    const Trace trace = relaxed("cases/deep_corner");
    const std::vector<PositionIteration>& its = trace.frames[0].position.iterations;
    REQUIRE(its.size() == 4);
    CHECK(its[3].penetration == doctest::Approx(0.1));
    CHECK_FALSE(next_contact(trace, {0, Stage::position, 0, 0}).has_value());
    // Backwards, the same contact is skipped back into the preparation.
    CHECK(previous_contact(trace, {0, Stage::position, 3, 0}) == Cursor{0, Stage::preparation, 0, 0});
}

TEST_CASE("next contact in the preparation is the next prepared contact") {
    const Trace trace = opened("cases/three_objects");
    CHECK(next_contact(trace, {0, Stage::preparation, 0, 4}) == Cursor{0, Stage::preparation, 1, 4});
    CHECK(previous_contact(trace, {0, Stage::preparation, 2, 1}) == Cursor{0, Stage::preparation, 1, 1});
}

TEST_CASE("next iteration from the preparation lands on the first phase's iteration 0") {
    const Trace book = opened("cases/ruler");
    CHECK(next_iteration(book, {0, Stage::preparation, 0, 2}) == Cursor{0, Stage::position, 0, 0});
    OpenOptions options;
    options.settings = {"phase_order=velocities_first"};
    const Trace swapped = opened("cases/ruler", options);
    CHECK(next_iteration(swapped, {0, Stage::preparation, 0, 2}) == Cursor{0, Stage::velocity, 0, 0});
    // Within the phases it is the next iteration, crossing from the first phase into the second.
    CHECK(next_iteration(book, {0, Stage::position, 0, 0}) == Cursor{0, Stage::velocity, 0, 0});
}

TEST_CASE("previous iteration skips the preparation into the previous frame's last iteration") {
    const Trace trace = stack_run();
    const FrameRecord& frame0 = trace.frames[0];
    REQUIRE(stages(trace.frames[1]).back() == Stage::velocity);
    const int last0 = static_cast<int>(frame0.velocity.iterations.size()) - 1;
    const std::optional<Cursor> back = previous_iteration(trace, {1, Stage::velocity, 0, 0});
    REQUIRE(back.has_value());
    CHECK(back->frame == 0);
    CHECK(back->stage == Stage::velocity);
    CHECK(back->item == last0);
    // And before the first frame's first iteration there is none.
    CHECK_FALSE(previous_iteration(trace, {0, Stage::velocity, 0, 0}).has_value());
}

// Regression: next_iteration was next_item from a phase, which at the end of a frame's last phase landed on
// the next frame's preparation (a prepared contact, not an iteration).
TEST_CASE("next iteration from a frame's last iteration lands on the next frame's first iteration") {
    const Trace trace = stack_run();
    const int last0 = static_cast<int>(trace.frames[0].velocity.iterations.size()) - 1;
    const std::optional<Cursor> next = next_iteration(trace, {0, Stage::velocity, last0, 0});
    REQUIRE(next.has_value());
    CHECK(next->frame == 1);
    CHECK(next->stage == stages(trace.frames[1])[1]);  // the first phase after the preparation
    CHECK(next->item == 0);
}

TEST_CASE("next stage goes to the start of the next stage and frame, previous stage first to this one's start") {
    const Trace trace = stack_run();
    CHECK(next_stage(trace, {0, Stage::preparation, 3, 2}) == Cursor{0, Stage::velocity, 0, 0});
    CHECK(next_stage(trace, {0, Stage::velocity, 5, 2}) == Cursor{1, Stage::preparation, 0, 0});
    // Inside a stage: back to its own start, as page-up does; from the start, to the previous stage's start.
    CHECK(previous_stage(trace, {1, Stage::velocity, 5, 2}) == Cursor{1, Stage::velocity, 0, 0});
    CHECK(previous_stage(trace, {1, Stage::velocity, 0, 0}) == Cursor{1, Stage::preparation, 0, 0});
    CHECK(previous_stage(trace, {1, Stage::preparation, 0, 0}) == Cursor{0, Stage::velocity, 0, 0});
    CHECK_FALSE(previous_stage(trace, {0, Stage::preparation, 0, 0}).has_value());
    CHECK_FALSE(next_stage(trace, *last_cursor(trace)).has_value());
}

TEST_CASE("a goto spec names each part it was given and leaves the others out") {
    const GotoSpec spec = parse_goto("frame=2,phase=velocity,iteration=3,contact=1,step=impulse", "--goto");
    CHECK(spec.frame == 2);
    CHECK(spec.stage == Stage::velocity);
    CHECK(spec.iteration == 3);
    CHECK(spec.contact == 1);
    CHECK(spec.step == "impulse");
    const GotoSpec only = parse_goto("phase=preparation", "--goto");
    CHECK(only.stage == Stage::preparation);
    CHECK_FALSE(only.frame.has_value());
    CHECK_FALSE(only.iteration.has_value());
    CHECK_FALSE(only.contact.has_value());
    CHECK_FALSE(only.step.has_value());
}

TEST_CASE("a malformed goto spec is an input error at the place it came from") {
    const std::string where = "line 7";
    for (const char* bad : {"", "frame", "fram=1", "frame=x", "frame=-1", "iteration=1.5", "contact=2x",
                            "phase=friction", "step=", "frame=0,,phase=velocity"}) {
        CAPTURE(bad);
        const formats::InputError e = parse_error(bad, where);
        CHECK(e.where() == where);
        CHECK_FALSE(e.problem().empty());
    }
    CHECK(contains(parse_error("fram=1", "x").problem(), "unknown part \"fram\""));
    CHECK(contains(parse_error("frame=x", "x").problem(), "frame must be a whole number"));
    CHECK(contains(parse_error("phase=friction", "x").problem(), "\"friction\""));
}

TEST_CASE("a goto names what the trace does not have") {
    const Trace trace = opened("cases/ruler");
    const formats::InputError frame = goto_error(trace, "frame=5");
    CHECK(frame.where() == "--goto");
    CHECK(contains(frame.problem(), "frame 5 is not in the trace"));
    CHECK(contains(frame.problem(), "recorded frames: 0..0"));
    CHECK(contains(goto_error(trace, "phase=velocity,iteration=1").problem(), "iterations 0..0, not 1"));
    // Without a phase, an iteration no phase has is named against the first phase.
    CHECK(contains(goto_error(trace, "iteration=5").problem(), "position phase of frame 0 has iterations 0..0, not 5"));
    CHECK(contains(goto_error(trace, "contact=1").problem(), "contact 1 is not recorded"));
    CHECK(contains(goto_error(trace, "phase=velocity,contact=4").problem(), "chose contact 4"));
    CHECK(contains(goto_error(trace, "phase=velocity,step=nonsense").problem(), "\"nonsense\""));
    CHECK(contains(goto_error(trace, "phase=preparation,iteration=0").problem(), "use contact=C"));
    // Three objects never penetrate: no position phase.
    CHECK(
        contains(goto_error(opened("cases/three_objects"), "phase=position").problem(), "has no position iterations"));
}

TEST_CASE("a goto with every part lands on that table") {
    const Trace trace = stack_run();
    // Frame 1's velocity iteration 4 chose contact 8 (see the recording); its impulse is step 3.
    REQUIRE(trace.frames[1].velocity.iterations[4].contact == 8);
    CHECK(resolve_goto(trace, parse_goto("frame=1,phase=velocity,iteration=4,contact=8,step=impulse", "g"), "g") ==
          Cursor{1, Stage::velocity, 4, 3});
    // contact=C alone in a phase: the first iteration that chose it.
    CHECK(resolve_goto(trace, parse_goto("frame=1,phase=velocity,contact=8", "g"), "g") ==
          Cursor{1, Stage::velocity, 4, 0});
    // In the preparation, contact=C is the prepared contact.
    CHECK(resolve_goto(trace, parse_goto("frame=2,contact=5,step=contact_velocity", "g"), "g") ==
          Cursor{2, Stage::preparation, 5, 3});
    // An iteration without a phase is the first phase that has it.
    CHECK(resolve_goto(trace, parse_goto("frame=0,iteration=2", "g"), "g") == Cursor{0, Stage::velocity, 2, 0});
}

TEST_CASE("step=angular_change goes to the position phase's table that shows the angular change") {
    // Checked with the engine first: the ruler's position phase has one iteration, a nonlinear projection
    // that turns the ruler, so its position_change table has an angular_change[0] row.
    const Trace trace = opened("cases/ruler");
    REQUIRE(item_count(trace.frames[0], Stage::position) == 1);
    REQUIRE(trace.frames[0].position.iterations[0].resolution.has_value());
    const Cursor c =
        resolve_goto(trace, parse_goto("phase=position,step=position_change.angular_change", "--goto"), "--goto");
    CHECK(c == Cursor{0, Stage::position, 0, 3});
    CHECK(step_at(trace, c) == "position_change");
    const std::vector<explain::StepTable> tables = step_tables(trace, c);
    const std::vector<explain::Row>& rows = tables[3].rows;
    CHECK(std::any_of(rows.begin(), rows.end(),
                      [](const explain::Row& r) { return r.quantity == "position_change.angular_change[0]"; }));
    // A step name is taken before a quantity: step=impulse is the impulse table even though the choice shows no
    // impulse and desired_delta_velocity (step 2) precedes it.
    CHECK(resolve_goto(trace, parse_goto("phase=velocity,step=impulse", "g"), "g") == Cursor{0, Stage::velocity, 0, 3});
}

TEST_CASE("a step named without a phase is found in the first stage of the frame that shows it") {
    // The ruler's preparation shows no angular change; its position phase does (the test above): without phase=,
    // the goto lands where the step is, as an iteration without a phase lands in the first phase that has it.
    const Trace trace = opened("cases/ruler");
    CHECK(resolve_goto(trace, parse_goto("step=position_change.angular_change", "g"), "g") ==
          resolve_goto(trace, parse_goto("phase=position,step=position_change.angular_change", "g"), "g"));
    // The preparation still comes first for a step it has.
    CHECK(resolve_goto(trace, parse_goto("step=basis", "g"), "g") == Cursor{0, Stage::preparation, 0, 0});
}

TEST_CASE("a goto step in another phase than the one named says which phase has it") {
    // Regression: a misspelt step was answered with the preparation's list of steps, which does not hold the step
    // meant, so the user could not see the right name.
    const Trace trace = opened("cases/ruler");
    CHECK(goto_error(trace, "phase=velocity,step=position_change").problem() ==
          "no step or quantity \"position_change\" in the velocity phase; it is in the position phase "
          "(phase=position)");
    const std::string misspelt = goto_error(trace, "step=positon_change").problem();
    CHECK(contains(misspelt, "no step or quantity \"positon_change\" in the preparation (its steps: basis, "));
    CHECK(contains(misspelt, "; did you mean \"position_change\", in the position phase (phase=position)?"));
    // A name close to one of this stage's own is suggested without a phase.
    CHECK(contains(goto_error(trace, "phase=velocity,step=impuls").problem(), "did you mean \"impulse\"?"));
    // Nothing near: no suggestion.
    CHECK_FALSE(contains(goto_error(trace, "step=nonsense").problem(), "did you mean"));
}

TEST_CASE("the location of every place leads back to that place") {
    for (const Trace& trace : {opened("cases/ruler"), stack_run(), relaxed("deep_plank")}) {
        for (const Cursor& c : walked_forward(trace)) {
            CAPTURE(describe(trace, c));
            CHECK(nearest_cursor(trace, location_of(trace, c)) == c);
        }
    }
}

TEST_CASE("a location says the frame number, stage, iteration, contact and step by name") {
    const Trace trace = stack_run();
    const Location l = location_of(trace, {1, Stage::velocity, 4, 3});
    CHECK(l.frame_number == 1);
    CHECK(l.stage == Stage::velocity);
    CHECK(l.iteration == 4);
    CHECK(l.contact == 8);
    CHECK(l.step == "impulse");
    const Location p = location_of(trace, {2, Stage::preparation, 5, 4});
    CHECK(p.iteration == 0);
    CHECK(p.contact == 5);
    CHECK(p.step == "desired_delta_velocity");
}

TEST_CASE("a location that no longer exists falls back to the closest place that does") {
    const Trace ruler = opened("cases/ruler");
    // No frame 9: the first place.
    CHECK(nearest_cursor(ruler, Location{9, Stage::velocity, 0, 0, "impulse"}) == *first_cursor(ruler));
    // Velocity iteration 5 of the ruler: its last (only) iteration, on the named step.
    CHECK(nearest_cursor(ruler, Location{0, Stage::velocity, 5, 0, "impulse"}) == Cursor{0, Stage::velocity, 0, 3});
    // A step this item lacks: its first step.
    CHECK(nearest_cursor(ruler, Location{0, Stage::velocity, 0, 0, "basis"}) == Cursor{0, Stage::velocity, 0, 0});
    // Three objects have no position phase: the frame's first stage, keeping the step name where it exists.
    const Trace three = opened("cases/three_objects");
    CHECK(nearest_cursor(three, Location{0, Stage::position, 0, 0, "desired_delta_velocity"}) ==
          Cursor{0, Stage::preparation, 0, 4});
    // A prepared contact past the last one: the last one.
    CHECK(nearest_cursor(three, Location{0, Stage::preparation, 0, 7, "basis"}) == Cursor{0, Stage::preparation, 2, 0});
}

TEST_CASE("a place is described by frame, stage, iteration, contact and step") {
    const Trace trace = stack_run();
    CHECK(describe(trace, {1, Stage::velocity, 4, 3}) ==
          "frame 1 · velocity phase · iteration 4 · contact 8 · impulse");
    CHECK(describe(trace, {2, Stage::preparation, 5, 0}) == "frame 2 · preparation · contact 5 · basis");
}

TEST_CASE("contact_at and preparation_of find a contact by its index in the frame's list") {
    const Trace trace = stack_run();
    const FrameRecord& frame = trace.frames[1];
    CHECK(contact_at(trace, {1, Stage::velocity, 4, 0}) == 8);
    CHECK(contact_at(trace, {1, Stage::preparation, 11, 0}) == 11);
    REQUIRE(preparation_of(frame, 8) != nullptr);
    CHECK(preparation_of(frame, 8)->contact == 8);
    CHECK(preparation_of(frame, 12) == nullptr);
    // With a contact filter, the prepared contacts are only those recorded.
    OpenOptions options;
    options.record = {"contacts=1,2"};
    const Trace filtered = opened("cases/three_objects", options);
    REQUIRE(filtered.frames[0].contacts.size() == 2);
    CHECK(preparation_of(filtered.frames[0], 0) == nullptr);
    CHECK(preparation_of(filtered.frames[0], 2) == &filtered.frames[0].contacts[1]);
}

TEST_CASE("a projected Gauss-Seidel visit shows its sweep, its bias and its accumulated impulse with the clamp") {
    OpenOptions options;
    options.preset = "pgs";
    options.frames = 3;
    const Trace trace = opened("stack_3", options);
    // The first visit of frame 2 that has a derivation: warm-started frames begin with last frame's totals.
    const FrameRecord& frame = trace.frames[2];
    REQUIRE(!frame.velocity.iterations.empty());
    const VelocityIteration& first = frame.velocity.iterations[0];
    REQUIRE(first.sweep);
    CHECK(first.sweep->stage == SolverStage::warm_start);
    const Cursor at{2, Stage::velocity, 0, 0};
    CHECK(table_steps(trace, at) == std::vector<std::string>{"choice", "contact_velocity", "desired_delta_velocity",
                                                             "accumulated", "impulse", "velocity_change", "updates"});
    const explain::StepTable choice = step_tables(trace, at)[0];
    CHECK(choice.title == "choice — warm_start visits contact " + std::to_string(first.contact));
    // Baumgarte's bias is a row of desired_delta_velocity.
    const explain::StepTable desired = step_tables(trace, at)[2];
    CHECK(std::any_of(desired.rows.begin(), desired.rows.end(),
                      [](const explain::Row& r) { return r.quantity == "position_bias"; }));
    const explain::StepTable total = step_tables(trace, at)[3];
    REQUIRE(total.rows.size() == 4);
    CHECK(total.rows[0].quantity == "accumulated.before");
    CHECK(total.rows[2].quantity == "accumulated.clamp");
    CHECK(total.rows[3].quantity == "accumulated.after");
    // A later visit is a solve sweep, and names its pass.
    const auto solve = std::find_if(frame.velocity.iterations.begin(), frame.velocity.iterations.end(),
                                    [](const VelocityIteration& it) { return it.sweep->stage == SolverStage::solve; });
    REQUIRE(solve != frame.velocity.iterations.end());
    const Cursor later{2, Stage::velocity, static_cast<int>(solve - frame.velocity.iterations.begin()), 0};
    CHECK(step_tables(trace, later)[0].title == "choice — solve sweep " + std::to_string(solve->sweep->pass) +
                                                    " visits contact " + std::to_string(solve->contact));
}

namespace {

// Traces that between them hold every kind of table: the book's cases, a velocity-based rewind, relaxation's passes,
// a projected Gauss-Seidel sweep with its accumulated impulse, soft step's sub-steps, friction's solve.
std::vector<Trace> traces_of_every_kind() {
    OpenOptions velocity_based, pgs, soft;
    velocity_based.settings = {"position_method=velocity_based"};
    pgs.settings = {"preset=pgs"};
    soft.settings = {"preset=soft_step"};
    pgs.frames = soft.frames = 2;
    return {opened("cases/ruler"),
            opened("cases/tilted_box", velocity_based),
            relaxed("cases/deep_bar"),
            opened("cases/sliding_box"),
            opened("stack_3", pgs),
            opened("stack_3", soft),
            stack_run()};
}

}  // namespace

TEST_CASE("the navigator's step names, read from the record, are the steps of the tables formatting makes") {
    int items = 0;
    for (const Trace& trace : traces_of_every_kind())
        for (const Cursor& at : every_place(trace)) {
            if (at.step != 0) continue;
            ++items;
            const std::vector<std::string_view> names = step_names(trace, at);
            CHECK(std::vector<std::string>(names.begin(), names.end()) == table_steps(trace, at));
        }
    CHECK(items > 100);
}

TEST_CASE("a goto's step takes every quantity of the word list by its full name or its last part") {
    // Each word shown in some table of these traces is reached by both its names, to a table that shows it; a
    // last part two words share (angular_change: rewind's and position_change's) means the later, the result.
    const std::vector<Trace> traces = traces_of_every_kind();
    std::set<std::string> reached;
    for (const Trace& trace : traces)
        for (const Cursor& at : every_place(trace)) {
            const std::vector<explain::StepTable> tables = step_tables(trace, at);
            for (const explain::Row& row : tables[static_cast<std::size_t>(at.step)].rows) {
                if (row.key.empty() || reached.count(row.key)) continue;
                const std::string where =
                    "frame=" + std::to_string(trace.frames[static_cast<std::size_t>(at.frame)].frame) +
                    ",phase=" + std::string(stage_name(at.stage)) +
                    (at.stage == Stage::preparation ? ",contact=" + std::to_string(contact_at(trace, at))
                                                    : ",iteration=" + std::to_string(at.item));
                std::string full = row.key;
                for (std::size_t b = full.find("[]"); b != std::string::npos; b = full.find("[]")) full.erase(b, 2);
                const std::string last = full.substr(full.rfind('.') == std::string::npos ? 0 : full.rfind('.') + 1);
                for (const std::string& name : {full, last}) {
                    INFO(where << ",step=" << name);
                    const Cursor c = resolve_goto(trace, parse_goto(where + ",step=" + name, "g"), "g");
                    CHECK(c.frame == at.frame);
                    CHECK(c.stage == at.stage);
                    CHECK(c.item == at.item);
                    const auto rows = step_tables(trace, c)[static_cast<std::size_t>(c.step)].rows;
                    const bool shows = std::any_of(rows.begin(), rows.end(), [&](const explain::Row& r) {
                        return r.key == row.key || (name == last && r.key.ends_with("." + last));
                    });
                    CHECK_MESSAGE(shows, "lands on " << step_at(trace, c) << ", which does not show it");
                }
                reached.insert(row.key);
            }
        }
    CHECK(reached.size() > 60);
    const Trace ruler = opened("cases/ruler");
    CHECK(resolve_goto(ruler, parse_goto("phase=position,step=angular_change", "g"), "g") ==
          resolve_goto(ruler, parse_goto("phase=position,step=position_change.angular_change", "g"), "g"));
    CHECK(step_at(ruler, resolve_goto(ruler, parse_goto("phase=velocity,step=impulse_world[1]", "g"), "g")) ==
          "impulse");
    CHECK(goto_error(ruler, "phase=position,step=angular_chnage")
              .problem()
              .ends_with("did you mean \"angular_change\"?"));
}

TEST_CASE("an AVBD iteration is a sweep over the bodies: each body visit's tables, then each contact's dual update") {
    OpenOptions options;
    options.frames = 2;
    options.settings = {"preset=avbd"};
    const Trace trace = opened("mass_ratio_100", options);
    const FrameRecord& frame = trace.frames.back();
    const int f = static_cast<int>(trace.frames.size()) - 1;
    // Iteration 0: the light box (body 0) with its eight contacts; 1: the heavy box; 2..9: the dual updates.
    const Cursor body{f, Stage::velocity, 0, 0};
    CHECK(table_steps(trace, body) ==
          std::vector<std::string>{"choice", "constraint", "force", "block_matrix", "block_force", "position_change"});
    const std::vector<explain::StepTable> tables = step_tables(trace, body);
    CHECK(tables[0].title == "choice — solve sweep 0 visits body 0");
    CHECK(tables[1].rows.size() == 8);      // one C* per gathered contact
    CHECK(tables[2].rows.size() == 3 * 8);  // lambda, k and F of each
    CHECK(tables[2].rows[2].key == "gathered[].force");
    CHECK(tables[2].rows[2].quantity == "gathered[0].force");
    CHECK(contains(tables[2].rows[2].meaning, "contact 0"));
    CHECK(tables[2].rows[2].formula == "F_n = max(λ_n − k_n C*_n, 0); |F_t| ≤ μ F_n");
    // The 6x6 block spans six lines, the move is in metres.
    CHECK(std::count(tables[3].rows[0].value.begin(), tables[3].rows[0].value.end(), '\n') == 5);
    CHECK(tables[5].rows[0].key == "position_change.linear_change");
    CHECK(tables[5].rows[0].equation == "(4)");
    CHECK(describe(trace, {f, Stage::velocity, 0, 5}) ==
          "frame " + std::to_string(frame.frame) + " · velocity phase · iteration 0 · body 0 · position_change");

    const Cursor dual{f, Stage::velocity, 2, 0};
    CHECK(table_steps(trace, dual) == std::vector<std::string>{"choice", "constraint", "force", "dual_update"});
    CHECK(step_tables(trace, dual)[0].title == "choice — dual sweep 0 updates contact 0");
    // The dual sweep's places in order: after the last contact's dual update, the next sweep's first body visit.
    Cursor at{f, Stage::velocity, 9, 3};
    at = *next_step(trace, at);
    CHECK(at == Cursor{f, Stage::velocity, 10, 0});
    CHECK(frame.velocity.iterations[10].body_visit->body == 0);
    // A goto names AVBD's steps and words.
    CHECK(step_at(trace, resolve_goto(trace, parse_goto("phase=velocity,iteration=0,step=block_force", "--goto"),
                                      "--goto")) == "block_force");
    CHECK(step_at(trace, resolve_goto(trace, parse_goto("phase=velocity,iteration=2,step=lambda", "--goto"),
                                      "--goto")) == "force");
    // Walking it forward and back visits every table once.
    const std::vector<Cursor> forward = walked_forward(trace);
    CHECK(forward == every_place(trace));
    std::vector<Cursor> back = walked_back(trace);
    std::reverse(back.begin(), back.end());
    CHECK(back == forward);
}
