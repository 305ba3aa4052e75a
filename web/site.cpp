#include "web/site.hpp"

#include "course/lesson_end.hpp"
#include "course/progress.hpp"
#include "formats/input_error.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_files.hpp"
#include "formats/trace_json.hpp"
#include "course/worksheet.hpp"
#include "gui/layout_check.hpp"
#include "gui/ui_state.hpp"
#include "web/page.hpp"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sys/stat.h>

namespace impulse::web {

struct Site::Open {
    int lesson_number = 0;  // 0: a file
    std::optional<course::PreparedLesson> lesson;
    std::optional<model::Session> session;
    std::unique_ptr<gui::InspectorApp> app;

    model::Session& inspected() { return lesson ? lesson->session : *session; }
};

namespace {

std::string file_error_text(const formats::FileError& e) {
    return std::filesystem::path(e.file).filename().string() + ": " + (e.where.empty() ? "" : e.where + ": ") +
           e.problem;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

const char* question_state(course::QuestionState state) {
    switch (state) {
        case course::QuestionState::open:
            return "open";
        case course::QuestionState::answered:
            return "answered";
        case course::QuestionState::skipped:
            return "skipped";
        default:
            return "none";
    }
}

}  // namespace

Site::Site() {
    display_.emplace(gui::DisplayOptions{});
    progress_file_ = course::progress_file();
    if (progress_file_) {
        course::LoadedProgress loaded = course::load_progress(*progress_file_);
        progress_ = std::move(loaded.progress);
        if (!loaded.note.empty()) message_ = loaded.note, message_is_error_ = true;
    }
    struct stat info {};
    if (progress_file_ && ::stat(progress_file_->c_str(), &info) == 0)
        saved_stamp_ =
            std::to_string(info.st_ino) + ":" + std::to_string(info.st_size) + ":" + std::to_string(info.st_mtime);
    actions_.open_lesson = [this](int number) { pending_ = [this, number] { open_lesson(number); }; };
    actions_.open_file = [this](const std::filesystem::path& file) { pending_ = [this, file] { open_file(file); }; };
    actions_.pick_file = [] { pick_file(Pick::open); };
    actions_.import_progress = [] { pick_file(Pick::progress); };
    actions_.worksheet = [this](int number) { pending_ = [this, number] { download_worksheet(number); }; };
    actions_.export_progress = [this] {
        if (!progress_file_) return;
        if (!std::filesystem::exists(*progress_file_)) course::save_progress(*progress_file_, progress_);
        offer_download(progress_file_->string());
    };
    listing_ = gui::list_course(data_folder, progress_);
}

Site::~Site() = default;

void Site::show_start(const std::string& message, bool is_error) {
    open_.reset();
    message_ = message, message_is_error_ = is_error;
    listing_ = gui::list_course(data_folder, progress_);
    settle_ = 3;
}

std::optional<std::filesystem::path> Site::lesson_file(int number) const {
    for (const std::filesystem::path& f : course::lesson_files(std::filesystem::path(data_folder) / "lessons"))
        if (std::atoi(f.filename().string().c_str()) == number) return f;
    return std::nullopt;
}

void Site::download_worksheet(int number) {
    const std::optional<std::filesystem::path> file = lesson_file(number);
    if (!file) return show_start("there is no lesson " + std::to_string(number), true);
    try {
        // As `impulse-lab worksheet LESSON.md --out sheet.csv` (cli/worksheet_command.cpp): the lesson's steps
        // that compute something to fill in.
        const course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson(*file));
        const formats::json document = formats::trace_json(lesson.session.trace());
        const std::vector<model::Cursor> places = course::places_with_cells(lesson.session, lesson.places, &document);
        const course::Worksheet sheet = course::make_worksheet(lesson.session, places, &document);
        std::filesystem::create_directories(downloads_folder);
        const std::string path = std::string(downloads_folder) + "/" + file->stem().string() + "-worksheet.csv";
        formats::write_file_atomically(path, course::worksheet_csv(sheet), path);
        offer_download(path);
        show_start("lesson " + std::to_string(number) + "'s worksheet: " + std::to_string(sheet.steps.size()) +
                   " steps to fill in, downloaded as " + std::filesystem::path(path).filename().string());
    } catch (const formats::FileError& e) {
        show_start(file_error_text(e), true);
    } catch (const formats::InputError& e) {
        show_start(file->filename().string() + ": " + e.what(), true);
    }
}

void Site::open_lesson(int number) {
    const std::optional<std::filesystem::path> file = lesson_file(number);
    if (!file) return show_start("there is no lesson " + std::to_string(number), true);
    auto open = std::make_unique<Open>();
    open->lesson_number = number;
    try {
        open->lesson.emplace(course::prepare_lesson(course::read_lesson(*file)));
    } catch (const formats::FileError& e) {
        return show_start(file_error_text(e), true);
    }
    gui::InspectorRun run;
    run.lesson = &*open->lesson;
    run.progress = &progress_;
    run.progress_file = progress_file_;
    run.offer_file = offer_download;
    // The lesson's end offers the next one; opening it comes back here (frame()).
    run.next_lesson = course::lesson_after(std::filesystem::path(data_folder) / "lessons", number);
    open->app = std::make_unique<gui::InspectorApp>(open->inspected(), run, *display_, errors_);
    open->app->state().record_layout = true;  // the lesson panel's items, for the test hook
    open_ = std::move(open);
    set_fragment("#lesson=" + std::to_string(number));
}

void Site::open_file(const std::filesystem::path& file) {
    auto open = std::make_unique<Open>();
    try {
        open->session.emplace(model::Session::open(file.string(), {}));
    } catch (const formats::FileError& e) {
        return show_start(file_error_text(e), true);
    } catch (const formats::InputError& e) {
        return show_start(file.filename().string() + ": " + e.what(), true);
    }
    gui::InspectorRun run;
    run.offer_file = offer_download;
    open->app = std::make_unique<gui::InspectorApp>(open->inspected(), run, *display_, errors_);
    open->app->state().record_layout = true;  // the tabs and export buttons, for the test hook
    open_ = std::move(open);
    // A shipped file has an address of its own; the student's own file has none to come back to.
    const std::string folder = file.parent_path().filename().string();
    if (file.string().starts_with(data_folder))
        set_fragment((folder == "cases" ? "#case=" : "#scene=") + file.stem().string());
}

void Site::route(const std::string& fragment) {
    const auto value = [&fragment](std::string_view key) -> std::optional<std::string> {
        if (!fragment.starts_with(key)) return std::nullopt;
        return fragment.substr(key.size());
    };
    const std::filesystem::path scenes = std::filesystem::path(data_folder) / "scenes";
    if (const auto number = value("#lesson="))
        open_lesson(std::atoi(number->c_str()));
    else if (const auto name = value("#scene="))
        open_file(scenes / (*name + ".json"));
    else if (const auto name = value("#case="))
        open_file(scenes / "cases" / (*name + ".json"));
    else if (open_)
        show_start();
}

void Site::file_picked(const std::string& path, bool as_progress) {
    if (!as_progress) return open_file(path);
    try {
        course::Progress imported = course::read_progress_text(read_text(path));
        if (progress_file_) course::save_progress(*progress_file_, imported);
        progress_ = std::move(imported);
        show_start("progress imported: " + std::to_string(progress_.lessons.size()) + " lesson(s)");
    } catch (const formats::InputError& e) {
        show_start(std::filesystem::path(path).filename().string() + ": " + e.what(), true);
    }
}

void Site::save_if_changed() {
    if (!progress_file_) return;
    struct stat info {};
    if (::stat(progress_file_->c_str(), &info) != 0) return;
    // An atomic write replaces the file: a new inode each time, so two saves in one millisecond still differ.
    const std::string stamp =
        std::to_string(info.st_ino) + ":" + std::to_string(info.st_size) + ":" + std::to_string(info.st_mtime);
    if (stamp == saved_stamp_) return;
    store(progress_file_->string());
    saved_stamp_ = stamp;
}

void Site::frame() {
    ++frames_;
    if (open_) {
        gui::InspectorApp& app = *open_->app;
        if (app.idle() && !display_->events_waiting()) return;
        if (!app.frame()) {  // Esc in a lesson, or the inspector quit: back to the start page
            save_if_changed();
            // Or on to the next lesson, when the lesson's end opened it.
            const auto& lesson = app.state().lesson;
            if (lesson && lesson->open_next && lesson->next_lesson) return open_lesson(lesson->next_lesson->number);
            set_fragment("");
            show_start();
            return;
        }
        save_if_changed();
        return;
    }
    if (settle_ <= 0 && !display_->events_waiting()) return;
    display_->begin_frame();
    settle_ = display_->had_events() ? 3 : settle_ - 1;
    gui::draw_start_page(listing_, message_, message_is_error_, actions_, &start_controls_);
    display_->end_frame();
    if (pending_) {
        const auto action = std::move(pending_);
        pending_ = nullptr;
        action();
    }
}

std::string Site::test_state() const {
    nlohmann::ordered_json state;
    const ImGuiIO& io = ImGui::GetIO();
    state["frames"] = frames_;
    state["screen"] = !open_ ? "start" : open_->lesson ? "lesson" : "inspector";
    state["width"] = io.DisplaySize.x;
    state["height"] = io.DisplaySize.y;
    state["pixel_ratio"] = io.DisplayFramebufferScale.x;
    state["message"] = message_;
    state["message_is_error"] = message_is_error_;
    state["idle"] = open_ ? open_->app->idle() : settle_ <= 0;
    nlohmann::ordered_json lessons = nlohmann::ordered_json::array();
    for (const gui::CourseListing::LessonLine& l : listing_.lessons)
        lessons.push_back({{"number", l.number}, {"title", l.title}, {"progress", l.progress}});
    state["lessons"] = lessons;
    const auto boxes = [](const std::vector<gui::LaidOutItem>& items) {
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (const gui::LaidOutItem& item : items)
            list.push_back({{"what", item.what}, {"box", {item.min_x, item.min_y, item.max_x, item.max_y}}});
        return list;
    };
    state["controls"] = boxes(open_ ? open_->app->state().controls : start_controls_);
    if (open_) {
        const gui::UiState& ui = open_->app->state();
        state["inspector_message"] = ui.message;
        state["inspector_message_is_error"] = ui.message_is_error;
        state["file"] = open_->lesson ? open_->lesson->lesson.file.string() : open_->session->path();
        if (ui.lesson) {
            const course::LessonRun& run = ui.lesson->run;
            nlohmann::ordered_json lesson;
            lesson["number"] = open_->lesson_number;
            lesson["title"] = run.lesson().lesson.title;
            lesson["step"] = run.step() + 1;
            lesson["steps"] = run.step_count();
            lesson["step_id"] = run.current().id;
            if (const auto& q = run.current().question) {
                lesson["question"] = {
                    {"kind", q->kind == course::Question::Kind::predict ? "predict" : "choose"},
                    {"state", question_state(run.state(run.step()))},
                    {"feedback", run.feedback(run.step())},
                    {"options", q->options.size()},
                };
            } else {
                lesson["question"] = nullptr;
            }
            lesson["typed"] = std::string(ui.lesson->typed.data());  // the answer field's text
            lesson["tally"] = course::tally_text(run.tally());
            state["lesson"] = lesson;
        }
        nlohmann::ordered_json items = nlohmann::ordered_json::array();
        for (const gui::LaidOutItem& item : ui.layout)
            items.push_back({{"what", item.what}, {"box", {item.min_x, item.min_y, item.max_x, item.max_y}}});
        state["items"] = items;
    }
    return state.dump();
}

std::string Site::layout_check(int width, int height) {
    if (!open_ || !open_->lesson) return "no lesson is open";
    const gui::LayoutReport report = gui::check_lesson_layout(*open_->lesson, width, height);
    // The check walked the lesson's session through every step: back to where the student is.
    gui::UiState& ui = open_->app->state();
    gui::go_to_lesson_step(open_->inspected(), ui, ui.lesson->run.step());
    gui::refresh_mask(open_->inspected(), ui);
    std::string text = std::to_string(report.states) + " states, " + std::to_string(report.items) + " items\n";
    for (const std::string& problem : report.problems) text += problem + "\n";
    return text;
}

}  // namespace impulse::web
