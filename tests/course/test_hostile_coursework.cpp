// Coursework as an attacker or a careless student hands it in (issue 29), and what a teacher meets (issue 26):
// each case is named after what went wrong before it was held.

#include "course/json_path.hpp"
#include "course/lesson.hpp"
#include "course/lesson_run.hpp"
#include "course/progress.hpp"
#include "course/worksheet.hpp"
#include "formats/csv.hpp"
#include "formats/json_text.hpp"
#include "formats/trace_json.hpp"

#include "support/opened.hpp"
#include "support/read_text.hpp"
#include "support/run_cli.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace impulse;
using impulse::test::CliResult;
using impulse::test::read_text;
using impulse::test::run_cli;
using impulse::test::TempDir;

namespace {

using impulse::test::ruler;

// The ruler's CSV worksheet with every cell's value set by `fill` (from the reference value at its path).
std::string ruler_sheet(const std::function<std::string(const formats::json&)>& fill) {
    const formats::json trace = formats::trace_json(test::opened("cases/ruler"));
    TempDir dir;
    const std::string sheet = dir.file("sheet.csv").string();
    REQUIRE(run_cli({"worksheet", ruler, "--out", sheet}).code == 0);
    // The value as a student's program would write it: quoted only for a comma, a quote or a line break (not
    // guarded against formulas, as our own CSV writer guards it).
    const auto raw = [](const std::string& value) {
        if (value.find_first_of(",\"\r\n") == std::string::npos) return value;
        std::string quoted = "\"";
        for (const char c : value) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
        return quoted + "\"";
    };
    std::string text;
    for (formats::CsvRow& row : formats::parse_csv(read_text(sheet))) {
        const std::string value =
            row.fields[0] == "cell" ? fill(*course::value_at(trace, course::parse_json_path(row.fields[1], ""))) : "";
        if (row.fields[0] == "cell") row.fields[4].clear();
        std::string line = formats::csv_row(row.fields);
        if (row.fields[0] == "cell") {
            // The value is the fifth field: after the fourth comma outside quotes.
            std::size_t at = 0, commas = 0;
            for (bool quoted = false; at < line.size() && commas < 4; ++at) {
                if (line[at] == '"') quoted = !quoted;
                if (line[at] == ',' && !quoted) ++commas;
            }
            line.insert(at, raw(value));
        }
        text += line;
    }
    return text;
}

std::string right_answer(const formats::json& value) {
    return course::scalar_text(value);
}

// The value of `column` in the rows of a CSV whose first field is `file`.
std::vector<std::string> column_of(const std::string& csv, const std::string& file, std::size_t column) {
    std::vector<std::string> values;
    for (const formats::CsvRow& row : formats::parse_csv(csv))
        if (row.fields[0].ends_with(file)) values.push_back(row.fields[column]);
    return values;
}

}  // namespace

TEST_CASE("a student's CSV cell holding a line break is graded, and shown escaped, in a class diff") {
    // Legal CSV: a class diff read past the end of the findings table's places (exit 70).
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    dir.write("class/ada.csv", ruler_sheet([](const formats::json&) { return "1.5\nsecond line\x1b[2J"; }));
    dir.write("class/ben.csv", ruler_sheet(right_answer));
    const CliResult r = run_cli({"diff", ruler, dir.file("class").string()});
    CHECK(r.code == 1);
    CHECK(r.err.empty());
    CHECK(r.out.find("1.5\\nsecond line\\x1b[2J") != std::string::npos);
    CHECK(r.out.find('\x1b') == std::string::npos);
}

TEST_CASE("one right cell copied 500 times scores what one right cell is worth") {
    // It scored 95.7 %: every copy counted as another right number.
    TempDir dir;
    const std::vector<formats::CsvRow> rows = formats::parse_csv(ruler_sheet(right_answer));
    std::string text = formats::csv_row(rows[0].fields);
    const auto cell =
        std::find_if(rows.begin(), rows.end(), [](const formats::CsvRow& r) { return r.fields[0] == "cell"; });
    REQUIRE(cell != rows.end());
    for (int i = 0; i < 500; ++i) text += formats::csv_row(cell->fields);
    const std::string sheet = dir.write("copier.csv", text).string();
    const CliResult r = run_cli({"diff", ruler, sheet, "--format", "json"});
    CHECK(r.code == 1);
    const formats::json report = formats::parse_json_text(r.out);
    CHECK(report["matched"] == 1);
    CHECK(report["score_percent"].get<double>() < 1.0);
    std::size_t duplicates = 0;
    for (const formats::json& f : report["findings"]) duplicates += f["kind"] == "duplicate";
    CHECK(duplicates == 499);
}

TEST_CASE("an empty sheet scores 0 and is not all match") {
    // It got "all match", exit code 0.
    TempDir dir;
    const std::string sheet = dir.write("empty.csv", std::string(course::worksheet_csv_header) + "\n").string();
    const CliResult r = run_cli({"diff", ruler, sheet});
    CHECK(r.code == 1);
    CHECK(r.out.find("the worksheet gives no cells: nothing to grade") != std::string::npos);
    CHECK(r.out.find("score 0.0 %") != std::string::npos);
    CHECK(r.out.find("all match") == std::string::npos);
}

TEST_CASE("cells of a step the sheet answers in part are graded blank, and cells it was not asked are wrong") {
    TempDir dir;
    const std::vector<formats::CsvRow> rows = formats::parse_csv(ruler_sheet(right_answer));
    std::string text = formats::csv_row(rows[0].fields);
    for (const formats::CsvRow& row : rows)
        if (row.fields[1] == "frames[0].contacts[0].desired_delta_velocity") text += formats::csv_row(row.fields);
    const std::string sheet = dir.write("one.csv", text).string();
    const formats::json report = formats::parse_json_text(run_cli({"diff", ruler, sheet, "--format", "json"}).out);
    CHECK(report["matched"] == 1);
    // Step 5's other numbers: separating_velocity, restitution_cutoff_applied, restitution_used,
    // velocity_from_acceleration.
    CHECK(report["blank"] == 4);
}

TEST_CASE("a formula in a student's answer reaches cells.csv as text a spreadsheet does not run") {
    // =cmd|' /C calc'!A0 went verbatim into cells.csv.
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    dir.write("class/ada.csv", ruler_sheet([](const formats::json&) { return "=cmd|' /C calc'!A0"; }));
    dir.write("class/ben.csv", ruler_sheet(right_answer));
    REQUIRE(run_cli({"diff", ruler, dir.file("class").string(), "--out", dir.file("report").string()}).code == 1);
    const std::string cells = read_text(dir.file("report/cells.csv"));
    CHECK(cells.find("\"'=cmd|' /C calc'!A0\"") != std::string::npos);
    CHECK(cells.find(",=cmd") == std::string::npos);
}

TEST_CASE("HTML and Markdown in a student's answer and file name are text on the feedback page") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    const std::string name = "<img src=x onerror=alert(1)>.csv";
    dir.write("class/" + name, ruler_sheet([](const formats::json&) { return "<script>alert(1)</script> **bold**"; }));
    dir.write("class/ben.csv", ruler_sheet(right_answer));
    REQUIRE(run_cli({"diff", ruler, dir.file("class").string(), "--out", dir.file("report").string()}).code == 1);
    std::string page;
    for (const auto& entry : std::filesystem::directory_iterator(dir.file("report/feedback")))
        if (entry.path().filename() != "ben.md") page = read_text(entry.path());
    REQUIRE_FALSE(page.empty());
    CHECK(page.find("<script>") == std::string::npos);
    CHECK(page.find("<img") == std::string::npos);
    CHECK(page.find("&lt;script&gt;alert\\(1\\)&lt;/script&gt; \\*\\*bold\\*\\*") != std::string::npos);
    CHECK(page.find("# Feedback on &lt;img src=x onerror=alert\\(1\\)&gt;.csv") != std::string::npos);
}

TEST_CASE("a feedback page names the reference by its file name, not by where the teacher keeps it") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    dir.write("class/ada.csv", ruler_sheet(right_answer));
    dir.write("class/ben.csv", ruler_sheet(right_answer));
    REQUIRE(run_cli({"diff", ruler, dir.file("class").string(), "--out", dir.file("report").string()}).code == 0);
    const std::string page = read_text(dir.file("report/feedback/ada.md"));
    CHECK(page.find("(ruler.json)") != std::string::npos);
    CHECK(page.find(IMPULSE_SOURCE_DIR) == std::string::npos);
}

TEST_CASE("the wrong numbers after the first divergence are said to follow from it only when there are some") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    // ada: one wrong number and nothing wrong after it; ben: every number wrong.
    bool first = true;
    dir.write("class/ada.csv", ruler_sheet([&first](const formats::json& v) {
                  if (first && v.is_number()) return first = false, std::string("12345");
                  return right_answer(v);
              }));
    dir.write("class/ben.csv", ruler_sheet([](const formats::json& v) { return v.is_number() ? "12345" : "x"; }));
    REQUIRE(run_cli({"diff", ruler, dir.file("class").string(), "--out", dir.file("report").string()}).code == 1);
    const std::string follow = "The wrong numbers after it often follow from this one";
    CHECK(read_text(dir.file("report/feedback/ada.md")).find(follow) == std::string::npos);
    CHECK(read_text(dir.file("report/feedback/ben.md")).find(follow) != std::string::npos);
}

TEST_CASE("cells.csv gives an expected number as the shortest decimal that grades the same, not float noise") {
    // 0.08560254040000001 was written as is.
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    dir.write("class/ada.csv", ruler_sheet([](const formats::json&) { return "1"; }));
    dir.write("class/ben.csv", ruler_sheet(right_answer));
    REQUIRE(run_cli({"diff", ruler, dir.file("class").string(), "--out", dir.file("report").string()}).code == 1);
    const std::vector<std::string> expected = column_of(read_text(dir.file("report/cells.csv")), "class/ada.csv", 4);
    REQUIRE_FALSE(expected.empty());
    // Within 1/1000 of the default tolerance (1e-9 relative): at most 13 significant digits, where the shortest
    // text that reads back to the last bit takes up to 17.
    for (const std::string& e : expected) {
        std::size_t digits = 0;
        bool leading = true;
        for (const char c : e.substr(0, e.find('e'))) {
            if (c >= '1' && c <= '9') leading = false;
            if (c >= '0' && c <= '9' && !leading) ++digits;
        }
        CHECK_MESSAGE(digits <= 13, e);
    }
    CHECK(std::find(expected.begin(), expected.end(), "0.0856025404") != expected.end());
}

TEST_CASE("worksheet and diff take a lesson by its number") {
    // `worksheet 7` was refused: lessons only by path.
    TempDir dir;
    const std::string sheet = dir.file("seven.csv").string();
    const CliResult made = run_cli({"worksheet", "7", "--out", sheet});
    CHECK(made.code == 0);
    // The counts are what the sheet shows: a row per number to fill in, each input row once (it said "109 inputs
    // given" over 93 input rows).
    const std::vector<formats::CsvRow> rows = formats::parse_csv(read_text(sheet));
    const auto count = [&rows](const char* kind) {
        return std::count_if(rows.begin(), rows.end(),
                             [kind](const formats::CsvRow& r) { return r.fields[0] == kind; });
    };
    CHECK(made.out == "worksheet written to " + sheet + ": 5 steps, " + std::to_string(count("cell")) +
                          " rows to fill in, " + std::to_string(count("input")) + " input rows\n");
    std::filesystem::create_directory(dir.file("class"));
    std::filesystem::copy_file(sheet, dir.file("class/blank.csv"));
    const CliResult graded = run_cli({"diff", "7", dir.file("class").string()});
    CHECK(graded.code == 1);
    CHECK(graded.out.find("(lesson 7 · ") != std::string::npos);
    CHECK(
        run_cli({"worksheet", "77", "--out", sheet}).err.starts_with("impulse-lab: worksheet: there is no lesson 77"));
}

TEST_CASE("a filled CSV sheet is a reference: an answer key") {
    // diff SHEET.csv FOLDER failed with a raw JSON parse error.
    TempDir dir;
    const std::string key = dir.write("key.csv", ruler_sheet(right_answer)).string();
    std::filesystem::create_directory(dir.file("class"));
    dir.write("class/ada.csv", ruler_sheet(right_answer));
    dir.write("class/ben.csv", ruler_sheet([](const formats::json&) { return "1"; }));
    const CliResult r = run_cli({"diff", key, dir.file("class").string(), "--format", "csv"});
    CHECK(r.code == 1);
    CHECK(r.out.find("class/ada.csv,worksheet,89,89,0,0,100.0,") != std::string::npos);
    CHECK(r.out.find("class/ben.csv,worksheet,89,") != std::string::npos);
    // The feedback speaks of the key's values, not the engine's: nothing was run.
    REQUIRE(run_cli({"diff", key, dir.file("class").string(), "--out", dir.file("report").string()}).code == 1);
    const std::string ben = read_text(dir.file("report/feedback/ben.md"));
    CHECK(ben.find("Every number is compared with the key's value") != std::string::npos);
    CHECK(ben.find("the key has ") != std::string::npos);
    CHECK(ben.find("the engine") == std::string::npos);
    // A blank key cannot be graded against.
    TempDir blank;
    const std::string sheet = blank.file("blank.csv").string();
    REQUIRE(run_cli({"worksheet", ruler, "--out", sheet}).code == 0);
    const CliResult refused = run_cli({"diff", sheet, dir.file("class").string()});
    CHECK(refused.code == 2);
    CHECK(refused.err.find(": is blank: an answer key given as the reference must fill every cell") !=
          std::string::npos);
}

TEST_CASE("a worksheet of a trace with a changed iteration number is refused, not a segfault") {
    TempDir dir;
    formats::json trace = formats::trace_json(test::opened("cases/ruler"));
    trace["frames"][0]["phases"][0]["iterations"][0]["iteration"] = 2147483647;
    const std::string file = dir.write("t.json", formats::format_json(trace)).string();
    const CliResult r = run_cli({"worksheet", file, "--out", dir.file("w.csv").string()});
    CHECK(r.code == 2);
    CHECK(r.err == "impulse-lab: " + file +
                       ": frames[0].phases[0].iterations[0].iteration: must be 0 (iterations are numbered in order "
                       "from 0), got 2147483647\n");
}

TEST_CASE("two corrupt progress files within one second keep a backup each") {
    // The second rename replaced the first backup: one student's progress was lost.
    TempDir dir;
    const std::filesystem::path file = dir.file("progress.json");
    dir.write("progress.json", "{ broken one");
    const course::LoadedProgress first = course::load_progress(file);
    dir.write("progress.json", "{ broken two");
    const course::LoadedProgress second = course::load_progress(file);
    CHECK(first.note.find("kept as progress.json.corrupt-") != std::string::npos);
    CHECK(second.note.find("kept as progress.json.corrupt-") != std::string::npos);
    std::vector<std::string> kept;
    for (const auto& entry : std::filesystem::directory_iterator(dir.file(".")))
        kept.push_back(read_text(entry.path()));
    std::sort(kept.begin(), kept.end());
    CHECK(kept == std::vector<std::string>{"{ broken one", "{ broken two"});
}

TEST_CASE("a tries count at the integer limit stays there instead of wrapping negative") {
    // 2147483647 + 1 wrapped to a negative count, and the next start threw all progress aside.
    TempDir dir;
    const std::filesystem::path file = dir.file("progress.json");
    const course::PreparedLesson lesson =
        course::prepare_lesson(course::read_lesson(course::lesson_files(IMPULSE_SOURCE_DIR "/lessons").front()));
    course::Progress progress;
    course::LessonRun run(lesson, &progress, file);
    int question = 0;
    while (question < run.step_count() && !lesson.lesson.steps[static_cast<std::size_t>(question)].question) ++question;
    REQUIRE(question < run.step_count());
    run.go_to(question);
    progress.lessons[lesson.lesson.name].answers[run.current().id].tries = INT_MAX;
    run.answer("123456789");  // wrong
    CHECK(progress.lessons[lesson.lesson.name].answers[run.current().id].tries == INT_MAX);
    const course::LoadedProgress loaded = course::load_progress(file);
    CHECK(loaded.note.empty());
    CHECK(loaded.progress.lessons.at(lesson.lesson.name).answers.at(run.current().id).tries == INT_MAX);
}

TEST_CASE("a lesson file that starts with a UTF-8 byte-order mark is read") {
    // It was refused: "line 1: a lesson starts with its header in a ```json block".
    const std::filesystem::path first = course::lesson_files(IMPULSE_SOURCE_DIR "/lessons").front();
    const std::string text = "\xEF\xBB\xBF" + read_text(first);
    const course::Lesson with_mark = course::read_lesson_text(text, first);
    const course::Lesson without = course::read_lesson_text(read_text(first), first);
    CHECK(with_mark.title == without.title);
    CHECK(with_mark.steps.size() == without.steps.size());
}
