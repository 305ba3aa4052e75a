#include "model/session.hpp"

#include "formats/input_files.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "model/runs.hpp"

#include <algorithm>
#include <cstdio>

namespace impulse::model {

namespace {

bool is_trace(const nlohmann::ordered_json& document) {
    return document.is_object() && document.contains("format") && document["format"] == formats::trace_format_name;
}

}  // namespace

Session Session::open(const std::string& path, const OpenOptions& options) {
    return open_text(formats::read_input_file(path), path, options);
}

Session Session::open_text(const std::string& text, const std::string& path, const OpenOptions& options) {
    Session s;
    s.path_ = formats::input_name(path);
    nlohmann::ordered_json document;
    try {
        document = formats::parse_json_text(text);
        if (is_trace(document)) {
            s.kind_ = SourceKind::trace_file;
            s.trace_ = formats::read_trace(document);
        } else {
            s.scene_ = formats::read_scene(document, options.preset);
            s.kind_ = s.scene_.contacts.empty() ? SourceKind::scene_file : SourceKind::case_file;
        }
    } catch (const formats::InputError& e) {
        throw formats::FileError{s.path_, e.where(), e.problem()};
    }
    document = {};

    for (const std::string& spec : options.record) formats::apply_record_spec(spec, s.recording_);
    if (s.kind_ == SourceKind::trace_file) {
        // A trace is shown as recorded; its header is what a changed setting re-runs.
        if (const auto flag = options.first_given())
            throw formats::InputError(
                std::string(*flag),
                "a trace is shown as it was recorded; give a scene or case file to run it differently");
        s.scene_ = s.trace_.scene;
        s.recording_ = s.trace_.recording;
        s.resolve_ = !s.scene_.contacts.empty();
        s.frames_ = s.trace_.frames.empty() ? 1 : s.trace_.frames.back().frame + 1;
    } else {
        for (const std::string& assignment : options.settings) formats::apply_setting(s.scene_, assignment, "--set");
        s.trace_budget_ = formats::trace_budget_bytes(options.max_trace_mb);
        s.resolve_ = s.kind_ == SourceKind::case_file;
        if (options.frames && s.resolve_)
            throw formats::InputError("--frames",
                                      "a case (a scene with contacts written in it) is resolved once; "
                                      "--frames is for scenes that are simulated");
        s.frames_ = options.frames ? *options.frames : std::min(s.scene_.world.frames, default_inspect_frames);
        s.rerun();
    }
    s.cursor_ = first_cursor(s.trace_);
    return s;
}

Session Session::from_trace(Trace trace, SourceKind kind, std::string path) {
    Session s;
    s.path_ = std::move(path);
    s.kind_ = kind;
    s.scene_ = trace.scene;
    s.recording_ = trace.recording;
    s.resolve_ = !trace.scene.contacts.empty();
    s.frames_ = trace.frames.empty() ? 1 : trace.frames.back().frame + 1;
    s.trace_ = std::move(trace);
    s.cursor_ = first_cursor(s.trace_);
    return s;
}

void Session::rerun() {
    const TraceBudget budget{trace_budget_, &recording_stopped_at_, true};
    broken_run_.reset();
    trace_ = resolve_ ? resolve_once(scene_, recording_, budget, &broken_run_)
                      : run_frames(scene_, recording_, frames_, budget, &broken_run_);
}

std::optional<std::string> Session::recording_note() const {
    if (!recording_stopped_at_) return std::nullopt;
    const auto range = [](int first, int last) {
        return first == last ? std::to_string(first) : std::to_string(first) + ".." + std::to_string(last);
    };
    const int last_asked = resolve_ ? 0 : std::min(recording_.last_frame, frames_ - 1);
    const int first_asked = std::min(recording_.first_frame, last_asked);
    const std::string recorded = trace_.frames.empty() ? "no frame"
                                 : trace_.frames.size() == 1
                                     ? "frame " + std::to_string(trace_.frames.front().frame)
                                     : "frames " + range(trace_.frames.front().frame, trace_.frames.back().frame);
    char budget[32];
    std::snprintf(budget, sizeof budget, "%g", static_cast<double>(trace_budget_) / 1e6);
    return "recorded " + recorded + " of " + range(first_asked, last_asked) + " (the trace reached --max-trace-mb " +
           budget + " at frame " + std::to_string(*recording_stopped_at_) + ")";
}

void Session::set(std::string_view assignment, std::string_view where) {
    Scene changed = scene_;
    formats::apply_setting(changed, assignment, where);
    const std::optional<Location> here = cursor_ ? std::optional(location_of(trace_, *cursor_)) : std::nullopt;
    scene_ = std::move(changed);
    rerun();
    ++revision_;
    cursor_ = here ? nearest_cursor(trace_, *here) : first_cursor(trace_);
}

}  // namespace impulse::model
