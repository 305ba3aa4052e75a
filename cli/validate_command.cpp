// `impulse-lab validate FILE...`: check case, trace and lesson files against their schemas and against what a
// schema cannot say (names, references, unit quaternions, inertia). A trace is told from a case by its
// "format" marker. Exit 0 when every file is valid, 1 when one is invalid (the verdict asked for), 2 when one cannot
// be read at all.

#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "formats/input_files.hpp"
#include "formats/scene_file.hpp"
#include "formats/input_error.hpp"
#include "formats/printable_text.hpp"
#include "formats/json_text.hpp"
#include "formats/trace_json.hpp"
#include "course/lesson.hpp"

#include <cctype>
#include <filesystem>

namespace impulse::cli {

namespace {

std::string count(std::size_t n, std::string_view one, std::string_view many) {
    return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

bool is_lesson(const std::string& path) {
    return path.ends_with(".md");
}

// A Markdown file that is neither named nor made like a lesson (a folder's README.md): nothing to check, so
// `validate lessons/*.md` checks the lessons and passes over the rest.
bool other_markdown(const std::string& path, const std::string& text) {
    const std::string name = std::filesystem::path(path).filename().string();
    const bool named = name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
                       std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '-';
    if (named) return false;
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    return first == std::string::npos || text.compare(first, 7, "```json") != 0;
}

// The verdict on a file read whole; throws formats::InputError or FileError for an invalid one.
std::string check_file(const std::string& path, const std::string& text) {
    if (is_lesson(path)) {
        if (other_markdown(path, text)) return "not a lesson (no NN- name, no ```json header): skipped";
        // A lesson: its header and sections, then its run, places and answers.
        const course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson_text(text, path));
        const auto questions = static_cast<std::size_t>(course::question_count(lesson.lesson));
        return "valid lesson " + std::to_string(lesson.lesson.number) + " (" +
               count(lesson.lesson.steps.size(), "step", "steps") + ", " + count(questions, "question", "questions") +
               ")";
    }
    const formats::json document = formats::parse_json_text(text);
    if (document.is_object() && document.contains("format") && document["format"] == formats::trace_format_name) {
        const Trace trace = formats::read_trace(document);
        std::size_t iterations = 0;
        for (const FrameRecord& f : trace.frames)
            iterations += f.position.iterations.size() + f.velocity.iterations.size();
        // Format 1 is read with its renamed keys moved (docs/trace-format.md): say so in the verdict's line.
        const std::string version = trace.version == trace_format_version
                                        ? std::to_string(trace.version)
                                        : std::to_string(trace.version) + ", read with format " +
                                              std::to_string(trace_format_version) + "'s renamed keys";
        return "valid trace (format version " + version + ", " + count(trace.frames.size(), "frame", "frames") + ", " +
               count(iterations, "iteration", "iterations") + ")";
    }
    const Scene c = formats::read_scene(document);
    // A case writes its contacts out; a scene leaves them to its shapes.
    const bool is_case = !c.contacts.empty();
    std::string verdict =
        std::string(is_case ? "valid case (" : "valid scene (") + count(c.bodies.size(), "body", "bodies");
    if (c.ground) verdict += ", ground";
    if (is_case) verdict += ", " + count(c.contacts.size(), "contact", "contacts");
    return verdict + ")";
}

}  // namespace

int validate_command(const std::vector<std::string>& files, std::ostream& out, std::ostream& err) {
    // An invalid file is the verdict asked for (1); a file that cannot be read at all is bad input (2).
    bool invalid = false, unreadable = false;
    const auto report = [&err](const formats::FileError& e) { err << error_line(e); };
    for (const std::string& file : files) {
        std::string text;
        try {
            text = formats::read_input_file(file,
                                            is_lesson(file) ? formats::max_text_input_bytes : formats::max_input_bytes);
        } catch (const formats::FileError& e) {
            report(e);
            unreadable = true;
            continue;
        }
        try {
            const std::string verdict = check_file(file, text);
            out << formats::one_line(formats::input_name(file)) << ": " << verdict << '\n';
        } catch (const formats::InputError& e) {
            err << error_line(formats::input_name(file), e.what());
            invalid = true;
        } catch (const formats::FileError& e) {
            report(e);
            invalid = true;
        }
    }
    return unreadable ? exit_bad_input : invalid ? exit_verdict : exit_ok;
}

}  // namespace impulse::cli
