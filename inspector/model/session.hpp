#pragma once
// What the inspector has open: the file's scene (or the trace's), the trace it made, and the cursor.
// A setting changed in the window or a script re-runs the scene and brings the cursor back to the same
// place where that still exists. No rendering here, so the tests drive it exactly as the window does.

#include "model/navigator.hpp"
#include "model/runs.hpp"
#include "formats/input_files.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::model {

enum class SourceKind {
    case_file,   // a scene with contacts written in it: resolved once (`resolve`)
    scene_file,  // a scene without: simulated frame by frame (`run`)
    trace_file,  // a recorded trace: shown as it is, re-run from its header when a setting changes
};

struct OpenOptions {
    std::optional<std::string> preset;  // --preset
    std::vector<std::string> settings;  // --set name=value, in order
    std::vector<std::string> record;    // --record frames=A..B / contacts=I,J
    std::optional<int> frames;          // frames to simulate for a scene (default: up to 60, the first second)
    std::optional<double>
        max_trace_mb;  // --max-trace-mb: the recording's budget (default: formats::default_max_trace_mb)

    // The flag of the first option given ("--preset", "--set", "--frames", "--record"), or none: for the
    // sources that run as they were made (a trace, a worksheet, a lesson) and refuse all four.
    std::optional<std::string_view> first_given() const {
        if (preset) return "--preset";
        if (!settings.empty()) return "--set";
        if (frames) return "--frames";
        if (!record.empty()) return "--record";
        if (max_trace_mb) return "--max-trace-mb";
        return std::nullopt;
    }
};

inline constexpr int default_inspect_frames = 60;

class Session {
public:
    // Reads, checks and runs the file. Throws formats::FileError for a bad file and formats::InputError for a bad
    // flag, before anything is shown.
    static Session open(const std::string& path, const OpenOptions& options);
    // The same for a file already read (standard input, or a file a caller looked into first); `path` names it.
    static Session open_text(const std::string& text, const std::string& path, const OpenOptions& options);
    // A session over a trace already in memory (tests, lessons).
    static Session from_trace(Trace trace, SourceKind kind, std::string path);

    const std::string& path() const { return path_; }
    SourceKind kind() const { return kind_; }
    const Trace& trace() const { return trace_; }
    // None when the trace records nothing to step through (e.g. no contact in the recorded frames).
    const std::optional<Cursor>& cursor() const { return cursor_; }
    void move_to(const Cursor& cursor) { cursor_ = cursor; }

    // Applies "name=value" as --set does (`where` names the source of the change in errors), re-runs, and
    // keeps the cursor on the same frame, contact and step where they still exist.
    void set(std::string_view assignment, std::string_view where);
    // Counts re-runs, so views built from the trace know when to rebuild.
    int revision() const { return revision_; }
    // The settings as run (the trace's header).
    const ResolverSettings& settings() const { return trace_.scene.settings; }
    // The frame at which the last run's recording reached --max-trace-mb and stopped, if it did. A scene's run
    // stops there too: the inspector shows what it recorded, so every frame it runs is a frame it shows.
    std::optional<int> recording_stopped_at() const { return recording_stopped_at_; }
    // Which frames the last run recorded when the budget cut it short, for the window's status line after every
    // (re-)run and the terminal: "recorded frames 0..6 of 0..59 (the trace reached --max-trace-mb 200 at frame
    // 7)". None when it recorded every frame asked for.
    std::optional<std::string> recording_note() const;
    // Where the last run stopped because a body's state became NaN or infinite, if it did: the trace ends
    // before that frame.
    const std::optional<BrokenRun>& broken_run() const { return broken_run_; }

private:
    void rerun();

    std::string path_;
    SourceKind kind_ = SourceKind::case_file;
    Scene scene_;  // what is re-run: the file's scene with the flags applied
    TraceFilter recording_;
    int frames_ = 1;       // scene and trace files: how many frames a re-run simulates
    bool resolve_ = true;  // re-run by resolving the written contacts once, else by simulating frames
    std::size_t trace_budget_ = formats::trace_budget_bytes(std::nullopt);  // bytes a run may record
    std::optional<int> recording_stopped_at_;
    std::optional<BrokenRun> broken_run_;
    Trace trace_;
    std::optional<Cursor> cursor_;
    int revision_ = 0;
};

}  // namespace impulse::model
