#pragma once
// A trace's places walked by the navigator, for the navigator's tests (tests/inspector/test_navigator*.cpp): the
// traces they walk, every place enumerated from the recording's shape alone, the walks forward and back, and the
// error a --goto raises.

#include "formats/input_error.hpp"
#include "model/navigator.hpp"
#include "model/session.hpp"

#include "support/opened.hpp"
#include "support/read_text.hpp"

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace impulse::test {

// Three frames of the stack, with `settings` as --set gives them: enough for moves to cross frames, small enough to
// walk every step.
inline Trace stack_run(std::vector<std::string> settings = {}) {
    model::OpenOptions options;
    options.frames = 3;
    options.settings = std::move(settings);
    return opened("stack_3", options);
}

// A shipped case or scene with the position phase relaxed: several passes, so the same contact is chosen
// more than once. Of deep_plank only the first frame, where its plank lands on four corners.
inline Trace relaxed(const std::string& name) {
    model::OpenOptions options;
    options.settings = {"position_method=relaxation"};
    if (name == "deep_plank") options.frames = 1;
    return opened(name, options);
}

// Every place in the trace, enumerated from the recording's shape alone (frames, their stages in the order
// they ran, items, tables), without using any move.
inline std::vector<model::Cursor> every_place(const Trace& trace) {
    std::vector<model::Cursor> places;
    for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f) {
        const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
        std::vector<model::Stage> order{model::Stage::preparation};
        if (frame.phase_order == PhaseOrder::positions_first)
            order.insert(order.end(), {model::Stage::position, model::Stage::velocity});
        else
            order.insert(order.end(), {model::Stage::velocity, model::Stage::position});
        for (model::Stage stage : order) {
            const std::size_t items = stage == model::Stage::preparation ? frame.contacts.size()
                                      : stage == model::Stage::position  ? frame.position.iterations.size()
                                                                         : frame.velocity.iterations.size();
            for (int item = 0; item < static_cast<int>(items); ++item) {
                const model::Cursor at{f, stage, item, 0};
                const int steps = static_cast<int>(model::step_tables(trace, at).size());
                for (int step = 0; step < steps; ++step) places.push_back({f, stage, item, step});
            }
        }
    }
    return places;
}

inline std::vector<model::Cursor> walked_forward(const Trace& trace) {
    std::vector<model::Cursor> walk;
    for (std::optional<model::Cursor> c = model::first_cursor(trace); c; c = model::next_step(trace, *c)) {
        walk.push_back(*c);
        REQUIRE(walk.size() < 100000);  // a move that never reaches the end would loop here
    }
    return walk;
}

inline std::vector<model::Cursor> walked_back(const Trace& trace) {
    std::vector<model::Cursor> walk;
    for (std::optional<model::Cursor> c = model::last_cursor(trace); c; c = model::previous_step(trace, *c)) {
        walk.push_back(*c);
        REQUIRE(walk.size() < 100000);
    }
    return walk;
}

inline std::vector<std::string> table_steps(const Trace& trace, const model::Cursor& cursor) {
    std::vector<std::string> names;
    for (const explain::StepTable& t : model::step_tables(trace, cursor)) names.push_back(t.step);
    return names;
}

inline std::string step_at(const Trace& trace, const model::Cursor& cursor) {
    return model::step_tables(trace, cursor)[static_cast<std::size_t>(cursor.step)].step;
}

// The error resolve_goto (or parse_goto) raises for `text`; fails the test when there is none.
inline formats::InputError goto_error(const Trace& trace, const std::string& text) {
    try {
        model::resolve_goto(trace, model::parse_goto(text, "--goto"), "--goto");
    } catch (const formats::InputError& e) {
        return e;
    }
    FAIL("--goto " << text << " was accepted");
    return formats::InputError("", "");
}

}  // namespace impulse::test
