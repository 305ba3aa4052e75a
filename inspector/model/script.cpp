#include "model/script.hpp"

#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/trace_json.hpp"
#include "model/derivation_view.hpp"

#include <charconv>

namespace impulse::model {

namespace {

using Move = std::optional<Cursor> (*)(const Trace&, const Cursor&);

struct MoveName {
    std::string_view text;
    ActionKind kind;
    Move move;
};

constexpr MoveName moves[] = {
    {"next step", ActionKind::next_step, next_step},
    {"prev step", ActionKind::previous_step, previous_step},
    {"next contact", ActionKind::next_contact, next_contact},
    {"prev contact", ActionKind::previous_contact, previous_contact},
    {"next iteration", ActionKind::next_iteration, next_iteration},
    {"prev iteration", ActionKind::previous_iteration, previous_iteration},
    {"next item", ActionKind::next_item, next_item},
    {"prev item", ActionKind::previous_item, previous_item},
    {"next phase", ActionKind::next_phase, next_stage},
    {"prev phase", ActionKind::previous_phase, previous_stage},
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> words(std::string_view s) {
    std::vector<std::string_view> out;
    while (!(s = trim(s)).empty()) {
        const std::size_t end = s.find_first_of(" \t");
        out.push_back(s.substr(0, end));
        s = end == std::string_view::npos ? std::string_view{} : s.substr(end);
    }
    return out;
}

std::string line_name(int line) {
    return line > 0 ? "line " + std::to_string(line) : "action";
}

const char* known_actions =
    "next|prev step|contact|iteration|item|phase [N], first, last, goto SPEC, set NAME VALUE, screenshot FILE, "
    "view PLANE, lesson step N, key NAME, type TEXT, export trace FILE, export table FILE, quit";

}  // namespace

Action parse_action(std::string_view text, int line) {
    const std::vector<std::string_view> w = words(text);
    const std::string where = line_name(line);
    if (w.empty()) throw formats::InputError(where, "empty action");
    const auto needs = [&](std::size_t n, const char* usage) {
        if (w.size() != n) throw formats::InputError(where, "\"" + std::string(trim(text)) + "\": expected " + usage);
    };
    if (w[0] == "next" || w[0] == "prev" || w[0] == "previous") {
        if (w.size() < 2 || w.size() > 3)
            throw formats::InputError(where, "\"" + std::string(trim(text)) +
                                                 "\": expected next|prev step|contact|iteration|item|phase [COUNT]");
        const std::string name = std::string(w[0] == "next" ? "next " : "prev ") + std::string(w[1]);
        for (const MoveName& m : moves)
            if (m.text == name) {
                Action a{m.kind, {}, 1, line};
                if (w.size() == 3) {
                    const auto [end, error] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), a.count);
                    if (error != std::errc() || end != w[2].data() + w[2].size() || a.count < 1 || a.count > 1000000)
                        throw formats::InputError(
                            where,
                            "repeat count must be a whole number from 1 to 1000000, got \"" + std::string(w[2]) + "\"");
                }
                return a;
            }
        throw formats::InputError(where, "\"" + std::string(w[1]) +
                                             "\" is not something to move by (step, contact, "
                                             "iteration, item or phase)");
    }
    if (w[0] == "first") return needs(1, "first"), Action{ActionKind::first, {}, 1, line};
    if (w[0] == "last") return needs(1, "last"), Action{ActionKind::last, {}, 1, line};
    if (w[0] == "quit") return needs(1, "quit"), Action{ActionKind::quit, {}, 1, line};
    if (w[0] == "goto") {
        needs(2, "goto frame=F,phase=P,iteration=I,contact=C,step=NAME");
        parse_goto(w[1], where);  // checked now, resolved against the trace when performed
        return {ActionKind::go_to, std::string(w[1]), 1, line};
    }
    if (w[0] == "set") {
        needs(3, "set NAME VALUE");
        return {ActionKind::set, std::string(w[1]) + "=" + std::string(w[2]), 1, line};
    }
    if (w[0] == "view") {
        needs(2, "view front|top|side|3d");
        if (w[1] != "front" && w[1] != "top" && w[1] != "side" && w[1] != "3d")
            throw formats::InputError(where, "view must be front, top, side or 3d, got \"" + std::string(w[1]) + "\"");
        return {ActionKind::view, std::string(w[1]), 1, line};
    }
    if (w[0] == "lesson") {
        needs(3, "lesson step N");
        int step = 0;
        const auto [end, error] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), step);
        if (w[1] != "step" || error != std::errc() || end != w[2].data() + w[2].size() || step < 1)
            throw formats::InputError(where,
                                      "expected lesson step N with N from 1, got \"" + std::string(trim(text)) + "\"");
        return {ActionKind::lesson_step, std::to_string(step), 1, line};
    }
    if (w[0] == "key") {
        needs(2, "key NAME (e.g. key Right, key ctrl+s)");
        return {ActionKind::key, std::string(w[1]), 1, line};
    }
    if (w[0] == "type") {
        // Everything after the word, spaces inside kept: "type 7,5 m/s".
        const std::string_view rest = trim(trim(text).substr(4));
        if (rest.empty()) throw formats::InputError(where, "expected type TEXT");
        return {ActionKind::type, std::string(rest), 1, line};
    }
    if (w[0] == "screenshot") {
        needs(2, "screenshot FILE.png");
        return {ActionKind::screenshot, std::string(w[1]), 1, line};
    }
    if (w[0] == "export") {
        if (w.size() == 3 && w[1] == "trace") return {ActionKind::export_trace, std::string(w[2]), 1, line};
        if (w.size() == 3 && w[1] == "table") return {ActionKind::export_table, std::string(w[2]), 1, line};
        throw formats::InputError(where, "\"" + std::string(trim(text)) +
                                             "\": expected export trace FILE or export table "
                                             "FILE");
    }
    throw formats::InputError(where, "unknown action \"" + std::string(w[0]) + "\" (actions: " + known_actions + ")");
}

std::vector<Action> parse_script(std::string_view text) {
    std::vector<Action> actions;
    int line = 0;
    while (!text.empty()) {
        ++line;
        const std::size_t end = text.find('\n');
        std::string_view content = trim(text.substr(0, end));
        // A comment may follow an action, after a space: "next step 4   # to the desired Δv".
        for (const std::string_view mark : {" #", "\t#"})
            if (const std::size_t at = content.find(mark); at != std::string_view::npos)
                content = trim(content.substr(0, at));
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        if (content.empty() || content.front() == '#') continue;
        actions.push_back(parse_action(content, line));
    }
    return actions;
}

std::string rerun_text(const Session& session, std::string_view assignment, bool* is_error) {
    std::string text = "re-ran with " + std::string(assignment);
    if (is_error) *is_error = session.broken_run().has_value();
    if (session.broken_run())
        return text + ": the run stopped at " + broken_run_text(session.trace().scene, *session.broken_run());
    if (const auto note = session.recording_note()) return text + ": " + *note;
    return text;
}

std::string exported_trace(const Session& session) {
    return formats::format_json(formats::trace_json(session.trace()));
}

std::string exported_table(const Session& session) {
    if (!session.cursor()) throw formats::InputError("export table", "the trace records nothing to show");
    return derivation_csv(derivation_view(session.trace(), *session.cursor()));
}

void perform(Session& session, const Action& action, std::string_view where, ActionHost* host) {
    const std::string at(where);
    for (const MoveName& m : moves) {
        if (m.kind != action.kind) continue;
        if (!session.cursor()) throw formats::InputError(at, "the trace records nothing to step through");
        Cursor c = *session.cursor();
        for (int i = 0; i < action.count; ++i) {
            const std::optional<Cursor> next = m.move(session.trace(), c);
            if (!next)
                throw formats::InputError(at, std::string(m.text) + ": already at the " +
                                                  (m.text.starts_with("next") ? "end" : "start") + " of the trace (" +
                                                  describe(session.trace(), c) + ")");
            c = *next;
        }
        session.move_to(c);
        return;
    }
    switch (action.kind) {
        case ActionKind::first:
        case ActionKind::last:
            if (const std::optional<Cursor> c =
                    action.kind == ActionKind::first ? first_cursor(session.trace()) : last_cursor(session.trace()))
                session.move_to(*c);
            return;
        case ActionKind::go_to:
            session.move_to(resolve_goto(session.trace(), parse_goto(action.argument, at), at));
            return;
        case ActionKind::set:
            session.set(action.argument, at);
            return;
        case ActionKind::export_trace:
        case ActionKind::export_table: {
            const std::string text =
                action.kind == ActionKind::export_trace ? exported_trace(session) : exported_table(session);
            if (action.argument != "-") {
                formats::write_file_atomically(action.argument, text, at);
                if (host) host->written(action.argument);
                return;
            }
            // "-": the command's standard output (cli/outputs.hpp).
            std::ostream* out = host ? host->standard_output() : nullptr;
            if (!out) throw formats::InputError(at, "standard output (\"-\") is not available here; name a file");
            out->write(text.data(), static_cast<std::streamsize>(text.size())).flush();
            return;
        }
        case ActionKind::screenshot:
        case ActionKind::view:
        case ActionKind::lesson_step:
        case ActionKind::key:
        case ActionKind::type:
        case ActionKind::quit:
            if (!host) throw formats::InputError(at, "only the inspector's window or --headless renderer can do this");
            if (action.kind == ActionKind::screenshot) {
                // The picture is taken a few frames later; "-" is standard output.
                if (action.argument == "-" && !host->standard_output())
                    throw formats::InputError(at, "standard output (\"-\") is not available here; name a file");
                if (action.argument != "-") formats::check_writable(action.argument, at);
                host->screenshot(action.argument);
            } else if (action.kind == ActionKind::view)
                host->view(action.argument);
            else if (action.kind == ActionKind::lesson_step)
                host->lesson_step(std::stoi(action.argument) - 1);
            else if (action.kind == ActionKind::key)
                host->key(action.argument);
            else if (action.kind == ActionKind::type)
                host->type(action.argument);
            else
                host->quit();
            return;
        default:
            return;
    }
}

}  // namespace impulse::model
