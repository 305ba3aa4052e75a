#pragma once
// A diff of one file as a person reads it (text), as a program reads it (JSON), or as a spreadsheet does (CSV).
// A class of several files: coursework/class_report.hpp.

#include "course/diff.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impulse::course {

struct DiffSubject {
    std::string reference;  // the file names, as given
    std::string other;
    Tolerance tolerance;
};

// Every mismatch and blank with its path, expected and found values, relative error and equation; the first
// divergence marked; a summary line.
std::string report_text(const DiffReport& report, const DiffSubject& subject);
std::string report_json(const DiffReport& report, const DiffSubject& subject);
// kind,path,expected,found,relative_error,quantity,formula,equation,first_divergence,place,unit
std::string report_csv(const DiffReport& report);

// The parts the class report shares: a finding's place and quantity ("frame 0 · … · impulse: impulse_world[1]"),
// a score as a person reads it ("87.5 %"), and findings as aligned rows under their places (at most `limit`).
std::string worded(const Finding& finding);
// Whether a value after `first` (the first divergence) differs from the reference too: only then can the wrong
// numbers after it follow from it (a blank or a repeat does not).
bool later_divergence(const DiffReport& report, const Finding& first);
// Whether the report holds the finding that its worksheet gives no cells.
bool empty_sheet(const DiffReport& report);
std::string percent_text(double percent);
std::string findings_table(const std::vector<Finding>& findings, std::size_t limit, const Tolerance& tolerance);

// A value as a report shows it to a person: numbers to the significant digits the tolerance looks at (at least
// 6, so 0.452919 against rtol 1e-4), everything else as the worksheet writes it.
std::string shown_value(const formats::json& value, const Tolerance& tolerance);

}  // namespace impulse::course
