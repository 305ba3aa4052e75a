#include "lessons/progress.hpp"

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/json_text.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>

namespace impulse::lessons {

namespace {

using json = nlohmann::ordered_json;
constexpr std::string_view format_name = "impulse-lab-progress";

// Throws std::exception (any) when the document is not progress as written by save_progress.
Progress read(const json& document) {
    if (!document.is_object() || document.value("format", "") != format_name || document.value("version", 0) != 1)
        throw std::runtime_error("not an impulse-lab-progress file of version 1");
    Progress progress;
    for (const auto& [name, lesson] : document.at("lessons").items()) {
        LessonProgress p;
        p.last_step = lesson.at("last_step").get<int>();
        if (p.last_step < 0) throw std::runtime_error("lessons." + name + ".last_step: negative");
        for (const auto& [id, a] : lesson.at("answers").items())
            p.answers[id] = {a.at("answer").get<std::string>(), a.at("correct").get<bool>(), a.at("tries").get<int>()};
        progress.lessons[name] = std::move(p);
    }
    return progress;
}

std::string time_stamp() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &utc);
    return text;
}

}  // namespace

std::optional<std::filesystem::path> progress_file() {
    if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config)
        return std::filesystem::path(config) / "impulse-lab" / "progress.json";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".config" / "impulse-lab" / "progress.json";
    return std::nullopt;
}

LoadedProgress load_progress(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::exists(file, error)) return {};
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
        if (!in) throw std::runtime_error("cannot be read");
        return {read(io::parse_json_text(text.str())), {}};
    } catch (const std::exception& e) {
        // Kept aside, never deleted: the student (or a teacher) may want to look at it.
        const std::filesystem::path aside = file.string() + ".corrupt-" + time_stamp();
        std::filesystem::rename(file, aside, error);
        const std::string why = dynamic_cast<const io::InputError*>(&e) ? std::string(e.what()) : e.what();
        return {{},
                "progress file " + file.string() + " is unreadable (" + why + "); " +
                    (error ? "it is left where it is and progress starts afresh"
                           : "kept as " + aside.filename().string() + ", progress starts afresh")};
    }
}

void save_progress(const std::filesystem::path& file, const Progress& progress) {
    json lessons = json::object();
    for (const auto& [name, p] : progress.lessons) {
        json answers = json::object();
        for (const auto& [id, a] : p.answers)
            answers[id] = {{"answer", a.answer}, {"correct", a.correct}, {"tries", a.tries}};
        lessons[name] = {{"last_step", p.last_step}, {"answers", answers}};
    }
    const json document = {{"format", format_name}, {"version", 1}, {"lessons", lessons}};
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    if (error)
        throw io::InputError("progress", "cannot create " + file.parent_path().string() + ": " + error.message());
    io::write_file_atomically(file, io::format_json(document), "progress");
}

}  // namespace impulse::lessons
