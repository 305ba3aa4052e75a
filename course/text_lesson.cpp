#include "course/text_lesson.hpp"

#include "course/mask.hpp"
#include "course/readings.hpp"
#include "course/terminal_views.hpp"
#include "explain/text_table.hpp"
#include "formats/input_error.hpp"
#include "model/script.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>

namespace impulse::course {

namespace {

std::string trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return std::string(s);
}

// Markdown as plain text: code spans and bold lose their marks, paragraphs are wrapped, list items indented; where
// the text has a window and a terminal reading, the terminal's.
void write_markdown(std::ostream& out, const std::string& text, int width) {
    const std::string markdown = reading(text, Reading::terminal);
    std::string paragraph;
    bool item = false;
    const auto flush = [&] {
        if (!paragraph.empty()) out << (item ? wrap_text("• " + paragraph, width, "  ") : wrap_text(paragraph, width));
        paragraph.clear();
        item = false;
    };
    std::size_t start = 0;
    while (start <= markdown.size()) {
        const std::size_t end = std::min(markdown.find('\n', start), markdown.size());
        std::string line = markdown.substr(start, end - start);
        start = end + 1;
        std::erase(line, '`');
        for (std::size_t bold = line.find("**"); bold != std::string::npos; bold = line.find("**")) line.erase(bold, 2);
        if (trim(line).empty()) {
            flush();
            out << '\n';
        } else if (line.starts_with("- ") || line.starts_with("* ")) {
            flush();
            item = true;
            paragraph = line.substr(2);
        } else if (line.starts_with("#")) {
            flush();
            out << line.substr(line.find_first_not_of("# ")) << '\n';
        } else {
            paragraph += (paragraph.empty() ? "" : " ") + trim(line);
        }
        if (end == markdown.size()) break;
    }
    flush();
}

const char* help_text =
    "Keys (then Enter): an answer (3.2, 3,2, 1/60, with its unit if you like) · Enter the next step · s skip the "
    "question (shows its answer) · b back · g N step N · t this item's earlier tables · o the bodies before and "
    "after · c the contacts · i the order the phase took them in · set NAME VALUE change a setting (re-runs the "
    "scene) · h these keys · q quit (your progress is kept)";

// A lesson being taken: the run, its session as the settings left it, and what the open questions hide there.
class TerminalLesson {
public:
    TerminalLesson(PreparedLesson& prepared, LessonRun& run, std::ostream& out, int width)
        : prepared_(prepared), run_(run), out_(out), width_(width) {}

    const Trace& trace() const { return prepared_.session.trace(); }

    Mask mask() {
        if (revision_ != prepared_.session.revision()) {
            reaches_ = question_reaches(prepared_, trace());
            revision_ = prepared_.session.revision();
        }
        return Mask(reaches_, run_.open(), trace());
    }

    // The current step's place in the session's trace (the lesson's own run, or a re-run with other settings).
    std::optional<model::Cursor> place() {
        try {
            return model::resolve_goto(trace(), model::parse_goto(run_.current().at, "at"), "at");
        } catch (const formats::InputError& e) {
            out_ << "  (this step's place, " << run_.current().at << ", is not in the re-run: " << e.problem() << ")\n";
            return std::nullopt;
        }
    }

    // The step's table, or (`earlier`) its item's tables up to it as the window's derivation table shows them.
    void tables(bool earlier = false) {
        const std::optional<model::Cursor> at = place();
        if (!at) return;
        const Mask m = mask();
        const std::vector<explain::StepTable> all = model::step_tables(trace(), *at);
        for (int t = earlier ? 0 : at->step; t <= at->step && t < static_cast<int>(all.size()); ++t) {
            explain::StepTable table = all[static_cast<std::size_t>(t)];
            for (explain::Row& r : table.rows)
                if (const HiddenBy by = m.row_hidden_by(*at, r))
                    r.value = hidden_until(prepared_.lesson, *by, run_.step());
            out_ << '\n';
            explain::write_table(out_, table, "  ", static_cast<std::size_t>(width_));
        }
    }

    void step() {
        const Lesson& lesson = prepared_.lesson;
        const std::optional<model::Cursor> at = place();
        out_ << "\n── Step " << run_.step() + 1 << " of " << run_.step_count() << " ──\n";
        if (at) out_ << wrap_text(model::describe(trace(), *at), width_, "  ");
        out_ << '\n';
        if (run_.step() == 0 && !lesson.introduction.empty()) {
            write_markdown(out_, lesson.introduction, width_);
            out_ << '\n';
        }
        write_markdown(out_, run_.current().text, width_);
        tables();
        if (!run_.current().question) return;
        const Question& q = *run_.current().question;
        out_ << '\n' << wrap_text("Question: " + reading(q.prompt, Reading::terminal), width_, "  ");
        for (std::size_t o = 0; o < q.options.size(); ++o)
            out_ << wrap_text("  " + std::to_string(o + 1) + ". " + reading(q.options[o].label, Reading::terminal),
                              width_, "     ");
        if (const std::string& said = run_.feedback(run_.step()); !said.empty()) out_ << wrap_text(said, width_, "  ");
    }

    void view(char key) {
        const std::optional<model::Cursor> at = place();
        if (!at) return;
        out_ << '\n';
        if (key == 'o') write_bodies(out_, trace(), *at, mask(), width_);
        if (key == 'c') write_contacts(out_, trace(), *at, mask());
        if (key == 'i') write_order(out_, trace(), *at, mask(), width_);
    }

    // `set NAME VALUE` (or NAME=VALUE): the window's Settings tab, typed.
    void set(std::string assignment) {
        if (const std::size_t space = assignment.find(' ');
            space != std::string::npos && assignment.find('=') == std::string::npos)
            assignment[space] = '=';
        try {
            prepared_.session.set(assignment, "set");
            out_ << wrap_text(
                model::rerun_text(prepared_.session, assignment) + " (the questions keep the lesson's own answers)",
                width_, "  ");
            tables();
        } catch (const formats::InputError& e) {
            out_ << "  " << e.problem() << '\n';
        }
    }

    void end(const std::optional<LessonLink>& next) {
        const LessonEnd e = lesson_end(run_);
        out_ << "\n── The end of lesson " << prepared_.lesson.number << " ──\n\n"
             << wrap_text("Score: " + score_text(e) + ".", width_, "  ");
        if (!e.open_steps.empty()) {
            out_ << "Still open:\n";
            for (const int s : e.open_steps) out_ << wrap_text("  " + open_question_text(run_, s), width_, "    ");
        }
        out_ << wrap_text(
            std::string(e.open_steps.empty() ? "" : "Type a step's number to go back to it, ") +
                (next ? "n for lesson " + std::to_string(next->number) + " · " + next->title + ", " : "") +
                "q to quit.",
            width_);
    }

private:
    PreparedLesson& prepared_;
    LessonRun& run_;
    std::ostream& out_;
    int width_;
    std::vector<std::optional<QuestionReach>> reaches_;
    int revision_ = -1;
};

std::string answer_prompt(const LessonRun& run) {
    const Question& q = *run.current().question;
    const Answer& a = *run.lesson().answers[static_cast<std::size_t>(run.step())];
    if (q.kind == Question::Kind::choose)
        return "Your answer (1 to " + std::to_string(q.options.size()) + "; s skip, h keys): ";
    return "Your answer" + (a.unit.empty() ? std::string() : " in " + a.unit) + " (s skip, h keys): ";
}

// "g 5" or a bare number at the end: a step from 1.
std::optional<int> step_number(std::string_view text) {
    int n = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return n;
}

}  // namespace

std::string wrap_text(std::string_view text, int width, std::string_view indent) {
    std::string out;
    const std::vector<std::string> lines = explain::wrap_words(text, static_cast<std::size_t>(std::max(width, 1)));
    // Lines after the first are indented: wrap again to the narrower width.
    if (lines.size() <= 1 || indent.empty()) {
        for (const std::string& l : lines) out += l + '\n';
        return out;
    }
    out += lines.front() + '\n';
    std::string rest;
    for (std::size_t i = 1; i < lines.size(); ++i) rest += (rest.empty() ? "" : " ") + lines[i];
    const std::size_t room = static_cast<std::size_t>(std::max(width, 1)) > indent.size() + 1
                                 ? static_cast<std::size_t>(width) - explain::display_width(indent)
                                 : 1;
    for (const std::string& l : explain::wrap_words(rest, room)) out += std::string(indent) + l + '\n';
    return out;
}

TerminalOutcome take_lesson(PreparedLesson& prepared, LessonRun& run, std::istream& in, std::ostream& out, int width,
                            const std::optional<LessonLink>& next) {
    const Lesson& lesson = prepared.lesson;
    width = std::clamp(width, 40, 160);
    TerminalLesson lessons(prepared, run, out, width);
    out << wrap_text("Lesson " + std::to_string(lesson.number) + " · " + lesson.title, width) << run.step_count()
        << " steps, " << question_count(lesson) << " questions.\n"
        << wrap_text(help_text, width, "  ");
    if (run.step() > 0) out << "Back at step " << run.step() + 1 << ", where you left off.\n";

    bool show = true;       // the step is to be written out (again)
    bool finished = false;  // the end-of-lesson screen is up
    bool asked = false;     // Enter on an open question asked once whether to leave it open
    TerminalOutcome outcome;
    std::string line;
    const auto go_to = [&](int step) {
        run.go_to(step);
        finished = false;
        asked = false;
        show = true;
    };
    while (true) {
        if (show && !finished) {
            lessons.step();
            show = false;
        }
        const bool last = run.step() + 1 == run.step_count();
        if (finished)
            out << "> ";
        else if (run.waiting())
            out << answer_prompt(run);
        else
            out << (last ? "That was the last step. Enter: the end of the lesson · b back · h keys: "
                         : "Enter: next step · b back · h keys: ");
        out.flush();
        if (!std::getline(in, line)) {
            out << '\n';
            break;
        }
        const std::string typed = trim(line);
        if (typed == "q" || typed == "quit") break;
        if (typed == "h" || typed == "help" || typed == "?") {
            out << wrap_text(help_text, width, "  ");
            continue;
        }
        if (finished) {
            if (typed == "n" && next) {
                outcome.next_lesson = true;
                break;
            }
            if (const std::optional<int> n = step_number(typed); n && *n >= 1 && *n <= run.step_count()) {
                go_to(*n - 1);
                continue;
            }
            if (typed.empty()) break;
            out << "  (a step's number, " << (next ? "n for the next lesson, " : "") << "or q)\n";
            continue;
        }
        if (typed == "b" || typed == "back") {
            if (run.step() > 0) go_to(run.step() - 1);
            continue;
        }
        if (typed.starts_with("g ")) {
            if (const std::optional<int> n = step_number(trim(typed.substr(2))); n && *n >= 1 && *n <= run.step_count())
                go_to(*n - 1);
            else
                out << "  (g N goes to step N, from 1 to " << run.step_count() << ")\n";
            continue;
        }
        if (typed == "t" || typed == "tables") {
            lessons.tables(true);
            continue;
        }
        if (typed == "o" || typed == "c" || typed == "i") {
            lessons.view(typed[0]);
            continue;
        }
        if (typed.starts_with("set ")) {
            lessons.set(trim(typed.substr(4)));
            continue;
        }
        if (run.waiting()) {
            if (typed.empty()) {
                // Leaving an open question asks first; a second Enter goes on and leaves it open for later.
                if (!asked) {
                    out << wrap_text(
                        "This question is still open: type your answer, s to skip it (shows the "
                        "engine's value), or Enter again to go on and leave it open for later.",
                        width, "  ");
                    asked = true;
                    continue;
                }
                if (last)
                    finished = true, lessons.end(next);
                else
                    go_to(run.step() + 1);
                continue;
            }
            if (typed == "s" || typed == "skip") {
                run.skip();
                out << wrap_text(run.feedback(run.step()), width, "  ");
            } else {
                try {
                    const AnswerVerdict v = run.answer(typed);
                    out << wrap_text(v.feedback, width, "  ");
                    if (!v.correct) continue;
                } catch (const formats::InputError& e) {
                    out << wrap_text(e.problem(), width, "  ");
                    continue;
                }
            }
            // Settled: the step's table again, with what was hidden now shown.
            lessons.tables();
            if (!run.save_problem().empty()) out << "  (progress not saved: " << run.save_problem() << ")\n";
            continue;
        }
        if (!typed.empty()) {
            out << "  (Enter for the next step, h for the keys)\n";
            continue;
        }
        if (last) {
            finished = true;
            lessons.end(next);
            continue;
        }
        go_to(run.step() + 1);
    }
    out << "Lesson " << lesson.number << ": " << tally_text(run.tally()) << ".\n";
    if (!run.save_problem().empty()) out << "Progress could not be saved: " << run.save_problem() << '\n';
    return outcome;
}

void write_annotated_lesson(std::ostream& out, const PreparedLesson& prepared) {
    const Lesson& lesson = prepared.lesson;
    out << "Lesson " << lesson.number << " · " << lesson.title << "\n(" << lesson.file.string() << ", scene "
        << lesson.scene.lexically_normal().string() << ")\n";
    if (!lesson.introduction.empty()) out << '\n' << reading(lesson.introduction, Reading::window) << '\n';
    const Trace& trace = prepared.session.trace();
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const Step& step = lesson.steps[i];
        const model::Cursor& place = prepared.places[i];
        out << "\n── Step " << i + 1 << " of " << lesson.steps.size() << " · " << model::describe(trace, place)
            << " ──\n\n"
            << reading(step.text, Reading::window) << '\n';
        if (step.question) {
            out << "\nQuestion: " << reading(step.question->prompt, Reading::window) << '\n';
            for (std::size_t o = 0; o < step.question->options.size(); ++o)
                out << "  " << o + 1 << ". " << reading(step.question->options[o].label, Reading::window) << '\n';
        }
        const std::vector<explain::StepTable> tables = model::step_tables(trace, place);
        out << '\n';
        explain::write_table(out, tables[static_cast<std::size_t>(place.step)]);
        if (step.question) out << "Answer (the engine's): " << prepared.answers[i]->shown << '\n';
    }
}

}  // namespace impulse::course
