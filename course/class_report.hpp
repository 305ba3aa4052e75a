#pragma once
// Grading a class: a report per handed-in file, summarised one row per file (text, JSON or CSV), every graded
// number one row per file (cells.csv), and a feedback page per student in the worksheet's own words, the
// first divergence marked (docs/coursework.md, "A class").

#include "course/diff_report.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impulse::course {

// One file of a class: its report, or why it could not be read.
struct ClassRow {
    std::string file;
    std::optional<DiffReport> report;
    std::string error;  // "where: problem" when the file could not be graded
};

// What the class was graded against, for the reports' headers.
struct ClassSubject {
    std::string reference;  // the file, as given
    std::string what;       // "lesson 7 · Calculating and applying the impulse", "worksheet", "case", "trace"
    Tolerance tolerance;
    bool answer_key = false;  // the expected values are a teacher's filled sheet, not the engine's run
};

// A table of the files (score, right, wrong, blank, the first divergence in the worksheet's words), then for
// each file its wrong and blank numbers in the worksheet's words (at most `per_file`), then a count.
std::string summary_text(const std::vector<ClassRow>& rows, const ClassSubject& subject, std::size_t per_file = 10);
std::string summary_json(const std::vector<ClassRow>& rows, const ClassSubject& subject);

// summary.csv: file,kind,cells,matched,mismatched,blank,score_percent,first_divergence,first_divergence_path,error
std::string summary_csv(const std::vector<ClassRow>& rows);

// cells.csv: file,place,quantity,unit,expected,found,relative_error,verdict,first_divergence,path; an expected
// number as the shortest decimal that grades the same under `tolerance` (0.0856025404, not 0.08560254040000001:
// rounded_for_hand_work), a relative error to 3 significant digits. A worksheet
// has a row for every number of its cells (right, wrong, blank), then one per difference in the settings or
// scene it was made with (verdict `setting` or `scene`); a trace a row per finding only (its verdict the
// finding's kind: value, missing, extra, setting, scene); a file that could not be read one row saying why.
std::string cells_csv(const std::vector<ClassRow>& rows, const Tolerance& tolerance);

// The feedback page handed back to the student who wrote `row.file` (Markdown).
std::string feedback_markdown(const ClassRow& row, const ClassSubject& subject);

// The names of the feedback pages of `files`, one each, in order: the file's name without its extension plus
// ".md", or its whole name plus ".md" when two files share that stem (ada.json and ada.csv).
std::vector<std::string> feedback_names(const std::vector<std::string>& files);

}  // namespace impulse::course
