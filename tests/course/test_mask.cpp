// Predict, then see: at every step of every shipped lesson, as the student meets it (the questions before it
// answered, it and those after open), no value the window or the terminal shows anywhere in the recording (any
// table of any item, the contacts list, the bodies) equals an open question's answer, unless it is one of the
// answer's inputs (what the student computes it from). And the giveaways the issue found stay hidden.

#include "explain/annotations.hpp"
#include "course/lesson_run.hpp"
#include "course/mask.hpp"
#include "model/replay.hpp"
#include "support/shipped.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

namespace impulse::test {

namespace {

using model::Cursor;
using model::Stage;

using impulse::test::shipped_lessons;

course::PreparedLesson lesson_number(int n) {
    for (const std::filesystem::path& file : course::lesson_files(shipped_lessons))
        if (std::atoi(file.filename().string().c_str()) == n) return course::prepare_lesson(course::read_lesson(file));
    FAIL("no lesson " << n);
    throw std::logic_error("unreachable");
}

// The numbers in a shown text ("(0, -0.5, 0) m", "v_s -2 → 1 m/s").
std::vector<double> numbers_in(const std::string& text) {
    std::vector<double> found;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        const bool starts =
            std::isdigit(static_cast<unsigned char>(c)) ||
            ((c == '-' || c == '.') && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])));
        if (!starts) {
            ++i;
            continue;
        }
        char* end = nullptr;
        found.push_back(std::strtod(text.c_str() + i, &end));
        i = static_cast<std::size_t>(end - text.c_str());
    }
    return found;
}

std::vector<Cursor> all_items(const Trace& trace) {
    std::vector<Cursor> items;
    for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f)
        for (Stage stage : model::stages(trace.frames[static_cast<std::size_t>(f)]))
            for (int i = 0; i < model::item_count(trace.frames[static_cast<std::size_t>(f)], stage); ++i)
                items.push_back(Cursor{f, stage, i, 0});
    return items;
}

// Everything a quantity is computed from, directly or through others.
std::set<std::string> upstream(std::string_view quantity) {
    std::set<std::string> found;
    std::vector<std::string_view> todo = explain::inputs_of(explain::annotation(quantity));
    while (!todo.empty()) {
        const std::string_view name = todo.back();
        todo.pop_back();
        if (!found.insert(std::string(name)).second) continue;
        if (const explain::Annotation* a = explain::find_annotation(name))
            for (std::string_view next : explain::inputs_of(*a)) todo.push_back(next);
    }
    return found;
}

// Everything the panels can show anywhere in the recording, before any mask: each table row of each item,
// each contact's values in the contacts list at each item, each body's state before and after each item.
struct Cells {
    struct TableRow {
        Cursor item;
        std::string where;
        explain::Row row;
    };
    struct ContactValue {
        Cursor item;
        std::string where;
        int contact;
        std::string key;
        double value;
    };
    struct Body {
        Cursor item;
        std::string where;
        int body;
        bool after;
        BodyState state;
    };
    std::vector<TableRow> rows;
    std::vector<ContactValue> contacts;
    std::vector<Body> bodies;
};

// `places`: the questions' items. In a frame of a few hundred items everything is taken. In one of thousands
// (the brick wall's 2700) the tables are taken at every prepared contact, the questions' items and the items
// next to them, and an even sample of 200 iterations, and the contacts list and the bodies at 60 of those:
// enough to see every rule at work, and the test stays at seconds (under AddressSanitizer too).
Cells all_cells(const Trace& trace, const std::vector<Cursor>& places) {
    Cells cells;
    const std::vector<Cursor> items = all_items(trace);
    const bool large = items.size() > 400;
    const std::size_t tables_every = large ? items.size() / 200 : 1;
    const std::size_t every = std::max<std::size_t>(1, items.size() / 60);
    for (std::size_t n = 0; n < items.size(); ++n) {
        const Cursor& item = items[n];
        const bool near_a_place = std::any_of(places.begin(), places.end(), [&](const Cursor& p) {
            return p.frame == item.frame && p.stage == item.stage && std::abs(p.item - item.item) <= 1;
        });
        if (!near_a_place && item.stage != Stage::preparation && n % tables_every != 0) continue;
        const std::string at = "frame " + std::to_string(trace.frames[static_cast<std::size_t>(item.frame)].frame) +
                               " · " + std::string(model::stage_name(item.stage)) + " item " +
                               std::to_string(item.item);
        for (const explain::StepTable& table : model::step_tables(trace, item))
            for (const explain::Row& row : table.rows) cells.rows.push_back({item, at + " · " + row.quantity, row});
        if (!near_a_place && n % every != 0) continue;
        for (const model::ContactRow& c : model::contact_rows(trace, item)) {
            const std::string where = at + " · contacts list, contact " + std::to_string(c.contact);
            cells.contacts.push_back({item, where, c.contact, "penetration", c.penetration});
            cells.contacts.push_back({item, where, c.contact, "desired_delta_velocity", c.desired_delta_velocity});
            cells.contacts.push_back({item, where, c.contact, "impulse_world", c.impulse_so_far.norm()});
        }
        const model::BodiesAtCursor bodies = model::bodies_at(trace, item);
        for (std::size_t b = 0; b < bodies.after.size(); ++b)
            for (const bool after : {false, true})
                cells.bodies.push_back({item,
                                        at + " · bodies, " + trace.scene.body_names[b] + (after ? " after" : " before"),
                                        static_cast<int>(b), after, after ? bodies.after[b] : bodies.before[b]});
    }
    return cells;
}

// Calls `visit(where, key, unit, value)` for every number the panels show through the mask.
template <typename Visit>
void for_each_shown(const Cells& cells, const course::Mask& mask, Visit visit) {
    for (const Cells::TableRow& r : cells.rows) {
        if (mask.hides_row(r.item, r.row)) continue;
        const std::string_view unit = explain::annotation(r.row.key).unit;
        for (double v : numbers_in(r.row.exact)) visit(r.where, r.row.key, unit, v);
        for (double v : numbers_in(r.row.other_frame)) visit(r.where + " (other frame)", r.row.key, unit, v);
    }
    for (const Cells::ContactValue& c : cells.contacts)
        if (!mask.hides_value(c.item, c.contact, c.key, c.value))
            visit(c.where, c.key, c.key == "impulse_world" ? "N·s" : explain::annotation(c.key).unit, c.value);
    for (const Cells::Body& b : cells.bodies) {
        if (mask.hides_body(b.item, b.body, b.after, b.state)) continue;
        for (int k = 0; k < 3; ++k) {
            visit(b.where + " position", "body_position", "m", b.state.position[k]);
            visit(b.where + " velocity", "body_velocity", "m/s", b.state.velocity[k]);
            visit(b.where + " ω", "body_angular_velocity", "rad/s", b.state.angular_velocity[k]);
        }
    }
}

}  // namespace

TEST_CASE("at every step of every lesson no value shown anywhere equals an open question's answer, but its inputs") {
    for (const std::filesystem::path& file : course::lesson_files(shipped_lessons)) {
        const course::PreparedLesson prepared = course::prepare_lesson(course::read_lesson(file));
        const Trace& trace = prepared.session.trace();
        const auto reaches = course::question_reaches(prepared, trace);
        const Cells cells = all_cells(trace, prepared.places);
        course::LessonRun run(prepared, nullptr, std::nullopt);
        for (int k = 0; k < run.step_count(); ++k) {
            run.answered_before(k);
            const course::Mask mask(reaches, run.open(), trace);
            struct Open {
                int step;
                const course::Answer* answer;
                double value, allowed;
                std::set<std::string> inputs;
            };
            std::vector<Open> open;
            for (int q = k; q < run.step_count(); ++q) {
                const course::Step& step = prepared.lesson.steps[static_cast<std::size_t>(q)];
                if (!step.question || step.question->kind != course::Question::Kind::predict) continue;
                const course::Answer& answer = *prepared.answers[static_cast<std::size_t>(q)];
                const double value = answer.value.get<double>();
                const double allowed = std::max(step.question->tolerance.relative.value_or(0) * std::abs(value),
                                                step.question->tolerance.absolute.value_or(0));
                // An answer of 0 (within its tolerance) is not given away by a zero: they are everywhere.
                if (std::abs(value) > allowed) open.push_back({q, &answer, value, allowed, upstream(answer.quantity)});
            }
            for_each_shown(cells, mask,
                           [&](const std::string& where, std::string_view key, std::string_view unit, double shown) {
                               for (const Open& o : open) {
                                   if (unit != o.answer->unit || o.inputs.count(std::string(key)) ||
                                       std::abs(shown - o.value) > o.allowed)
                                       continue;
                                   FAIL_CHECK(file.filename().string()
                                              << " at step " << k + 1 << ": the answer of step " << o.step + 1 << " ("
                                              << o.answer->shown << ", " << o.answer->quantity << ") shows as " << shown
                                              << " in " << where);
                               }
                           });
        }
    }
}

TEST_CASE("lesson 1's giveaways stay hidden until their questions are answered") {
    const course::PreparedLesson prepared = lesson_number(1);
    const Trace& trace = prepared.session.trace();
    const auto reaches = course::question_reaches(prepared, trace);
    course::LessonRun run(prepared, nullptr, std::nullopt);
    const Cursor preparation{0, Stage::preparation, 0, 0}, iteration{0, Stage::velocity, 0, 0};
    const auto row = [](const char* key) {
        explain::Row r;
        r.key = key;
        return r;
    };
    // At step 1 the contacts list showed Δv 7.5 (step 5's answer); three presses of → showed the impulse
    // 15 N·s (step 6's) and the ball's velocity after (step 8's).
    const course::Mask first(reaches, run.open(), trace);
    CHECK(first.hides_value(preparation, 0, "desired_delta_velocity", 7.5));
    CHECK(first.hides_row(iteration, row("impulse")));
    CHECK(first.hides_row(iteration, row("impulse_world")));
    CHECK(first.hides_row(iteration, row("velocity_change")));
    CHECK(first.hides_body(iteration, 0, true));
    CHECK_FALSE(first.hides_body(iteration, 0, false));  // the ball as it comes in is what the lesson starts from
    // At step 5, with Δv open and d answered: g = Δv / d would give Δv away in one multiplication.
    run.answered_before(4);
    const course::Mask fifth(reaches, run.open(), trace);
    CHECK(fifth.hides_row(preparation, row("desired_delta_velocity")));
    CHECK_FALSE(fifth.hides_row(preparation, row("delta_velocity_per_unit_impulse")));
    CHECK(fifth.hides_row(iteration, row("impulse")));
    CHECK_FALSE(fifth.hides_row(preparation, row("separating_velocity")));  // what Δv is computed from
    // All answered: nothing hidden.
    run.answered_before(run.step_count());
    const course::Mask none(reaches, run.open(), trace);
    CHECK_FALSE(none.hides_row(iteration, row("impulse")));
    CHECK_FALSE(none.hides_body(iteration, 0, true));
}

TEST_CASE("lesson 3's first question hides the normal its swap reversed, and its bodies' order") {
    const course::PreparedLesson prepared = lesson_number(3);
    const Trace& trace = prepared.session.trace();
    const auto reaches = course::question_reaches(prepared, trace);
    course::LessonRun run(prepared, nullptr, std::nullopt);
    const course::Mask mask(reaches, run.open(), trace);
    explain::Row normal;
    normal.key = "normal";
    CHECK(mask.hides_row(Cursor{0, Stage::preparation, 0, 0}, normal));
    CHECK(mask.hides_bodies_of(0, 0));
    CHECK_FALSE(mask.hides_bodies_of(0, 1));  // the ruler's contact was written the usual way round
}

TEST_CASE("lesson 3's last answer, the same bounce at every contact, is hidden at the other two contacts too") {
    const course::PreparedLesson prepared = lesson_number(3);
    const Trace& trace = prepared.session.trace();
    const auto reaches = course::question_reaches(prepared, trace);
    const std::size_t last = prepared.lesson.steps.size() - 1;
    REQUIRE(reaches[last]);
    // The three contacts (light 0, ruler 1, dumbbell 2) all leave at −c·v_s = 1 m/s.
    CHECK(reaches[last]->contacts == std::set<int>{0, 1, 2});
    explain::Row update;
    update.key = "velocity_update";
    std::vector<bool> open(prepared.lesson.steps.size(), false);
    open[last] = true;
    const course::Mask mask(reaches, open, trace);
    CHECK(mask.hides_row(Cursor{0, Stage::velocity, 0, 0}, update));
}

}  // namespace impulse::test
