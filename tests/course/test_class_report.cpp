// Grading a class: `diff REFERENCE FOLDER --out DIR` writes summary.csv, cells.csv and a feedback page per
// student, all or nothing; the reference may be a lesson, a worksheet, a case or a trace; every file in the
// folder gets its row; the score is right / cells; the reports speak the worksheet's words.

#include "course/class_report.hpp"
#include "course/diff.hpp"
#include "course/json_path.hpp"
#include "course/lesson.hpp"
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
#include <fstream>
#include <sstream>

using namespace impulse;
using namespace impulse::course;
using impulse::test::CliResult;
using impulse::test::read_text;
using impulse::test::run_cli;
using impulse::test::TempDir;

namespace {

using impulse::test::ruler;
const std::string lesson_7 = IMPULSE_SOURCE_DIR "/lessons/07-calculating-and-applying-the-impulse.md";

std::vector<formats::CsvRow> read_csv(const std::filesystem::path& file) {
    return formats::parse_csv(read_text(file));
}

// A CSV worksheet of `source` (a lesson or case) as `worksheet` writes it, each cell row's value set by `fill`
// from the reference's value (return nullopt to leave the row out of the file).
std::string filled_csv(
    const std::string& source, const formats::json& reference,
    const std::function<std::optional<std::string>(const std::string&, const formats::json&)>& fill) {
    TempDir dir;
    const std::string sheet = dir.file("sheet.csv").string();
    REQUIRE(run_cli({"worksheet", source, "--out", sheet}).code == 0);
    std::string text;
    for (formats::CsvRow& row : read_csv(sheet)) {
        if (row.fields[0] == "cell") {
            const std::optional<std::string> value =
                fill(row.fields[1], *value_at(reference, parse_json_path(row.fields[1], "")));
            if (!value) continue;
            row.fields[4] = *value;
        }
        text += formats::csv_row(row.fields);
    }
    return text;
}

std::optional<std::string> exact(const std::string&, const formats::json& value) {
    return scalar_text(value);
}

formats::json lesson_reference() {
    return formats::trace_json(course::prepare_lesson(course::read_lesson(lesson_7)).session.trace());
}

std::size_t lines_with(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

}  // namespace

TEST_CASE("a lesson is a reference as worksheet runs it: its sheet filled in matches, and a row left out is blank") {
    TempDir dir;
    const formats::json reference = lesson_reference();
    const std::string all = dir.write("all.csv", filled_csv(lesson_7, reference, exact)).string();
    const CliResult r = run_cli({"diff", lesson_7, all});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("67 matched, 0 mismatched, 0 blank: all match; score 100.0 %") != std::string::npos);

    // A student who deletes the rows they could not do is not graded on fewer cells: the lesson's sheet asks for
    // them, so they count as blank.
    const std::string part = dir.write("part.csv", filled_csv(lesson_7, reference,
                                                              [](const std::string& path, const formats::json& value) {
                                                                  return path.find(".updates[") == std::string::npos
                                                                             ? std::optional(scalar_text(value))
                                                                             : std::nullopt;
                                                              }))
                                 .string();
    const CliResult p = run_cli({"diff", lesson_7, part, "--format", "json"});
    CHECK(p.code == 1);
    const formats::json report = formats::parse_json_text(p.out);
    CHECK(report["blank"] == 14);  // two updates: delta (3), after (3), desired_delta_velocity_after (1)
    CHECK(report["matched"] == 53);
    CHECK(report["score_percent"].get<double>() == doctest::Approx(100.0 * 53 / 67));

    // A lesson runs with its own settings.
    const CliResult flag = run_cli({"diff", lesson_7, all, "--set", "restitution_cutoff=0"});
    CHECK(flag.code == 2);
    CHECK(flag.err ==
          "impulse-lab: --set: a lesson runs with its own settings; give its scene file to run it "
          "differently\n");
}

TEST_CASE("a class report is written as a set: summary.csv, cells.csv and a feedback page per student") {
    TempDir dir;
    const formats::json reference = lesson_reference();
    std::filesystem::create_directories(dir.file("class/drafts"));
    // Ada: every number right, written to six significant figures as a student would.
    dir.write("class/ada.csv", filled_csv(lesson_7, reference, [](const std::string&, const formats::json& v) {
                  if (!v.is_number_float()) return std::optional(scalar_text(v));
                  char text[32];
                  std::snprintf(text, sizeof text, "%.6g", v.get<double>());
                  return std::optional<std::string>(text);
              }));
    // Ben: d without its angular part, so g = Δv / d and everything after it are off.
    dir.write("class/ben.csv", filled_csv(lesson_7, reference, [&](const std::string& path, const formats::json& v) {
                  if (path == "frames[0].contacts[0].delta_velocity_per_unit_impulse")
                      return std::optional<std::string>("1.33333");
                  return std::optional(scalar_text(v));
              }));
    // Cy: the last step left blank.
    dir.write("class/cy.csv", filled_csv(lesson_7, reference, [](const std::string& path, const formats::json& v) {
                  return std::optional<std::string>(path.find(".updates[") == std::string::npos ? scalar_text(v) : "");
              }));
    dir.write("class/dee.xlsx", "PK\x03\x04 a spreadsheet in its own format");
    dir.write("class/.DS_Store", "hidden: not a submission");
    dir.write("class/drafts/old.csv", "in a sub-folder: not a submission");

    const std::string out = dir.file("report").string();
    const CliResult r = run_cli({"diff", lesson_7, dir.file("class").string(), "--rtol", "1e-4", "--out", out});
    CHECK(r.code == 1);
    const std::string dee = dir.file("class/dee.xlsx").string();
    CHECK(r.err == "impulse-lab: " + dee +
                       ": not a worksheet or trace: only .json and .csv files are read (save a spreadsheet as CSV, "
                       "comma-separated)\n");
    CHECK(r.out.find("class report written to " + out + ": summary.csv, cells.csv and 4 feedback pages in feedback/") !=
          std::string::npos);

    const std::vector<formats::CsvRow> summary = read_csv(dir.file("report/summary.csv"));
    REQUIRE(summary.size() == 5);
    CHECK(summary[1].fields == std::vector<std::string>{dir.file("class/ada.csv").string(), "worksheet", "67", "67",
                                                        "0", "0", "100.0", "", "", ""});
    // Ben's d is the first wrong number; the impulse and everything computed from it follow.
    CHECK(summary[2].fields[6] != "100.0");
    CHECK(summary[2].fields[7] ==
          "frame 0 · preparation · contact 0 · delta_velocity_per_unit_impulse: delta_velocity_per_unit_impulse");
    CHECK(summary[2].fields[8] == "frames[0].contacts[0].delta_velocity_per_unit_impulse");
    // 14 blank of 67: 53 / 67 = 79.1 %.
    CHECK(summary[3].fields == std::vector<std::string>{dir.file("class/cy.csv").string(), "worksheet", "67", "53", "0",
                                                        "14", "79.1", "", "", ""});
    CHECK(summary[4].fields[0] == dee);
    CHECK(summary[4].fields[9].starts_with("not a worksheet or trace"));

    // cells.csv: a row for every number of every sheet read, one for the file that was not.
    const std::vector<formats::CsvRow> cells = read_csv(dir.file("report/cells.csv"));
    CHECK(cells[0].fields == std::vector<std::string>{"file", "place", "quantity", "unit", "expected", "found",
                                                      "relative_error", "verdict", "first_divergence", "path"});
    CHECK(cells.size() == 1 + 3 * 67 + 1);
    const auto ben_d = std::find_if(cells.begin(), cells.end(), [&](const formats::CsvRow& row) {
        return row.fields[0] == dir.file("class/ben.csv").string() &&
               row.fields[9] == "frames[0].contacts[0].delta_velocity_per_unit_impulse";
    });
    REQUIRE(ben_d != cells.end());
    CHECK(ben_d->fields[1] == "frame 0 · preparation · contact 0 · delta_velocity_per_unit_impulse");
    CHECK(ben_d->fields[2] == "delta_velocity_per_unit_impulse");
    CHECK(ben_d->fields[3] == "m/s per N·s");
    CHECK(ben_d->fields[5] == "1.33333");
    CHECK(ben_d->fields[7] == "wrong");
    CHECK(ben_d->fields[8] == "true");

    // The feedback pages, one per student, in the worksheet's words.
    for (const char* page : {"ada.md", "ben.md", "cy.md", "dee.md"})
        CHECK_MESSAGE(std::filesystem::exists(dir.file(std::string("report/feedback/") + page)), page);
    const std::string ben = read_text(dir.file("report/feedback/ben.md"));
    CHECK(ben.starts_with("# Feedback on ben.csv\n"));
    CHECK(ben.find("## ▶ Where it first went wrong\n\n**frame 0 · preparation · contact 0 · "
                   "delta_velocity_per_unit_impulse**, "
                   "`delta_velocity_per_unit_impulse` (m/s per N·s): the engine has 2.22559, you have 1.33333") !=
          std::string::npos);
    CHECK(lines_with(ben, "| ▶ |") == 1);
    CHECK(ben.find("frames[0]") == std::string::npos);  // no raw paths for a student
    const std::string cy = read_text(dir.file("report/feedback/cy.md"));
    CHECK(cy.find("**Score: 53 of 67 numbers right (79.1 %)** · 0 wrong · 14 blank") != std::string::npos);
    CHECK(read_text(dir.file("report/feedback/dee.md")).find("This file could not be graded") != std::string::npos);
    CHECK(read_text(dir.file("report/feedback/ada.md")).find("Every number is right.") != std::string::npos);
}

TEST_CASE("the class summary in the terminal shows each file's wrong cells in the worksheet's words") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    const formats::json reference = formats::trace_json(test::opened("cases/ruler"));
    dir.write("class/ada.csv", filled_csv(ruler, reference, exact));
    dir.write("class/ben.csv", filled_csv(ruler, reference, [](const std::string& path, const formats::json& v) {
                  return std::optional<std::string>(
                      path == "frames[0].phases[1].iterations[0].impulse_world[1]" ? "0.15" : scalar_text(v));
              }));
    const CliResult r = run_cli({"diff", ruler, dir.file("class").string()});
    CHECK(r.code == 1);
    CHECK(r.out.find(dir.file("class/ben.csv").string() + ": 1 finding\n"
                                                          "   kind   quantity          expected       found  unit  "
                                                          "rel. error  formula      eq.\n"
                                                          "frame 0 · velocity phase · iteration 0 · contact 0 · "
                                                          "impulse\n"
                                                          "▶  value  impulse_world[1]  0.14073673208  0.15   N·s   "
                                                          "0.0658      C · impulse\n") != std::string::npos);
    CHECK(r.out.find("2 files: 1 all match, 1 with mismatches or blanks, 0 unreadable") != std::string::npos);
}

TEST_CASE("a trace handed in with worksheets gets its row, its score over every value it compared") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    formats::json trace = formats::trace_json(test::opened("cases/ruler"));
    trace["frames"][0]["phases"][1]["iterations"][0]["impulse_world"][1] = 0.15;
    dir.write("class/engine.json", formats::format_json(trace));
    dir.write("class/sheet.csv", filled_csv(ruler, formats::trace_json(test::opened("cases/ruler")), exact));
    const std::string out = dir.file("report").string();
    CHECK(run_cli({"diff", ruler, dir.file("class").string(), "--out", out}).code == 1);
    const std::vector<formats::CsvRow> summary = read_csv(dir.file("report/summary.csv"));
    REQUIRE(summary.size() == 3);
    // 299 values match and one differs: 99.7 %.
    CHECK(summary[1].fields == std::vector<std::string>{dir.file("class/engine.json").string(), "trace", "300", "299",
                                                        "1", "0", "99.7",
                                                        "frame 0 · velocity phase · iteration 0 · contact 0 · impulse: "
                                                        "impulse_world[1]",
                                                        "frames[0].phases[1].iterations[0].impulse_world[1]", ""});
    // A trace's rows in cells.csv are its findings only.
    const std::vector<formats::CsvRow> cells = read_csv(dir.file("report/cells.csv"));
    CHECK(std::count_if(cells.begin(), cells.end(), [&](const formats::CsvRow& row) {
              return row.fields[0] == dir.file("class/engine.json").string();
          }) == 1);
}

TEST_CASE(
    "--out of a class is a folder: a file name, an existing file or a missing parent is refused, nothing written") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    dir.write("class/a.csv", "kind,path,value\n");
    dir.write("taken", "a file already");
    const std::string folder = dir.file("class").string();
    const std::vector<std::pair<std::string, std::string>> table{
        {dir.file("grades.csv").string(),
         "impulse-lab: --out: with several files --out is a folder for summary.csv, "
         "cells.csv and the feedback pages, got '" +
             dir.file("grades.csv").string() + "', a file name (--format csv prints the summary alone)\n"},
        {dir.file("taken").string(),
         "impulse-lab: --out: with several files --out is a folder for summary.csv, "
         "cells.csv and the feedback pages, and '" +
             dir.file("taken").string() + "' is a file\n"},
        {dir.file("no/report").string(),
         "impulse-lab: --out: cannot create '" + dir.file("no/report").string() + "': No such file or directory\n"},
    };
    for (const auto& [out, message] : table) {
        const auto& expected = message;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
        CAPTURE(expected);
        const CliResult r = run_cli({"diff", ruler, folder, "--out", out});
        CHECK(r.code == 2);
        CHECK(r.err == message);
        CHECK(r.out.empty());
    }
    CHECK(dir.entries() == 2);
}

TEST_CASE("a class report that cannot be written whole leaves the one before it as it was") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    const formats::json reference = formats::trace_json(test::opened("cases/ruler"));
    dir.write("class/ada.csv", filled_csv(ruler, reference, exact));
    dir.write("class/ben.csv", filled_csv(ruler, reference, exact));
    const std::string out = dir.file("report").string();
    REQUIRE(run_cli({"diff", ruler, dir.file("class").string(), "--out", out}).code == 0);
    const std::string summary = read_text(dir.file("report/summary.csv"));

    // Ben hands in again, wrong this time; but his page cannot be replaced (a folder stands in its place).
    dir.write("class/ben.csv", filled_csv(ruler, reference, [](const std::string& path, const formats::json& v) {
                  return std::optional<std::string>(
                      path == "frames[0].phases[1].iterations[0].impulse_world[1]" ? "0.15" : scalar_text(v));
              }));
    std::filesystem::remove(dir.file("report/feedback/ben.md"));
    std::filesystem::create_directory(dir.file("report/feedback/ben.md"));
    const CliResult r = run_cli({"diff", ruler, dir.file("class").string(), "--out", out});
    CHECK(r.code == 2);
    CHECK(r.err ==
          "impulse-lab: --out: cannot write '" + dir.file("report/feedback/ben.md").string() + "': Is a directory\n");
    CHECK(read_text(dir.file("report/summary.csv")) == summary);
    // And no temporary is left behind.
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir.file("report")))
        CHECK_MESSAGE(entry.path().filename().string().find(".tmp-") == std::string::npos, entry.path());
}

TEST_CASE("the score is right over cells, a blank counts against it, and a sheet without cells scores 0") {
    DiffReport sheet;
    sheet.other_kind = "worksheet";
    for (const Verdict v : {Verdict::right, Verdict::right, Verdict::right, Verdict::wrong, Verdict::blank})
        sheet.graded.push_back({"x", 1.0, nullptr, std::nullopt, v, "", "", ""});
    const Score s = score_of(sheet);
    CHECK(s.cells == 5);
    CHECK(s.right == 3);
    CHECK(s.wrong == 1);
    CHECK(s.blank == 1);
    CHECK(*s.percent == doctest::Approx(60.0));  // 3 / 5

    DiffReport trace;
    trace.other_kind = "trace";
    trace.matched = 299;
    trace.mismatched = 1;
    CHECK(*score_of(trace).percent == doctest::Approx(99.666666666));
    DiffReport empty;
    empty.other_kind = "worksheet";
    CHECK(*score_of(empty).percent == 0.0);
}

TEST_CASE("feedback pages are named after the files, and files of the same name are told apart") {
    CHECK(feedback_names({"class/ada.csv", "class/ben.json"}) == std::vector<std::string>{"ada.md", "ben.md"});
    CHECK(feedback_names({"class/ada.csv", "class/ada.json"}) == std::vector<std::string>{"ada.csv.md", "ada.json.md"});
    CHECK(feedback_names({"a/ada.csv", "b/ada.csv"}) == std::vector<std::string>{"ada.csv.md", "ada.csv-2.md"});
}

TEST_CASE("an expected number is shown to the digits the tolerance looks at") {
    CHECK(shown_value(0.45291949485020394, Tolerance{1e-4, 1e-12}) == "0.452919");  // 6 at least
    CHECK(shown_value(0.1407367320754168, Tolerance{}) == "0.14073673208");         // rtol 1e-9: 11 digits
    CHECK(shown_value(0.25, Tolerance{1e-4, 1e-12}) == "0.25");                     // no trailing zeros
    CHECK(shown_value(-0.0, Tolerance{}) == "0");
    CHECK(shown_value(true, Tolerance{}) == "true");
}
