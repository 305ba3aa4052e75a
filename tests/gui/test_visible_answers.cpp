// Predict, then see, as the screen shows it: every step of every lesson laid out as the student meets it (the
// questions before it answered, the later ones open), with each tab of the lesson's panel in front in turn, and
// every piece of text the frame draws — the tables and their other-frame readings, the contacts, the bodies, the
// navigator, the plots' labels, the scene's labels, the toolbar — read back from ImGui's own draw data
// (gui/visible_text.hpp) and searched for each open question's answer as the tables print it. Left out: the
// lesson's own panel (the author's words: a prompt gives the inputs) and numbers that label things rather than
// measure them (step 3, contact 2, iteration 0, eq. 7.5, 4 contacts, the contacts list's # column).

#include "explain/annotations.hpp"
#include "explain/format.hpp"
#include "gui/layout_check.hpp"
#include "gui/visible_text.hpp"
#include "course/lesson.hpp"
#include "course/lesson_run.hpp"
#include "course/mask.hpp"
#include "model/replay.hpp"

#include <doctest/doctest.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

namespace impulse::test {

namespace {

bool word_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// The word before position `at` of `text` ("contact" in "contact 3"), and the one after `end`.
std::string word_before(const std::string& text, std::size_t at) {
    std::size_t end = at;
    while (end > 0 && text[end - 1] == ' ') --end;
    std::size_t start = end;
    while (start > 0 && text[start - 1] != ' ' && text[start - 1] != '(') --start;
    return text.substr(start, end - start);
}
std::string word_after(const std::string& text, std::size_t end) {
    while (end < text.size() && text[end] == ' ') ++end;
    std::size_t stop = end;
    while (stop < text.size() && text[stop] != ' ' && text[stop] != ')' && text[stop] != ',') ++stop;
    return text.substr(end, stop - end);
}

// The numbers of a run that are values: not a name's index (impulse[0], t1), nor a label's number.
std::vector<std::string> value_tokens(const std::string& text) {
    static const std::set<std::string> label_before{
        "step",  "Step",   "steps", "contact", "contacts", "iteration", "iterations", "frame",
        "Frame", "frames", "sweep", "pass",    "Lesson",   "lesson",    "body",       "sub-step",
        "of",    "eq.",    "ch.",   "#",       "option",   "sub-steps", "passes"};
    static const std::set<std::string> label_after{"contact", "contacts", "iteration", "iterations",
                                                   "of",      "steps",    "frames",    "·"};
    std::vector<std::string> tokens;
    for (std::size_t i = 0; i < text.size();) {
        const bool sign =
            text[i] == '-' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]));
        if (!std::isdigit(static_cast<unsigned char>(text[i])) && !sign) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        if (sign) ++i;
        while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.' ||
                                   text[i] == 'e' || ((text[i] == '-' || text[i] == '+') && text[i - 1] == 'e')))
            ++i;
        std::string token = text.substr(start, i - start);
        while (!token.empty() && (token.back() == '.' || token.back() == 'e')) token.pop_back();
        const bool in_name = (start > 0 && (word_char(text[start - 1]) ||
                                            (text[start - 1] == '[' && start > 1 && word_char(text[start - 2])))) ||
                             (i < text.size() && word_char(text[i]));  // "3D", "t1"
        const bool label = label_before.count(word_before(text, start)) || label_after.count(word_after(text, i));
        if (!in_name && !label) tokens.push_back(token);
    }
    return tokens;
}

// The units a run names ("(0.4, 0.3, 0) m" names m): a number beside another unit is another quantity.
std::set<std::string> units_in(std::string text) {
    static const std::vector<std::string> units = [] {
        std::vector<std::string> all;
        for (const explain::Annotation& a : explain::vocabulary())
            if (!a.unit.empty() && std::find(all.begin(), all.end(), a.unit) == all.end()) all.emplace_back(a.unit);
        all.push_back("N·s");
        // The longest first: "m/s per N·s" before "m/s", "m/s" before "m".
        std::sort(all.begin(), all.end(),
                  [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
        return all;
    }();
    std::set<std::string> found;
    for (const std::string& unit : units)
        for (std::size_t at = text.find(unit); at != std::string::npos; at = text.find(unit, at + 1)) {
            const std::size_t end = at + unit.size();
            const bool whole = (at == 0 || text[at - 1] == ' ') &&
                               (end == text.size() || text[end] == ' ' || text[end] == ')' || text[end] == ',');
            if (!whole) continue;
            found.insert(unit);
            text.replace(at, unit.size(), std::string(unit.size(), '#'));  // not found again inside a longer one
        }
    return found;
}

struct Open {
    int step;
    std::string shown;  // as the tables print it: "7.5", "-0.162232"
    std::string unit;   // "m/s"
    // A small whole number (1, 3, −2) is also a basis entry, a count or a coordinate of many things: it counts
    // as this answer only beside the answer's unit. Any number beside another unit is another quantity.
    bool needs_unit;
};

// Whether a question's answer, as printed, is one of the numbers its inputs in its unit show through `mask` (in
// their own frame) at its place, or the bodies' states going in: what the student is meant to work from.
bool given_by_inputs(const course::PreparedLesson& lesson,
                     const std::vector<std::optional<course::QuestionReach>>& reaches, const course::Mask& mask,
                     const Open& o) {
    const auto& reach = reaches[static_cast<std::size_t>(o.step)];
    if (!reach) return false;
    const Trace& trace = lesson.session.trace();
    const model::Cursor& place = lesson.places[static_cast<std::size_t>(o.step)];
    std::vector<std::string> given;
    for (const explain::StepTable& table : model::step_tables(trace, place))
        for (const explain::Row& row : table.rows)
            if (reach->inputs.count(row.key) && !mask.hides_row(place, row) &&
                explain::annotation(row.key).unit == o.unit)
                for (const std::string& token : value_tokens(row.value)) given.push_back(token);
    const model::BodiesAtCursor bodies = model::bodies_at(trace, place);
    for (std::size_t i = 0; i < bodies.before.size(); ++i) {
        const BodyState& b = bodies.before[i];
        if (mask.hides_body(place, static_cast<int>(i), false, b)) continue;
        const Vec3& state = o.unit == "m/s" ? b.velocity : o.unit == "m" ? b.position : b.angular_velocity;
        if (o.unit != "m/s" && o.unit != "m" && o.unit != "rad/s") continue;
        for (const std::string& token : value_tokens(explain::vector(state))) given.push_back(token);
    }
    return std::find(given.begin(), given.end(), o.shown) != given.end();
}

}  // namespace

TEST_CASE("no open question's answer is visible anywhere in the window, at any step of any lesson, in any tab") {
    const std::vector<std::filesystem::path> files = course::lesson_files(IMPULSE_SOURCE_DIR "/lessons");
    REQUIRE(files.size() == 14);
    int frames = 0, searched = 0;
    std::set<std::string> excused;
    for (const std::filesystem::path& file : files) {
        course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson(file));
        const auto reaches = course::question_reaches(lesson, lesson.session.trace());
        gui::OffscreenLayout layout(1280, 800);
        const gui::TextReader reader(*ImGui::GetIO().Fonts);
        gui::UiState state;
        state.lesson.emplace(course::LessonRun(lesson, nullptr, std::nullopt), true);
        layout.frame(lesson.session, state);
        const int steps = state.lesson->run.step_count();
        for (int k = 0; k < steps; ++k) {
            // The answers still open at step k (a 0 is everywhere and gives nothing away).
            std::vector<Open> open;
            for (int q = k; q < steps; ++q) {
                const course::Step& s = lesson.lesson.steps[static_cast<std::size_t>(q)];
                if (!s.question || s.question->kind != course::Question::Kind::predict) continue;
                const double value = lesson.answers[static_cast<std::size_t>(q)]->value.get<double>();
                const double allowed = std::max(s.question->tolerance.relative.value_or(0) * std::abs(value),
                                                s.question->tolerance.absolute.value_or(0));
                const course::Answer& a = *lesson.answers[static_cast<std::size_t>(q)];
                if (std::abs(value) > allowed)
                    open.push_back(
                        {q, explain::number(value), a.unit, value == std::round(value) && std::abs(value) < 10});
            }
            // An answer that its own inputs show as it is stays in view with them: the box's world velocity
            // (3, −2, 0) m/s, which the question gives, has the slip along tangent 2 = world x as a part.
            gui::go_to_lesson_step(lesson.session, state, k);  // with every question before it answered
            std::erase_if(open, [&](const Open& o) {
                if (!given_by_inputs(lesson, reaches, state.mask, o)) return false;
                excused.insert(file.filename().string().substr(0, 2) + " step " + std::to_string(o.step + 1));
                return true;
            });
            for (const char* tab : {"Contacts", "Bodies", "Plots", "Navigator", "Settings", "Export"}) {
                state.show_tab = tab;
                layout.frame(lesson.session, state);  // the tab comes to the front at the next frame
                layout.frame(lesson.session, state);
                frames += 2;
                std::map<std::pair<std::string, float>, int> line_runs;  // runs seen per window and line
                for (const gui::VisibleRun& run : reader.read(*ImGui::GetDrawData())) {
                    const int index = line_runs[{run.window, run.y}]++;
                    if (run.window == "Lesson" || run.window.starts_with("Lesson/")) continue;
                    std::vector<std::string> tokens = value_tokens(run.text);
                    const std::set<std::string> units = units_in(run.text);
                    // The contacts list's first column is the contact's number.
                    if (std::string(tab) == "Contacts" && run.window.find("contacts") != std::string::npos &&
                        index == 0 && tokens.size() == 1 && tokens[0].find('.') == std::string::npos)
                        continue;
                    for (const std::string& token : tokens) {
                        ++searched;
                        for (const Open& o : open)
                            if (token == o.shown && (units.empty() ? !o.needs_unit : units.count(o.unit) > 0))
                                FAIL_CHECK(file.filename().string()
                                           << " at step " << k + 1 << ", " << std::string(tab) << " in front: step "
                                           << o.step + 1 << "'s answer " << o.shown << " shows in " << run.window
                                           << ": \"" << run.text << "\"");
                    }
                }
            }
        }
    }
    std::string left_out;
    for (const std::string& e : excused) left_out += (left_out.empty() ? "" : ", ") + e;
    MESSAGE(frames << " frames laid out, " << searched << " numbers read off them; answers shown by their own inputs, "
                   << "left out: lesson " << left_out);
    CHECK(searched > 5000);
}

TEST_CASE("the text read back from a frame is the text drawn, combining marks and clipped cells included") {
    course::PreparedLesson lesson =
        course::prepare_lesson(course::read_lesson(course::lesson_files(IMPULSE_SOURCE_DIR "/lessons").front()));
    gui::OffscreenLayout layout(1280, 800);
    gui::UiState state;
    state.lesson.emplace(course::LessonRun(lesson, nullptr, std::nullopt), true);
    layout.frame(lesson.session, state);
    gui::go_to_lesson_step(lesson.session, state, 2);  // delta_velocity_per_unit_impulse: Δθ̇ in its formulas
    layout.frame(lesson.session, state);
    layout.frame(lesson.session, state);
    std::string all;
    for (const gui::VisibleRun& run : gui::TextReader(*ImGui::GetIO().Fonts).read(*ImGui::GetDrawData()))
        all += run.window + ": " + run.text + "\n";
    INFO(all);
    CHECK(all.find("Derivation") != std::string::npos);
    CHECK(all.find("Δθ̇ = I⁻¹ u") != std::string::npos);
    CHECK(all.find("Lesson: Lesson 1 · An impulse is an instant change of velocity") != std::string::npos);
    CHECK(value_tokens("iteration 3 → contact 1 (Δv 7.5 m/s)") == std::vector<std::string>{"7.5"});
    CHECK(value_tokens("impulse[0] (0, -0.5, 3) eq. 14.3 [5.8, 1.2]") ==
          std::vector<std::string>{"0", "-0.5", "3", "5.8", "1.2"});
}

}  // namespace impulse::test
