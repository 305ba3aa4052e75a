#pragma once
// A student's progress through the lessons: each question's last answer and whether it was right, and the
// step each lesson was left at. Kept per user in the standard config location
// ($XDG_CONFIG_HOME/impulse-lab/progress.json, else ~/.config/impulse-lab/progress.json) and written
// atomically. A file that cannot be read is moved aside and reported, never silently dropped.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace impulse::course {

struct AnswerRecord {
    std::string answer;  // the last answer, as typed
    bool correct = false;
    int tries = 0;         // answers given (a skip is not one)
    bool skipped = false;  // the student asked for the answer instead (kept as "skipped"; files before it lack it)
};

// How a lesson's questions went: right at the first try, right after wrong tries, skipped, and tried but
// still open (only wrong answers so far).
struct Tally {
    int first_try = 0;
    int after_retries = 0;
    int skipped = 0;
    int open = 0;
};

struct LessonProgress {
    int last_step = 0;                            // index of the step the student was last on
    std::map<std::string, AnswerRecord> answers;  // by step id
};

struct Progress {
    std::map<std::string, LessonProgress> lessons;  // by lesson name ("01-impulse-is-a-velocity-change")
};

Tally tally(const LessonProgress& lesson);
// "3 right at the first try, 1 after retries, 1 skipped" (the parts that are not 0), or "none answered yet".
std::string tally_text(const Tally& tally);

// Where progress is kept; none when neither XDG_CONFIG_HOME nor HOME is set.
std::optional<std::filesystem::path> progress_file();

struct LoadedProgress {
    Progress progress;
    std::string note;  // one line when a corrupt file was moved aside ("... kept as progress.json.corrupt-...")
};
// Progress from a file's text, as save_progress writes it; throws formats::InputError(JSON path, problem) for
// anything else. Touches no file.
Progress read_progress_text(std::string_view text);

// A missing file is empty progress. A corrupt one is renamed beside itself with a time stamp and reported.
LoadedProgress load_progress(const std::filesystem::path& file);

// Writes atomically (creating the folder); throws formats::InputError("progress", ...) when it cannot.
void save_progress(const std::filesystem::path& file, const Progress& progress);

}  // namespace impulse::course
