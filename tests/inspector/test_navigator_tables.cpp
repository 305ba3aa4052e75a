// The navigator's tables of each kind of iteration: a projected Gauss-Seidel visit with its sweep and clamp, AVBD's
// body visits and dual updates, and the step names (read from the record, not by formatting) and word-list names a
// --goto takes. The moves themselves: test_navigator.cpp.

#include "model/navigator.hpp"
#include "model/session.hpp"

#include "support/navigator_places.hpp"
#include "support/opened.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

using namespace impulse;
using namespace impulse::model;
using namespace impulse::test;

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

TEST_CASE("a sweep's choice table names the order it visits in: index, colour, or colour four pairs at a time") {
    // (Not a structured binding: Debian 12's clang 14 does not capture one in doctest's CAPTURE.)
    for (const std::pair<std::string, std::string>& run :
         {std::pair<std::string, std::string>{"soft_step_recycled", "next in index order"},
          std::pair<std::string, std::string>{"soft_step_coloured", "next in colour order"},
          std::pair<std::string, std::string>{"soft_step_wide", "next in colour order, four pairs side by side"}}) {
        const std::string& preset = run.first;
        const std::string& formula = run.second;
        CAPTURE(preset);
        OpenOptions options;
        options.preset = preset;
        options.frames = 2;
        const Trace trace = opened("stack_3", options);
        const explain::StepTable choice = step_tables(trace, Cursor{1, Stage::velocity, 0, 0})[0];
        const auto contact = std::find_if(choice.rows.begin(), choice.rows.end(),
                                          [](const explain::Row& r) { return r.quantity == "contact"; });
        REQUIRE(contact != choice.rows.end());
        CHECK(contact->formula == formula);
    }
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
