// `impulse-lab diff`: traces compared value by value with the reference, worksheets filled by a program (as a
// student's engine would) graded cell by cell, a folder of submissions summarised one row per file, and
// bad input refused in one line.

#include "course/diff.hpp"
#include "course/json_path.hpp"
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
#include <functional>
#include <sstream>

using namespace impulse;
using namespace impulse::course;
using impulse::test::CliResult;
using impulse::test::read_text;
using impulse::test::run_cli;
using impulse::test::TempDir;

namespace {

using impulse::test::cases;
using impulse::test::ruler;

formats::json read_json(const std::filesystem::path& file) {
    return formats::parse_json_text(read_text(file));
}

std::string write_json(const TempDir& dir, const std::string& name, const formats::json& document) {
    return dir.write(name, formats::format_json(document)).string();
}

// The reference trace of a case, as `resolve --trace` writes it.
formats::json reference_trace(const std::string& file) {
    return formats::trace_json(test::opened(file));
}

// A trace file edited by `edit`.
std::string edited_trace(const TempDir& dir, const std::string& name, const std::function<void(formats::json&)>& edit) {
    formats::json trace = reference_trace("cases/ruler");
    edit(trace);
    return write_json(dir, name, trace);
}

// A JSON report of diff REFERENCE OTHER.
formats::json diff_json(const std::string& reference, const std::string& other, int expected_code) {
    const CliResult r = run_cli({"diff", reference, other, "--format", "json"});
    CHECK(r.code == expected_code);
    CHECK(r.err.empty());
    return formats::parse_json_text(r.out);
}

// A worksheet of the case with every cell filled from the reference trace, as a student's engine would fill it.
formats::json filled_worksheet(const std::string& file) {
    const formats::json trace = reference_trace(file);
    TempDir dir;
    const std::string sheet = dir.file("sheet.json").string();
    REQUIRE(run_cli({"worksheet", IMPULSE_SOURCE_DIR "/scenes/" + file + ".json", "--out", sheet}).code == 0);
    formats::json document = read_json(sheet);
    for (formats::json& step : document["steps"])
        for (formats::json& cell : step["cells"])
            cell["value"] = *value_at(trace, parse_json_path(cell["path"].get<std::string>(), ""));
    return document;
}

// The same as CSV: each cell row's value written from the reference.
std::string filled_csv(const std::string& file, const std::vector<std::string>& steps) {
    const formats::json trace = reference_trace(file);
    TempDir dir;
    const std::string sheet = dir.file("sheet.csv").string();
    std::vector<std::string> args{"worksheet", IMPULSE_SOURCE_DIR "/scenes/" + file + ".json", "--out", sheet};
    for (const std::string& s : steps) args.insert(args.end(), {"--steps", s});
    REQUIRE(run_cli(args).code == 0);
    std::string text;
    for (formats::CsvRow& row : formats::parse_csv(read_text(sheet))) {
        if (row.fields[0] == "cell") row.fields[4] = scalar_text(*value_at(trace, parse_json_path(row.fields[1], "")));
        text += formats::csv_row(row.fields);
    }
    return text;
}

// The cell of a filled worksheet at `path` (a whole cell), for editing.
formats::json& cell_at(formats::json& sheet, const std::string& path) {
    for (formats::json& step : sheet["steps"])
        for (formats::json& cell : step["cells"])
            if (cell["path"] == path) return cell["value"];
    FAIL("no cell " << path);
    return sheet;
}

}  // namespace

TEST_CASE("diff of a trace with itself matches everything and exits 0") {
    TempDir dir;
    const std::string trace = edited_trace(dir, "same.json", [](formats::json&) {});
    const CliResult r = run_cli({"diff", ruler, trace});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("0 mismatched, 0 blank: all match") != std::string::npos);
    const formats::json report = diff_json(trace, trace, 0);
    CHECK(report["mismatched"] == 0);
    CHECK(report["matched"].get<int>() > 200);
    CHECK(report["findings"].empty());
    CHECK(report["first_divergence"].is_null());
}

TEST_CASE("one perturbed value is reported at exactly its path as the first divergence") {
    TempDir dir;
    // g_y = 0.1407367320754168 N·s in the ruler's velocity iteration; 0.15 is off by 6.58 %.
    const std::string other = edited_trace(dir, "perturbed.json", [](formats::json& t) {
        t["frames"][0]["phases"][1]["iterations"][0]["impulse_world"][1] = 0.15;
    });
    const formats::json report = diff_json(ruler, other, 1);
    CHECK(report["mismatched"] == 1);
    REQUIRE(report["findings"].size() == 1);
    const formats::json& f = report["findings"][0];
    CHECK(f["kind"] == "value");
    CHECK(f["path"] == "frames[0].phases[1].iterations[0].impulse_world[1]");
    CHECK(f["expected"].get<double>() == 0.1407367320754168);
    CHECK(f["found"].get<double>() == 0.15);
    CHECK(f["relative_error"].get<double>() == doctest::Approx((0.15 - 0.1407367320754168) / 0.1407367320754168));
    // In the worksheet's own words: the step that computes it, and its name there.
    CHECK(f["place"] == "frame 0 · velocity phase · iteration 0 · contact 0 · impulse");
    CHECK(f["quantity"] == "impulse_world[1]");
    CHECK(f["unit"] == "N·s");
    CHECK(f["formula"] == "C · impulse");
    CHECK(f["first_divergence"] == true);
    CHECK(report["first_divergence"] == f["path"]);

    // The text names the place once, above its rows, and shows the expected value to the digits the tolerance
    // looks at (rtol 1e-9: 11 significant figures).
    const CliResult text = run_cli({"diff", ruler, other});
    CHECK(text.code == 1);
    CHECK(text.out.find("frame 0 · velocity phase · iteration 0 · contact 0 · impulse\n"
                        "▶  value  impulse_world[1]  0.14073673208  0.15   N·s   0.0658      C · impulse\n") !=
          std::string::npos);
    CHECK(text.out.find("▶ first divergence: frame 0 · velocity phase · iteration 0 · contact 0 · impulse: "
                        "impulse_world[1] (frames[0].phases[1].iterations[0].impulse_world[1])") != std::string::npos);
    CHECK(text.out.find("299 matched, 1 mismatched, 0 blank; score 99.7 %") != std::string::npos);
}

TEST_CASE("a difference within the tolerance matches, and the tolerance is a flag") {
    TempDir dir;
    const std::string other = edited_trace(dir, "close.json", [](formats::json& t) {
        t["frames"][0]["contacts"][0]["desired_delta_velocity"] = 4.5 * (1 + 1e-11);
    });
    CHECK(diff_json(ruler, other, 0)["mismatched"] == 0);
    CHECK(run_cli({"diff", ruler, other, "--rtol", "0", "--atol", "0"}).code == 1);
    // An expected 0 is matched by rounding noise below atol, and its relative error is the absolute one.
    const std::string noisy = edited_trace(dir, "noisy.json", [](formats::json& t) {
        t["frames"][0]["contacts"][0]["contact_velocity"][1] = 1e-13;
        t["frames"][0]["contacts"][0]["contact_velocity"][2] = 1e-6;
    });
    const formats::json report = diff_json(ruler, noisy, 1);
    REQUIRE(report["findings"].size() == 1);
    CHECK(report["findings"][0]["path"] == "frames[0].contacts[0].contact_velocity[2]");
    CHECK(report["findings"][0]["relative_error"].get<double>() == 1e-6);
}

TEST_CASE("a missing iteration and an extra contact are reported as such, once each") {
    TempDir dir;
    const std::string other = edited_trace(dir, "reshaped.json", [](formats::json& t) {
        formats::json& frame = t["frames"][0];
        frame["phases"][1]["iterations"] = formats::json::array();
        frame["phases"][1]["iterations_used"] = 0;
        formats::json extra = frame["contacts"][0];
        extra["contact"] = 1;
        frame["contacts"].push_back(extra);
        frame["contact_count"] = 2;
    });
    const formats::json report = diff_json(ruler, other, 1);
    std::vector<std::pair<std::string, std::string>> found;
    for (const formats::json& f : report["findings"]) found.emplace_back(f["kind"], f["path"]);
    CHECK(found == std::vector<std::pair<std::string, std::string>>{
                       {"value", "frames[0].contact_count"},
                       {"extra", "frames[0].contacts[1]"},
                       {"value", "frames[0].phases[1].iterations_used"},
                       {"missing", "frames[0].phases[1].iterations[0]"},
                   });
    CHECK(report["findings"][3]["expected"]["iteration"] == 0);
    CHECK(report["findings"][1]["found"]["contact"] == 1);
}

TEST_CASE("a changed setting is reported as a setting, before anything it changed") {
    TempDir dir;
    const std::string chapter = dir.file("chapter.json").string();
    REQUIRE(run_cli({"resolve", ruler, "--set", "restitution_cutoff=0.3", "--trace", chapter}).code == 0);
    const formats::json report = diff_json(ruler, chapter, 1);
    REQUIRE(report["findings"].size() >= 1);
    const formats::json& first = report["findings"][0];
    CHECK(first["kind"] == "setting");
    CHECK(first["path"] == "settings.restitution_cutoff");
    CHECK(first["expected"] == 0.25);
    CHECK(first["found"] == 0.3);
    CHECK(first["first_divergence"] == true);
    CHECK(report["first_divergence"] == "settings.restitution_cutoff");
}

TEST_CASE("a malformed file or a bad flag gets one line, exit code 2 and no report") {
    TempDir dir;
    const std::string good = edited_trace(dir, "good.json", [](formats::json&) {});
    const std::string broken = dir.write("broken.json", "{\"format\": \"impulse-lab-trace\",").string();
    const std::string wrong = edited_trace(dir, "wrong.json", [](formats::json& t) {
        t["frames"][0]["phases"][1]["iterations"][0]["impulse_world"] = "up";
    });
    const std::string sheet = dir.write("sheet.json", R"({"format": "impulse-lab-worksheet", "version": 1,
        "steps": [{"cells": [{"path": "frames[0].basis[", "value": 1}]}]})")
                                  .string();
    const std::string csv =
        dir.write("sheet.csv", "kind,path,value\ncell,frames[0].contacts[0].basis[0][0],1\nanswer,x,2\n").string();
    const std::string report = dir.file("report.txt").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> table{
        {{"diff", ruler, broken}, "impulse-lab: " + broken + ": invalid JSON at line 1, column 32"},
        {{"diff", ruler, wrong},
         "impulse-lab: " + wrong + ": frames[0].phases[1].iterations[0].impulse_world: must be an array, got \"up\""},
        {{"diff", ruler, sheet},
         "impulse-lab: " + sheet + ": steps[0].cells[0].path: \"frames[0].basis[\" is not a path such as"},
        {{"diff", ruler, csv}, "impulse-lab: " + csv + ": line 3: kind must be \"input\" or \"cell\", got \"answer\""},
        {{"diff", ruler, ruler},
         "impulse-lab: " + ruler + ": format: expected a trace (\"impulse-lab-trace\") or a worksheet"},
        {{"diff", broken, good}, "impulse-lab: " + broken + ": invalid JSON at line 1, column 32"},
        {{"diff", dir.file("none.json").string(), good},
         "impulse-lab: " + dir.file("none.json").string() + ": cannot read: No such file or directory"},
        {{"diff", ruler, good, "--rtol", "-1"}, "impulse-lab: --rtol: must be a number >= 0, got -1"},
        {{"diff", ruler, good, "--atol", "nan"}, "impulse-lab: --atol: must be a number >= 0, got nan"},
        {{"diff", ruler, good, "--format", "xml"},
         "impulse-lab: --format: must be one of text, json, csv, got \"xml\""},
        {{"diff", ruler}, "impulse-lab: OTHER is required"},
    };
    for (auto [args, starts] : table) {
        args.insert(args.end(), {"--out", report});
        const auto& expected = starts;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
        CAPTURE(expected);
        const CliResult r = run_cli(args);
        CHECK(r.code == 2);
        CHECK(r.err.rfind(starts, 0) == 0);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.out.empty());
        CHECK_FALSE(std::filesystem::exists(report));
    }
}

TEST_CASE("a worksheet filled from the reference matches every cell and writes the report file too") {
    TempDir dir;
    const std::string sheet = write_json(dir, "filled.json", filled_worksheet("cases/ruler"));
    const std::string report = dir.file("report.json").string();
    const CliResult r = run_cli({"diff", ruler, sheet, "--format", "json", "--out", report});
    CHECK(r.code == 0);
    const formats::json written = read_json(report);
    CHECK(r.out == read_text(report));
    CHECK(written["other_kind"] == "worksheet");
    CHECK(written["matched"] == 89);  // every number of the ruler's 47 cells
    CHECK(written["mismatched"] == 0);
    CHECK(written["blank"] == 0);
    // The worksheet itself can be the reference: it re-runs what it was made from.
    CHECK(run_cli({"diff", sheet, sheet}).code == 0);
}

TEST_CASE("one wrong cell of a worksheet is reported alone, and a blank one as blank") {
    TempDir dir;
    formats::json document = filled_worksheet("cases/sliding_box");
    // Two of the sliding box's values: the first impulse's normal part, and body 0's rotation change.
    cell_at(document, "frames[0].phases[1].iterations[0].impulse")[0] = 0.5;
    cell_at(document, "frames[0].phases[1].iterations[0].rotation_change[0]")[2] = nullptr;
    const std::string sheet = write_json(dir, "student.json", document);
    const formats::json report = diff_json(cases + "sliding_box.json", sheet, 1);
    CHECK(report["mismatched"] == 1);
    CHECK(report["blank"] == 1);
    REQUIRE(report["findings"].size() == 2);
    const formats::json& wrong = report["findings"][0];
    CHECK(wrong["kind"] == "value");
    CHECK(wrong["path"] == "frames[0].phases[1].iterations[0].impulse[0]");
    CHECK(wrong["expected"].get<double>() == doctest::Approx(0.45291949485020394));
    CHECK(wrong["found"] == 0.5);
    CHECK(wrong["equation"] == "(14.3)");
    CHECK(wrong["first_divergence"] == true);
    const formats::json& blank = report["findings"][1];
    CHECK(blank["kind"] == "blank");
    CHECK(blank["path"] == "frames[0].phases[1].iterations[0].rotation_change[0][2]");
    CHECK(blank["first_divergence"] == false);
}

TEST_CASE("a CSV worksheet is graded the same way, one row per number") {
    TempDir dir;
    const std::vector<std::string> steps{"phase=velocity,iteration=0,step=impulse", "phase=position,iteration=0"};
    const std::string perfect = dir.write("perfect.csv", filled_csv("cases/ruler", steps)).string();
    const formats::json all = diff_json(ruler, perfect, 0);
    CHECK(all["mismatched"] == 0);
    CHECK(all["matched"].get<int>() > 10);

    std::string text = filled_csv("cases/ruler", steps);
    const std::string row = "cell,frames[0].phases[1].iterations[0].impulse_world[1],impulse,impulse_world[1],";
    const std::size_t at = text.find(row);
    REQUIRE(at != std::string::npos);
    text.replace(at + row.size(), text.find(',', at + row.size()) - at - row.size(), "0.15");
    const std::string blank_row =
        "cell,frames[0].phases[0].iterations[0].penetration_inertia,penetration_inertia,penetration_inertia,";
    const std::size_t blank_at = text.find(blank_row);
    REQUIRE(blank_at != std::string::npos);
    text.erase(blank_at + blank_row.size(), text.find(',', blank_at + blank_row.size()) - blank_at - blank_row.size());
    const formats::json report = diff_json(ruler, dir.write("student.csv", text).string(), 1);
    REQUIRE(report["findings"].size() == 2);
    // In trace order: the position phase ran first.
    CHECK(report["findings"][0]["kind"] == "blank");
    CHECK(report["findings"][0]["path"] == "frames[0].phases[0].iterations[0].penetration_inertia");
    CHECK(report["findings"][1]["kind"] == "value");
    CHECK(report["findings"][1]["path"] == "frames[0].phases[1].iterations[0].impulse_world[1]");
    CHECK(report["findings"][1]["first_divergence"] == true);
    CHECK(report["all_match"] == false);
}

TEST_CASE("a folder of filled worksheets is summarised one row per file, a malformed one included") {
    TempDir dir;
    std::filesystem::create_directory(dir.file("class"));
    formats::json perfect = filled_worksheet("cases/ruler");
    write_json(dir, "class/ada.json", perfect);
    formats::json wrong = perfect;
    cell_at(wrong, "frames[0].phases[1].iterations[0].impulse_world")[1] = 0.15;
    write_json(dir, "class/ben.json", wrong);
    dir.write("class/cy.json", "{\"format\": \"impulse-lab-worksheet\", \"version\": 2, \"steps\": []}");
    const CliResult r = run_cli({"diff", ruler, dir.file("class").string(), "--format", "csv"});
    // A submission that cannot be read does not stop the others: it gets its row and a line, and exit code 1.
    CHECK(r.code == 1);
    const std::string cy = dir.file("class/cy.json").string();
    CHECK(r.err == "impulse-lab: " + cy + ": version: must be 1, got 2\n");
    const std::vector<formats::CsvRow> rows = formats::parse_csv(r.out);
    REQUIRE(rows.size() == 4);
    CHECK(rows[0].fields == std::vector<std::string>{"file", "kind", "cells", "matched", "mismatched", "blank",
                                                     "score_percent", "first_divergence", "first_divergence_path",
                                                     "error"});
    CHECK(rows[1].fields == std::vector<std::string>{dir.file("class/ada.json").string(), "worksheet", "89", "89", "0",
                                                     "0", "100.0", "", "", ""});
    // 88 of 89: 98.876... %, one decimal.
    CHECK(rows[2].fields ==
          std::vector<std::string>{dir.file("class/ben.json").string(), "worksheet", "89", "88", "1", "0", "98.9",
                                   "frame 0 · velocity phase · iteration 0 · contact 0 · impulse: impulse_world[1]",
                                   "frames[0].phases[1].iterations[0].impulse_world[1]", ""});
    CHECK(rows[3].fields == std::vector<std::string>{cy, "", "", "", "", "", "", "", "", "version: must be 1, got 2"});
}

TEST_CASE("several files that all match exit 0 with a text summary") {
    TempDir dir;
    const std::string a = write_json(dir, "a.json", filled_worksheet("cases/ruler"));
    const std::string b = edited_trace(dir, "b.json", [](formats::json&) {});
    const CliResult r = run_cli({"diff", ruler, a, b});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("2 files: 2 all match, 0 with mismatches or blanks, 0 unreadable") != std::string::npos);
}

TEST_CASE(
    "a CSV answer that is not a number is graded wrong, a row cut short is blank, and so is the rest of its step") {
    TempDir dir;
    const std::string sheet = dir.write("answers.csv",
                                        "kind,path,value\n"
                                        "cell,frames[0].phases[1].iterations[0].impulse_model,frictionless\n"
                                        "cell,frames[0].contacts[0].restitution_cutoff_applied,FALSE\n"
                                        "cell,frames[0].contacts[0].separating_velocity,minus three\n"
                                        "cell,frames[0].contacts[0].desired_delta_velocity\n"
                                        "cell,frames[0].contacts[3].penetration,0.02\n")
                                  .string();
    const formats::json report = diff_json(ruler, sheet, 1);
    CHECK(report["matched"] == 2);
    CHECK(report["mismatched"] == 2);
    // Graded at the places of the steps it answers: step 5 of contact 0 (separating_velocity, restitution_used,
    // velocity_from_acceleration, desired_delta_velocity) and step 6 of iteration 0 (impulse_model, impulse and
    // impulse_world, three numbers each); what it leaves out of them is blank.
    CHECK(report["blank"] == 9);
    std::vector<std::pair<std::string, std::string>> found;
    for (const formats::json& f : report["findings"])
        if (f["kind"] != "blank" || f["path"] == "frames[0].contacts[0].desired_delta_velocity")
            found.emplace_back(f["kind"], f["path"]);
    CHECK(found == std::vector<std::pair<std::string, std::string>>{
                       {"value", "frames[0].contacts[0].separating_velocity"},
                       {"blank", "frames[0].contacts[0].desired_delta_velocity"},
                       {"not_in_reference", "frames[0].contacts[3].penetration"},
                   });
    CHECK(report["findings"][0]["found"] == "minus three");
    CHECK(report["findings"][0]["relative_error"].is_null());
}

TEST_CASE("a velocity iteration's wrong contact velocity is the first divergence, not the desired change after it") {
    // The iteration's record writes desired_delta_velocity before contact_velocity; the derivation computes
    // them the other way round, and so must the first divergence be chosen.
    TempDir dir;
    formats::json document = filled_worksheet("cases/ruler");
    cell_at(document, "frames[0].phases[1].iterations[0].contact_velocity")[0] = -2.9;
    cell_at(document, "frames[0].phases[1].iterations[0].desired_delta_velocity") = 4.35;  // −(1 + 0.5)·(−2.9)
    const formats::json report = diff_json(ruler, write_json(dir, "student.json", document), 1);
    REQUIRE(report["findings"].size() == 2);
    CHECK(report["findings"][0]["path"] == "frames[0].phases[1].iterations[0].contact_velocity[0]");
    CHECK(report["findings"][0]["first_divergence"] == true);
    CHECK(report["findings"][1]["path"] == "frames[0].phases[1].iterations[0].desired_delta_velocity");
}
