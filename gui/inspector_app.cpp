#include "gui/inspector_app.hpp"

#include "gui/display.hpp"
#include "gui/key_events.hpp"
#include "gui/layout_memory.hpp"
#include "gui/panels.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <numeric>

namespace impulse::gui {

namespace {

// Screenshots wait for the panels to settle: ImGui sizes tables and scrolls to the cursor over a frame.
constexpr int settle_frames = 2;

class Host final : public model::ActionHost {
public:
    Host(model::Session& session, UiState& state) : session_(session), state_(state), camera_(state.camera) {}

    void lesson_step(int step) override {
        if (!state_.lesson) throw formats::InputError("lesson step", "no lesson is open");
        const int count = state_.lesson->run.step_count();
        if (step >= count)
            throw formats::InputError("lesson step", "the lesson has steps 1.." + std::to_string(count) + ", not " +
                                                         std::to_string(step + 1));
        go_to_lesson_step(session_, state_, step);
    }

    void view(const std::string& plane) override {
        camera_.plane = plane == "top"    ? ViewPlane::top
                        : plane == "side" ? ViewPlane::side
                        : plane == "3d"   ? ViewPlane::perspective
                                          : ViewPlane::front;
    }
    void screenshot(const std::string& path) override {
        pending_ = path;
        settle_ = settle_frames;
    }
    void quit() override { quit_ = true; }
    void key(const std::string& chord) override { push_key(chord); }
    void type(const std::string& text) override { push_text(text); }
    std::ostream* standard_output() override { return standard_output_; }
    void set_standard_output(std::ostream* out) { standard_output_ = out; }
    void written(const std::string& path) override {
        if (offer_file_) offer_file_(path);
    }
    void set_offer_file(std::function<void(const std::string&)> offer) { offer_file_ = std::move(offer); }

    bool quitting() const { return quit_; }
    bool waiting() const { return pending_.has_value(); }
    // Whether this frame is the one to read back; counts the settling frames down.
    bool capture_now() { return pending_ && settle_-- <= 0; }
    std::string take() {
        std::string path = *pending_;
        pending_.reset();
        return path;
    }

private:
    model::Session& session_;
    UiState& state_;
    SceneCamera& camera_;
    std::optional<std::string> pending_;
    int settle_ = 0;
    bool quit_ = false;
    std::ostream* standard_output_ = nullptr;
    std::function<void(const std::string&)> offer_file_;
};

double percentile(std::vector<double> sorted, double p) {
    std::sort(sorted.begin(), sorted.end());
    const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
    const auto low = static_cast<std::size_t>(rank);
    const std::size_t high = std::min(low + 1, sorted.size() - 1);
    return sorted[low] + (sorted[high] - sorted[low]) * (rank - static_cast<double>(low));
}

void print_bench(std::ostream& out, const InspectorRun& run, const std::vector<double>& ms, const Trace& trace) {
    const ImDrawData* drawn = ImGui::GetDrawData();
    int draw_calls = 0;
    for (int i = 0; drawn && i < drawn->CmdListsCount; ++i) draw_calls += drawn->CmdLists[i]->CmdBuffer.Size;
    const int vertices = drawn ? drawn->TotalVtxCount : 0;
    std::size_t contacts = 0, iterations = 0;
    for (const FrameRecord& f : trace.frames)
        contacts += f.contacts.size(), iterations += f.position.iterations.size() + f.velocity.iterations.size();
    char line[512];
    std::snprintf(
        line, sizeof line,
        "bench: %zu frames at %dx%d %s, one derivation step per frame; trace: %zu frame(s), %zu contacts, "
        "%zu iterations\n"
        "  opened in %.0f ms\n"
        "  frame time ms: p50 %.2f  p90 %.2f  p99 %.2f  max %.2f  mean %.2f  (last frame: %d vertices, %d draw "
        "calls)\n",
        ms.size(), run.width, run.height, run.headless ? "headless" : "in a window", trace.frames.size(), contacts,
        iterations, run.load_seconds * 1e3, percentile(ms, 50), percentile(ms, 90), percentile(ms, 99),
        *std::max_element(ms.begin(), ms.end()),
        std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size()), vertices, draw_calls);
    out << line;
}

}  // namespace

struct InspectorApp::Impl {
    Impl(model::Session& s, const InspectorRun& r, Display& d, std::ostream& e)
        : session(s), run(r), display(d), err(e), host(s, state), layout(!r.headless) {}

    model::Session& session;
    InspectorRun run;
    Display& display;
    std::ostream& err;
    UiState state;
    Host host;
    std::deque<model::Action> queue;
    bool close_when_done = false;
    Pixels pixels;
    // ImGui settles a layout over a couple of frames after any input, so a window only idles after a few.
    int busy_frames = 3;
    bool done = false;
    int status = 0;
    RememberedLayout layout;  // a window remembers where its borders were dragged

    void fail(const std::string& line) {
        err << "impulse-lab: " << line << '\n';
        status = 2;
        done = true;
    }
    void write_screenshot();
    void next_action();
};

InspectorApp::InspectorApp(model::Session& session, const InspectorRun& run, Display& display, std::ostream& err)
    : impl_(std::make_unique<Impl>(session, run, display, err)) {
    Impl& m = *impl_;
    m.queue.assign(run.script.begin(), run.script.end());
    if (run.screenshot) m.queue.push_back({model::ActionKind::screenshot, *run.screenshot, 1, 0});
    // Headless, or after a final screenshot, the inspector closes once everything asked for is done.
    m.close_when_done = run.headless || run.screenshot.has_value();
    UiState& state = m.state;
    // The run stopped early: say where in the status line, not only on the terminal.
    if (session.broken_run()) {
        state.message = "the run stopped at " + model::broken_run_text(session.trace().scene, *session.broken_run());
        state.message_is_error = true;
    } else if (const auto note = session.recording_note()) {
        state.message = *note;  // which frames there are to step through
    }
    if (run.lesson) {
        // Back where the student left off, with the answers they gave shown again.
        state.lesson.emplace(course::LessonRun(*run.lesson, run.progress, run.progress_file), run.lesson_preview);
        state.lesson->next_lesson = run.next_lesson;
        go_to_lesson_step(session, state, state.lesson->run.step());
        refresh_mask(session, state);
    }
    m.host.set_standard_output(run.standard_output);
    m.host.set_offer_file(run.offer_file);
}

InspectorApp::~InspectorApp() {
    impl_->layout.keep(impl_->state);
}

int InspectorApp::status() const {
    return impl_->status;
}

UiState& InspectorApp::state() {
    return impl_->state;
}

bool InspectorApp::idle() const {
    const Impl& m = *impl_;
    return m.queue.empty() && !m.host.waiting() && m.busy_frames <= 0;
}

void InspectorApp::Impl::write_screenshot() {
    const std::string path = host.take();
    try {
        const std::string png = encode_png(pixels);
        if (run.standard_output && path == "-") {
            run.standard_output->write(png.data(), static_cast<std::streamsize>(png.size())).flush();
        } else {
            formats::write_file_atomically(path, png, path);
            host.written(path);
        }
    } catch (const std::exception& e) {
        // A script's or --screenshot's failure ends the run; the window's button reports it and goes on.
        if (close_when_done || !queue.empty()) return fail(e.what());
        state.message = e.what();
        state.message_is_error = true;
    }
}

void InspectorApp::Impl::next_action() {
    const model::Action action = queue.front();
    queue.pop_front();
    const std::string where =
        action.line > 0 ? run.script_name + ": line " + std::to_string(action.line) : std::string("--screenshot");
    try {
        model::perform(session, action, where, &host);
        // A re-run says what it gave, in the window and (for a script) on the terminal when the recording
        // was cut short: the frames a later goto can reach.
        if (action.kind == model::ActionKind::set) {
            state.message = model::rerun_text(session, action.argument, &state.message_is_error);
            if (session.recording_note()) err << "impulse-lab: note: " << where << ": " << state.message << '\n';
        }
    } catch (const formats::InputError& e) {
        fail(e.what());
    }
}

bool InspectorApp::frame() {
    Impl& m = *impl_;
    if (m.done) return false;
    if (!m.display.begin_frame(idle())) {
        m.done = true;
        return false;
    }
    m.busy_frames = m.display.had_events() ? 3 : m.busy_frames - 1;
    m.state.pressed_keys = m.display.pressed_keys();
    m.layout.take_up(m.state);
    draw_inspector(m.session, m.state, m.host);
    const bool capture = m.host.capture_now();
    m.display.end_frame(capture ? &m.pixels : nullptr);
    if (capture) m.write_screenshot();
    if (m.done) return false;
    if (m.host.quitting() || m.state.quit)
        m.done = true;
    else if (m.host.waiting())
        return true;
    else if (!m.queue.empty())
        m.next_action();
    else if (m.close_when_done)
        m.done = true;
    return !m.done;
}

void InspectorApp::bench(int frames, std::ostream& out) {
    Impl& m = *impl_;
    model::Session& session = m.session;
    std::vector<double> ms;
    ms.reserve(static_cast<std::size_t>(frames));
    for (int i = 0; i < frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        // Every frame moves one step (wrapping at the end), so each rebuilds the views: the worst case.
        if (session.cursor()) {
            std::optional<model::Cursor> next = model::next_step(session.trace(), *session.cursor());
            if (!next) next = model::first_cursor(session.trace());
            session.move_to(*next);
        }
        if (!m.display.begin_frame()) break;
        draw_inspector(session, m.state, m.host);
        m.display.end_frame();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    if (!ms.empty()) print_bench(out, m.run, ms, session.trace());
}

int run_inspector(model::Session& session, const InspectorRun& run, std::ostream& out, std::ostream& err) {
    // Every file the run will write must be writable before anything is shown or written.
    try {
        for (const model::Action& a : run.script)
            if (a.kind == model::ActionKind::screenshot || a.kind == model::ActionKind::export_trace ||
                a.kind == model::ActionKind::export_table)
                if (!(run.standard_output && a.argument == "-"))
                    formats::check_writable(a.argument, run.script_name + ": line " + std::to_string(a.line));
        if (run.screenshot && !(run.standard_output && *run.screenshot == "-"))
            formats::check_writable(*run.screenshot, "--screenshot");
    } catch (const formats::InputError& e) {
        err << "impulse-lab: " << e.what() << '\n';
        return 2;
    }

    std::optional<Display> display;
    try {
        display.emplace(
            DisplayOptions{run.headless, run.width, run.height, run.fit_to_screen, "Impulse Lab — " + session.path()});
    } catch (const DisplayError& e) {
        err << "impulse-lab: inspect: " << e.what() << '\n';
        return 2;
    }
    if (!display->font_note().empty()) err << "impulse-lab: note: " << display->font_note() << '\n';

    InspectorApp app(session, run, *display, err);
    while (app.frame()) {
    }
    if (run.next_lesson_chosen && app.state().lesson) *run.next_lesson_chosen = app.state().lesson->open_next;
    if (app.status() != 0) return app.status();
    if (run.bench_frames) app.bench(*run.bench_frames, out);
    return 0;
}

}  // namespace impulse::gui
