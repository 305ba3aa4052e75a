// The vocabulary: one row per quantity with the step that computes it and the quantities it is computed from.
// Its inputs are what a lesson's open question hides by (everything computed from the answer), so they must
// name rows and never loop, and every row the tables show must be in it. And the numbers as shown: rounding
// noise as 0, every digit kept for exports, percentages with three significant figures.

#include "explain/annotations.hpp"
#include "explain/format.hpp"
#include "model/navigator.hpp"
#include "settings/settings.hpp"
#include "support/opened.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>

namespace impulse::test {

TEST_CASE("every vocabulary row has a step, a unique name, and inputs that are rows") {
    std::set<std::string_view> names;
    for (const explain::Annotation& a : explain::vocabulary()) {
        INFO(a.quantity);
        CHECK(names.insert(a.quantity).second);
        CHECK_FALSE(a.step.empty());
        for (std::string_view input : explain::inputs_of(a)) {
            INFO(input);
            CHECK(explain::find_annotation(input) != nullptr);
        }
    }
}

TEST_CASE("no quantity is computed from itself, however far its consumers reach") {
    for (const explain::Annotation& a : explain::vocabulary()) {
        const std::vector<std::string_view> later = explain::consumers(a.quantity);
        INFO(a.quantity);
        CHECK(std::find(later.begin(), later.end(), a.quantity) == later.end());
    }
    // By hand: the desired Δv feeds the impulse (14.3), the impulse the velocity change (7.5) and the
    // bodies; it is not an input of the basis or of d.
    const std::vector<std::string_view> from_desired = explain::consumers("desired_delta_velocity");
    for (std::string_view c : {"impulse", "impulse_world", "velocity_change", "bodies_after"})
        CHECK(std::find(from_desired.begin(), from_desired.end(), c) != from_desired.end());
    for (std::string_view c : {"basis", "delta_velocity_per_unit_impulse", "separating_velocity"})
        CHECK(std::find(from_desired.begin(), from_desired.end(), c) == from_desired.end());
}

TEST_CASE("every row of every table of the shipped cases under every preset is a vocabulary row") {
    for (const char* name : {"cases/ruler", "cases/sliding_box", "cases/tilted_box", "cases/three_objects_drawn",
                             "cases/oblique_friction", "stack_3"}) {
        for (std::string_view preset : preset_names()) {
            model::OpenOptions options;
            options.preset = std::string(preset);
            options.frames = 2;
            const std::string file(name);
            if (file.starts_with("cases/")) options.frames.reset();
            const Trace trace = opened(file, options);
            for (std::size_t f = 0; f < trace.frames.size(); ++f)
                for (model::Stage stage : model::stages(trace.frames[f]))
                    for (int i = 0; i < model::item_count(trace.frames[f], stage); ++i)
                        for (const explain::StepTable& t :
                             model::step_tables(trace, model::Cursor{static_cast<int>(f), stage, i, 0}))
                            for (const explain::Row& r : t.rows) {
                                INFO(name << " " << preset << " " << t.step << " " << r.quantity);
                                REQUIRE(explain::find_annotation(r.key) != nullptr);
                                CHECK(explain::annotation(r.key).step.size() > 0);
                            }
        }
    }
}

TEST_CASE("a question's path names its quantity, with the item it is read in") {
    using explain::ItemKind;
    const auto name = [](std::string_view path, ItemKind item) {
        const explain::Annotation* a = explain::quantity_of_path(path, item);
        return a ? std::string(a->quantity) : std::string("none");
    };
    CHECK(name("desired_delta_velocity", ItemKind::contact) == "desired_delta_velocity");
    CHECK(name("impulse[0]", ItemKind::velocity_iteration) == "impulse");
    CHECK(name("updates[0].after[0]", ItemKind::velocity_iteration) == "velocity_update");
    CHECK(name("updates[2].after", ItemKind::position_iteration) == "penetration_update");
    CHECK(name("rewind.time", ItemKind::position_iteration) == "rewind.time");
    CHECK(name("friction_solve.delta_velocity_matrix[1][1]", ItemKind::velocity_iteration) ==
          "friction_solve.delta_velocity_matrix");
    CHECK(name("angular_limit.applied[0]", ItemKind::position_iteration) == "angular_limit.applied");
    CHECK(name("angular_limit.maximum[0]", ItemKind::position_iteration) == "angular_limit.maximum");
    CHECK(name("move_split.linear_move[1]", ItemKind::position_iteration) == "move_split.linear_move");
    CHECK(name("impulse[0]", ItemKind::contact) == "none");  // a prepared contact has no impulse
    CHECK(name("no_such_key", ItemKind::contact) == "none");
}

TEST_CASE("rounding noise prints as 0 beside the values it sits with, and every digit stays in the exact text") {
    // 1.11e-16 beside 0.5: below 1e-10 of the scale, noise.
    CHECK(explain::number(1.1102230246251565e-16, 0.5) == "0");
    CHECK(explain::vector(Vec3(1.1102230246251565e-16, -0.5, 0.25)) == "(0, -0.5, 0.25)");
    // A small value on its own, or beside values of its own size, is a value: its exponent is kept.
    CHECK(explain::number(2.7755575615628914e-17) == "2.77556e-17");
    CHECK(explain::number(5.21387e-07, 1.0) == "5.21387e-07");
    CHECK(explain::exact(0.1 + 0.2) == "0.30000000000000004");
    // Percentages with three significant figures: 1/15 is 6.67 %, not 6.66667 %.
    CHECK(explain::percent(100.0 / 15.0) == "6.67");
    CHECK(explain::percent(100.0 / 3.0) == "33.3");
    CHECK(explain::percent(1250.0) == "1250");
}

}  // namespace impulse::test
