#include "course/text_lesson.hpp"

#include "explain/text_table.hpp"
#include "formats/input_error.hpp"
#include "course/mask.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace impulse::course {

namespace {

std::string trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return std::string(s);
}

// Markdown as plain text: code spans and bold lose their marks, paragraphs are wrapped, list items indented.
void write_markdown(std::ostream& out, const std::string& markdown, int width) {
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

// The step's table, or (`earlier`) its item's tables up to it as the window's derivation table shows them,
// with what the mask hides as "?".
void write_tables(std::ostream& out, const Trace& trace, const model::Cursor& place, const Mask& mask,
                  bool earlier = false) {
    const std::vector<explain::StepTable> tables = model::step_tables(trace, place);
    for (int t = earlier ? 0 : place.step; t <= place.step && t < static_cast<int>(tables.size()); ++t) {
        explain::StepTable table = tables[static_cast<std::size_t>(t)];
        for (explain::Row& r : table.rows)
            if (mask.hides_row(place, r)) {
                r.value = "? (hidden until you answer)";
                r.other_frame.clear();
            }
        out << '\n';
        explain::write_table(out, table);
    }
}

void write_step(std::ostream& out, const LessonRun& run, const std::vector<std::optional<QuestionReach>>& reaches,
                int width) {
    const PreparedLesson& prepared = run.lesson();
    const Lesson& lesson = prepared.lesson;
    const auto i = static_cast<std::size_t>(run.step());
    const Step& step = run.current();
    const Trace& trace = prepared.session.trace();
    const model::Cursor& place = prepared.places[i];
    out << "\n── Step " << run.step() + 1 << " of " << run.step_count() << " · " << model::describe(trace, place)
        << " ──\n\n";
    if (run.step() == 0 && !lesson.introduction.empty()) {
        write_markdown(out, lesson.introduction, width);
        out << '\n';
    }
    write_markdown(out, step.text, width);
    write_tables(out, trace, place, Mask(reaches, run.open(), trace));
}

void write_question(std::ostream& out, const LessonRun& run, int width) {
    const Question& q = *run.current().question;
    out << '\n' << wrap_text("Question: " + q.prompt, width, "  ");
    for (std::size_t o = 0; o < q.options.size(); ++o)
        out << wrap_text("  " + std::to_string(o + 1) + ". " + q.options[o].label, width, "     ");
}

std::string answer_prompt(const LessonRun& run) {
    const Question& q = *run.current().question;
    const Answer& a = *run.lesson().answers[static_cast<std::size_t>(run.step())];
    if (q.kind == Question::Kind::choose)
        return "Your answer (1 to " + std::to_string(q.options.size()) + "; s skip, b back, t tables, q quit): ";
    return "Your answer" + (a.unit.empty() ? std::string() : " in " + a.unit) + " (s skip, b back, t tables, q quit): ";
}

}  // namespace

std::string wrap_text(std::string_view text, int width, std::string_view indent) {
    std::string out, line;
    const auto columns = [](const std::string& s) { return static_cast<int>(explain::display_width(s)); };
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find(' ', start), text.size());
        const std::string word(text.substr(start, end - start));
        start = end + 1;
        if (word.empty()) continue;
        if (!line.empty() && columns(line) + 1 + columns(word) > width) {
            out += line + '\n';
            line = std::string(indent);
        }
        line += (line.empty() || line == indent ? "" : " ") + word;
    }
    if (!line.empty()) out += line + '\n';
    return out;
}

void take_lesson(LessonRun& run, std::istream& in, std::ostream& out, int width) {
    const PreparedLesson& prepared = run.lesson();
    const Lesson& lesson = prepared.lesson;
    width = std::clamp(width, 40, 160);
    const auto reaches = question_reaches(prepared, prepared.session.trace());
    out << "Lesson " << lesson.number << " · " << lesson.title << '\n'
        << run.step_count() << " steps, " << question_count(lesson)
        << " questions. Enter: next step · b: back · t: this item's earlier tables · s: skip a question (shows "
           "its answer) · q: quit (your progress is kept)\n";
    if (run.step() > 0) out << "Back at step " << run.step() + 1 << ", where you left off.\n";

    bool show = true;  // the step is to be written out (again)
    std::string line;
    while (true) {
        if (show) {
            write_step(out, run, reaches, width);
            if (run.current().question) {
                write_question(out, run, width);
                const std::string& said = run.feedback(run.step());
                if (!said.empty()) out << wrap_text(said, width, "  ");
            }
            show = false;
        }
        const bool last = run.step() + 1 == run.step_count();
        if (run.waiting())
            out << answer_prompt(run);
        else
            out << (last ? "That was the last step. Enter to finish, b back: "
                         : "Enter: next step · b back · t tables · q quit: ");
        out.flush();
        if (!std::getline(in, line)) {
            out << '\n';
            break;
        }
        const std::string typed = trim(line);
        if (typed == "q" || typed == "quit") break;
        if (typed == "b" || typed == "back") {
            if (run.step() > 0) run.go_to(run.step() - 1), show = true;
            continue;
        }
        if (typed == "t" || typed == "tables") {
            write_tables(out, prepared.session.trace(), prepared.places[static_cast<std::size_t>(run.step())],
                         Mask(reaches, run.open(), prepared.session.trace()), true);
            continue;
        }
        if (run.waiting()) {
            if (typed.empty()) {
                out << "  (answer first, or s to skip, or b to go back)\n";
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
                    out << "  " << e.problem() << '\n';
                    continue;
                }
            }
            // Settled: the step's tables again, with what was hidden now shown.
            write_tables(out, prepared.session.trace(), prepared.places[static_cast<std::size_t>(run.step())],
                         Mask(reaches, run.open(), prepared.session.trace()));
            if (!run.save_problem().empty()) out << "  (progress not saved: " << run.save_problem() << ")\n";
            continue;
        }
        if (!typed.empty()) {
            out << "  (Enter for the next step, b to go back, q to quit)\n";
            continue;
        }
        if (last) break;
        run.go_to(run.step() + 1);
        show = true;
    }
    out << "Lesson " << lesson.number << ": " << tally_text(run.tally()) << ".\n";
    if (!run.save_problem().empty()) out << "Progress could not be saved: " << run.save_problem() << '\n';
}

void write_annotated_lesson(std::ostream& out, const PreparedLesson& prepared) {
    const Lesson& lesson = prepared.lesson;
    out << "Lesson " << lesson.number << " · " << lesson.title << "\n(" << lesson.file.string() << ", scene "
        << lesson.scene.lexically_normal().string() << ")\n";
    if (!lesson.introduction.empty()) out << '\n' << lesson.introduction << '\n';
    const Trace& trace = prepared.session.trace();
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const Step& step = lesson.steps[i];
        const model::Cursor& place = prepared.places[i];
        out << "\n── Step " << i + 1 << " of " << lesson.steps.size() << " · " << model::describe(trace, place)
            << " ──\n\n"
            << step.text << '\n';
        if (step.question) {
            out << "\nQuestion: " << step.question->prompt << '\n';
            for (std::size_t o = 0; o < step.question->options.size(); ++o)
                out << "  " << o + 1 << ". " << step.question->options[o].label << '\n';
        }
        const std::vector<explain::StepTable> tables = model::step_tables(trace, place);
        out << '\n';
        explain::write_table(out, tables[static_cast<std::size_t>(place.step)]);
        if (step.question) out << "Answer (the engine's): " << prepared.answers[i]->shown << '\n';
    }
}

}  // namespace impulse::course
