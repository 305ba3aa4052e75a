#pragma once
// A diff as a person reads it (text), as a program reads it (JSON), or as a spreadsheet does (CSV); and the
// class summary of several files, one row each.

#include "coursework/diff.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impulse::coursework {

struct DiffSubject {
    std::string reference;  // the file names, as given
    std::string other;
    Tolerance tolerance;
};

// Every mismatch and blank with its path, expected and found values, relative error and equation; the first
// divergence marked; a summary line.
std::string report_text(const DiffReport& report, const DiffSubject& subject);
std::string report_json(const DiffReport& report, const DiffSubject& subject);
// kind,path,expected,found,relative_error,quantity,formula,equation,first_divergence
std::string report_csv(const DiffReport& report);

// One file of a class: its report, or why it could not be read.
struct ClassRow {
    std::string file;
    std::optional<DiffReport> report;
    std::string error;  // "where: problem" when the file could not be graded
};

std::string summary_text(const std::vector<ClassRow>& rows, const std::string& reference, const Tolerance& tolerance);
std::string summary_json(const std::vector<ClassRow>& rows, const std::string& reference, const Tolerance& tolerance);
// file,matched,mismatched,blank,first_divergence,error
std::string summary_csv(const std::vector<ClassRow>& rows);

}  // namespace impulse::coursework
