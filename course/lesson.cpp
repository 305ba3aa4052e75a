#include "course/lesson.hpp"

#include "course/answer_number.hpp"
#include "course/readings.hpp"
#include "course/slips.hpp"
#include "course/trace_path.hpp"
#include "formats/input_files.hpp"
#include "explain/annotations.hpp"
#include "formats/words.hpp"
#include "explain/format.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/json_values.hpp"
#include "formats/schema_validator.hpp"
#include "formats/scene_file.hpp"
#include "formats/schemas.hpp"
#include "formats/suggest.hpp"
#include "formats/trace_json.hpp"
#include "course/course_schemas.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>

namespace impulse::course {

namespace {

using json = nlohmann::ordered_json;

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::string line_at(int line) {
    return "line " + std::to_string(line);
}

bool valid_id(std::string_view id) {
    return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
    });
}

Question read_question(const json& q, const std::string& where) {
    Question question;
    question.kind = q["kind"] == "predict" ? Question::Kind::predict : Question::Kind::choose;
    question.prompt = q["prompt"].get<std::string>();
    question.value = q["value"].get<std::string>();
    if (q.contains("tolerance")) {
        const json& t = q["tolerance"];
        if (t.contains("relative")) question.tolerance.relative = t["relative"].get<double>();
        if (t.contains("absolute")) question.tolerance.absolute = t["absolute"].get<double>();
    }
    if (q.contains("options"))
        for (const json& o : q["options"]) question.options.push_back({o["label"].get<std::string>(), o["value"]});
    if (q.contains("reveals"))
        for (std::size_t i = 0; i < q["reveals"].size(); ++i) {
            const std::string name = q["reveals"][i].get<std::string>();
            if (!explain::find_annotation(name)) {
                std::vector<std::string> names;
                for (const explain::Annotation& a : explain::vocabulary()) names.emplace_back(a.quantity);
                const std::optional<std::string> suggestion = formats::closest_name(name, names);
                throw formats::InputError(where + ".reveals[" + std::to_string(i) + "]",
                                          "\"" + name +
                                              "\" is not a quantity of the vocabulary (docs/trace-format.md)" +
                                              (suggestion ? "; did you mean \"" + *suggestion + "\"?" : std::string()));
            }
            question.reveals.push_back(name);
        }
    if (question.kind == Question::Kind::predict) {
        if (!q.contains("tolerance"))
            throw formats::InputError(where + ".tolerance",
                                      "a predict question needs a tolerance: {\"relative\": r} or "
                                      "{\"absolute\": a}");
        if (!question.options.empty())
            throw formats::InputError(where + ".options",
                                      "a predict question has no options (did you mean \"kind\": "
                                      "\"choose\"?)");
    } else {
        if (question.options.empty()) throw formats::InputError(where + ".options", "a choose question needs options");
        if (q.contains("tolerance"))
            throw formats::InputError(where + ".tolerance", "a choose question has no tolerance");
    }
    return question;
}

std::string text_of(const json& value) {
    if (value.is_number()) return explain::number(value.get<double>());
    if (value.is_string()) return value.get<std::string>();
    return value.dump();
}

}  // namespace

std::string question_quantity(const Question& question, model::Stage stage) {
    const explain::ItemKind item = stage == model::Stage::preparation ? explain::ItemKind::contact
                                   : stage == model::Stage::position  ? explain::ItemKind::position_iteration
                                                                      : explain::ItemKind::velocity_iteration;
    const explain::Annotation* a = explain::quantity_of_path(question.value, item);
    return a ? std::string(a->quantity) : std::string();
}

Lesson read_lesson_text(std::string_view text, const std::filesystem::path& file) {
    // An editor on Windows saves UTF-8 with a byte-order mark: it is no part of the text (the header was refused).
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    Lesson lesson;
    lesson.file = file;
    lesson.name = file.stem().string();
    formats::require_utf8(text);  // shown in the window and written to the headless text and worksheets
    {
        int number = 0;
        const auto [end, error] = std::from_chars(lesson.name.data(), lesson.name.data() + lesson.name.size(), number);
        if (error != std::errc() || end == lesson.name.data() || *end != '-')
            throw formats::InputError("", "a lesson file is named NN-slug.md (e.g. 01-impulse.md)");
        lesson.number = number;
    }

    // Split into lines, keeping numbers for errors.
    std::vector<std::string_view> lines;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    std::size_t at = 0;
    while (at < lines.size() && trim(lines[at]).empty()) ++at;
    if (at == lines.size() || trim(lines[at]) != "```json")
        throw formats::InputError(line_at(static_cast<int>(at) + 1),
                                  "a lesson starts with its header in a ```json block");
    const std::size_t header_start = ++at;
    while (at < lines.size() && trim(lines[at]) != "```") ++at;
    if (at == lines.size())
        throw formats::InputError(line_at(static_cast<int>(header_start)),  // the opening fence's line
                                  "the ```json header block is not closed by ```");
    std::string header_text;
    for (std::size_t i = header_start; i < at; ++i) header_text += std::string(lines[i]) + "\n";
    json header;
    try {
        header = formats::parse_json_text(header_text);
    } catch (const formats::InputError& e) {
        throw formats::InputError("header", e.problem());
    }
    formats::SchemaValidator(formats::parse_json_text(course::lesson_schema_text())).validate(header);

    lesson.title = header["title"].get<std::string>();
    lesson.scene = (file.parent_path() / header["scene"].get<std::string>()).lexically_normal();
    if (header.contains("set"))
        for (const json& s : header["set"]) lesson.settings.push_back(s.get<std::string>());
    if (header.contains("frames")) lesson.frames = header["frames"].get<int>();
    if (header.contains("record"))
        for (const json& r : header["record"]) lesson.record.push_back(r.get<std::string>());
    std::set<std::string> ids;
    for (std::size_t i = 0; i < header["steps"].size(); ++i) {
        const json& s = header["steps"][i];
        const std::string where = "steps[" + std::to_string(i) + "]";
        Step step;
        step.id = s["id"].get<std::string>();
        if (!valid_id(step.id))
            throw formats::InputError(where + ".id", "use letters, digits, - and _ only, got \"" + step.id + "\"");
        if (!ids.insert(step.id).second) throw formats::InputError(where + ".id", "\"" + step.id + "\" is used twice");
        step.at = s["at"].get<std::string>();
        // A step renamed since the lesson was written (docs/trace-format.md) is read by its new name, with a note.
        for (const formats::words::StepRename& r : formats::words::step_renames()) {
            const std::string old_place = "step=" + std::string(r.old_name);
            const std::size_t found = step.at.find(old_place);
            const std::size_t end = found + old_place.size();
            if (found != std::string::npos && (end == step.at.size() || step.at[end] == ','))
                step.at.replace(found + 5, r.old_name.size(), r.new_name),
                    lesson.notes.push_back(where + ".at: step \"" + std::string(r.old_name) + "\" is now \"" +
                                           std::string(r.new_name) + "\"");
        }
        model::parse_goto(step.at, where + ".at");
        if (s.contains("question")) step.question = read_question(s["question"], where + ".question");
        lesson.steps.push_back(std::move(step));
    }

    // The sections: "## id" up to the next "## " heading.
    std::string* into = &lesson.introduction;
    std::set<std::string> seen;
    for (std::size_t i = at + 1; i < lines.size(); ++i) {
        const std::string_view line = lines[i];
        if (line.starts_with("## ")) {
            const std::string id(trim(line.substr(3)));
            const auto step =
                std::find_if(lesson.steps.begin(), lesson.steps.end(), [&](const Step& s) { return s.id == id; });
            if (step == lesson.steps.end())
                throw formats::InputError(line_at(static_cast<int>(i) + 1), "section \"" + id +
                                                                                "\" has no step in the "
                                                                                "header's steps");
            if (!seen.insert(id).second)
                throw formats::InputError(line_at(static_cast<int>(i) + 1), "a second section \"" + id + "\"");
            into = &step->text;
            continue;
        }
        *into += std::string(line) + "\n";
    }
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        Step& s = lesson.steps[i];
        if (!seen.count(s.id))
            throw formats::InputError("steps[" + std::to_string(i) + "].id",
                                      "no \"## " + s.id + "\" section for this step");
        s.text = std::string(trim(s.text));
    }
    lesson.introduction = std::string(trim(lesson.introduction));
    // Every text with a window and a terminal reading must hold both whole (course/readings.hpp).
    check_readings(lesson.introduction, "introduction");
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const Step& s = lesson.steps[i];
        check_readings(s.text, "section \"" + s.id + "\"");
        if (!s.question) continue;
        const std::string where = "steps[" + std::to_string(i) + "].question";
        check_readings(s.question->prompt, where + ".prompt");
        for (std::size_t o = 0; o < s.question->options.size(); ++o)
            check_readings(s.question->options[o].label, where + ".options[" + std::to_string(o) + "].label");
    }
    return lesson;
}

int question_count(const Lesson& lesson) {
    return static_cast<int>(
        std::count_if(lesson.steps.begin(), lesson.steps.end(), [](const Step& s) { return s.question.has_value(); }));
}

Lesson read_lesson(const std::filesystem::path& file) {
    try {
        return read_lesson_text(formats::read_input_file(file.string(), formats::max_text_input_bytes), file);
    } catch (const formats::InputError& e) {
        throw formats::FileError{file.string(), e.where(), e.problem()};
    }
}

std::vector<std::filesystem::path> lesson_files(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".md" && name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
            std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '-')
            files.push_back(entry.path());
    }
    if (error) throw formats::FileError{folder.string(), "", "cannot read the lessons folder: " + error.message()};
    std::sort(files.begin(), files.end());
    return files;
}

PreparedLesson prepare_lesson(Lesson lesson) {
    const std::string file = lesson.file.string();
    model::OpenOptions options;
    options.settings = lesson.settings;
    options.record = lesson.record;
    // A case is resolved once; a scene is simulated for `frames` frames (default 1). Which one it is decides
    // the options, so the file is read once first; running it is what costs.
    const std::string scene_file = lesson.scene.string();
    bool is_case = false;
    try {
        is_case = !formats::read_scene_text(formats::read_input_file(scene_file)).contacts.empty();
    } catch (const formats::InputError& e) {
        throw formats::FileError{scene_file, e.where(), e.problem()};
    }
    if (is_case && lesson.frames)
        throw formats::FileError{
            file, "frames",
            "the scene is a case (its contacts are written out): it is resolved once, so it has no "
            "frames to simulate"};
    if (!is_case) options.frames = lesson.frames.value_or(1);
    model::Session session = [&] {
        try {
            return model::Session::open(scene_file, options);
        } catch (const formats::InputError& e) {
            throw formats::FileError{file,
                                     e.where() == "--set"      ? "set"
                                     : e.where() == "--record" ? "record"
                                                               : e.where(),
                                     e.problem()};
        }
    }();
    PreparedLesson prepared{std::move(lesson), std::move(session), {}, {}};
    const Trace& trace = prepared.session.trace();

    for (std::size_t i = 0; i < prepared.lesson.steps.size(); ++i) {
        const Step& step = prepared.lesson.steps[i];
        const std::string where = "steps[" + std::to_string(i) + "]";
        try {
            const model::Cursor place =
                model::resolve_goto(trace, model::parse_goto(step.at, where + ".at"), where + ".at");
            prepared.places.push_back(place);
            if (!step.question) {
                prepared.answers.emplace_back();
                continue;
            }
            const Question& q = *step.question;
            std::string problem;
            const json item = item_json(trace, place);
            const json* value = follow(item, q.value, problem);
            if (!value) throw formats::InputError(where + ".question.value", problem);
            Answer answer{*value, question_quantity(q, place.stage), {}, -1, {}};
            if (answer.quantity.empty())
                throw formats::InputError(where + ".question.value", "\"" + q.value +
                                                                         "\" names no quantity of the vocabulary here "
                                                                         "(docs/trace-format.md lists the keys)");
            answer.unit = explain::annotation(answer.quantity).unit;
            if (q.kind == Question::Kind::predict) {
                if (!value->is_number())
                    throw formats::InputError(where + ".question.value", "a predict question needs a number, and \"" +
                                                                             q.value + "\" is " + value->dump());
                answer.shown = explain::with_unit(explain::number(value->get<double>()), answer.unit);
            } else {
                if (value->is_object() || value->is_array() || value->is_null())
                    throw formats::InputError(
                        where + ".question.value",
                        "a choose question needs a single value, and \"" + q.value + "\" is " + value->dump());
                for (std::size_t o = 0; o < q.options.size(); ++o) {
                    const json& v = q.options[o].value;
                    const bool equal = v.is_number() && value->is_number()
                                           ? std::abs(v.get<double>() - value->get<double>()) <= 1e-12
                                           : v == *value;
                    if (!equal) continue;
                    if (answer.correct_option >= 0)
                        throw formats::InputError(where + ".question.options",
                                                  "two options equal the engine's value " + text_of(*value));
                    answer.correct_option = static_cast<int>(o);
                }
                if (answer.correct_option < 0)
                    throw formats::InputError(where + ".question.options",
                                              "no option equals the engine's value " + text_of(*value));
                answer.shown = q.options[static_cast<std::size_t>(answer.correct_option)].label;
            }
            prepared.answers.push_back(std::move(answer));
        } catch (const formats::InputError& e) {
            throw formats::FileError{file, e.where(), e.problem()};
        }
    }
    return prepared;
}

AnswerVerdict check_answer(const Question& question, const Answer& answer, std::string_view typed) {
    if (question.kind == Question::Kind::choose) {
        const std::string how = "type the number of an option, from 1 to " + std::to_string(question.options.size());
        double given = 0.0;
        try {
            given = read_answer_number(typed, "");
        } catch (const formats::InputError&) {
            throw formats::InputError("answer", how);
        }
        const int option = static_cast<int>(given) - 1;
        if (given != std::floor(given) || option < 0 || option >= static_cast<int>(question.options.size()))
            throw formats::InputError("answer", how);
        if (option == answer.correct_option) return {true, "right: " + answer.shown};
        return {false, "not quite: option " + std::to_string(option + 1) +
                           " is not what the engine does; try again, or skip to see its answer"};
    }
    const double given = read_answer_number(typed, answer.unit);
    const double value = answer.value.get<double>();
    const double error = given - value;
    const double allowed = std::max(question.tolerance.relative.value_or(0.0) * std::abs(value),
                                    question.tolerance.absolute.value_or(0.0));
    // How far off, as a share of the value (or, for a value of 0, in its unit).
    const bool relative = std::abs(value) > allowed && value != 0.0;
    const std::string off = relative ? explain::percent(std::abs(error) / std::abs(value) * 100.0) + " %"
                                     : explain::with_unit(explain::number(std::abs(error)), answer.unit);
    if (std::abs(error) <= allowed) {
        // Closer than the six digits a table shows is the engine's value itself: no percentage of rounding noise.
        const bool as_shown = std::abs(error) <= shown_precision * std::abs(value) || std::abs(error) <= 1e-9 * allowed;
        return {true,
                "right: the engine has " + answer.shown + (as_shown ? std::string() : " (you were " + off + " off)")};
    }
    // A slip that has a name says more than "200 % too low".
    const std::string slip = likely_slip(
        value, given,
        std::max(question.tolerance.relative.value_or(0.0), value != 0.0 ? allowed / std::abs(value) : 0.0));
    return {false, "not quite: " + (slip.empty() ? off + (error > 0 ? " too high" : " too low") : slip) +
                       "; try again, or skip to see the engine's value"};
}

std::string skipped_text(const Answer& answer) {
    return "skipped: the engine's answer is " + answer.shown;
}

}  // namespace impulse::course
