// The inspector's navigator: a trace read as frame -> stage -> item -> step, and the moves over it. Stepping
// forward visits every table once, stepping back retraces it exactly, the coarser moves land where their
// names say, and a place named by a person (--goto) or remembered across a re-run comes back to the same
// table.

#include "formats/input_error.hpp"
#include "model/navigator.hpp"
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

using namespace impulse::test;

formats::InputError parse_error(const std::string& text, const std::string& where) {
    try {
        parse_goto(text, where);
    } catch (const formats::InputError& e) {
        return e;
    }
    FAIL("\"" << text << "\" parsed");
    return formats::InputError("", "");
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
