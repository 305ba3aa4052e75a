#include "course/progress.hpp"

#include "formats/input_files.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <limits>
#include <cstdlib>
#include <cerrno>
#include <cstdio>
#include <ctime>
#include <fcntl.h>
#include <sys/stat.h>

namespace impulse::course {

namespace {

using json = nlohmann::ordered_json;
constexpr std::string_view format_name = "impulse-lab-progress";

// Renames `from` to `to` unless `to` exists (then -1 with errno EEXIST). Linux's renameat2 does it in one step; the
// browser's file system (emscripten's) has no renameat2 and one thread, where a look before the rename is the same.
int rename_no_replace(const std::filesystem::path& from, const std::filesystem::path& to) {
#ifdef __EMSCRIPTEN__
    struct stat info {};
    if (::stat(to.c_str(), &info) == 0) {
        errno = EEXIST;
        return -1;
    }
    return std::rename(from.c_str(), to.c_str());
#else
    return ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE);
#endif
}

// A whole number from 0 to INT_MAX at `path`; anything else (a fraction, a huge or negative number, text)
// is an error, never a cast.
int read_count(const json& object, const std::string& path, const char* key) {
    const std::string where = formats::json_path_child(path, key);
    if (!object.contains(key)) throw formats::InputError(where, "missing");
    const json& value = object[key];
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
        value.get<std::int64_t>() > std::numeric_limits<int>::max())
        throw formats::InputError(where, "must be a whole number from 0 to " +
                                             std::to_string(std::numeric_limits<int>::max()) + ", got " + value.dump());
    return static_cast<int>(value.get<std::int64_t>());
}

const json& member(const json& object, const std::string& path, const char* key, json::value_t type,
                   const char* type_name) {
    const std::string where = formats::json_path_child(path, key);
    if (!object.contains(key)) throw formats::InputError(where, "missing");
    if (object[key].type() != type) throw formats::InputError(where, std::string("must be ") + type_name);
    return object[key];
}

}  // namespace

Progress read_progress_text(std::string_view text) {
    const json document = formats::parse_json_text(text);
    if (!document.is_object() || document.value("format", json()) != format_name ||
        document.value("version", json()) != 1)
        throw formats::InputError("", "not an impulse-lab-progress file of version 1");
    Progress progress;
    for (const auto& [name, lesson] : member(document, "", "lessons", json::value_t::object, "an object").items()) {
        const std::string path = formats::json_path_child("lessons", name);
        if (!lesson.is_object()) throw formats::InputError(path, "must be an object");
        LessonProgress p;
        p.last_step = read_count(lesson, path, "last_step");
        const std::string answers_path = formats::json_path_child(path, "answers");
        for (const auto& [id, a] : member(lesson, path, "answers", json::value_t::object, "an object").items()) {
            const std::string where = formats::json_path_child(answers_path, id);
            if (!a.is_object()) throw formats::InputError(where, "must be an object");
            p.answers[id] = {member(a, where, "answer", json::value_t::string, "text").get<std::string>(),
                             member(a, where, "correct", json::value_t::boolean, "true or false").get<bool>(),
                             read_count(a, where, "tries"),
                             // Written since skipping was added; older files have no skipped question.
                             a.contains("skipped") &&
                                 member(a, where, "skipped", json::value_t::boolean, "true or false").get<bool>()};
        }
        progress.lessons[name] = std::move(p);
    }
    return progress;
}

namespace {

std::string time_stamp() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &utc);
    return text;
}

}  // namespace

Tally tally(const LessonProgress& lesson) {
    Tally t;
    for (const auto& [id, a] : lesson.answers) {
        if (a.skipped)
            ++t.skipped;
        else if (a.correct)
            ++(a.tries <= 1 ? t.first_try : t.after_retries);
        else if (a.tries > 0)
            ++t.open;
    }
    return t;
}

std::string tally_text(const Tally& t) {
    std::string text;
    const auto part = [&text](int n, const std::string& what) {
        if (n > 0) text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + what;
    };
    part(t.first_try, "right at the first try");
    part(t.after_retries, "right after retries");
    part(t.skipped, "skipped");
    part(t.open, "tried, not yet right");
    return text.empty() ? "none answered yet" : text;
}

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
    std::string why;
    try {
        return {read_progress_text(formats::read_input_file(file.string(), formats::max_text_input_bytes)), {}};
    } catch (const formats::FileError& e) {
        why = e.problem;  // unreadable, or larger than any progress file we write
    } catch (const std::exception& e) {
        why = e.what();
    }
    // Kept aside, never deleted: the student (or a teacher) may want to look at it. Two corrupt files within one
    // second (a second start of the same broken file, a file broken again) each keep their own name: the rename
    // never replaces a file already there (-2, -3, ... after the time).
    std::filesystem::path aside;
    const std::string stamp = file.string() + ".corrupt-" + time_stamp();
    for (int n = 1; n <= 1000; ++n) {
        aside = n == 1 ? stamp : stamp + "-" + std::to_string(n);
        if (rename_no_replace(file, aside) == 0) {
            error.clear();
            break;
        }
        error = std::error_code(errno, std::generic_category());
        if (errno != EEXIST) break;
    }
    return {{},
            "progress file " + file.string() + " is unreadable (" + why + "); " +
                (error ? "it is left where it is and progress starts afresh"
                       : "kept as " + aside.filename().string() + ", progress starts afresh")};
}

void save_progress(const std::filesystem::path& file, const Progress& progress) {
    json lessons = json::object();
    for (const auto& [name, p] : progress.lessons) {
        json answers = json::object();
        for (const auto& [id, a] : p.answers)
            answers[id] = {{"answer", a.answer}, {"correct", a.correct}, {"tries", a.tries}, {"skipped", a.skipped}};
        lessons[name] = {{"last_step", p.last_step}, {"answers", answers}};
    }
    const json document = {{"format", format_name}, {"version", 1}, {"lessons", lessons}};
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    if (error)
        throw formats::InputError("progress", "cannot create " + file.parent_path().string() + ": " + error.message());
    formats::write_file_atomically(file, formats::format_json(document), "progress");
}

}  // namespace impulse::course
