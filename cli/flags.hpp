#pragma once
// What the command line knows of its flags beyond CLI11: values said in words ("a whole number from 1 to
// 10000000"), the names a choice takes, which arguments are files read or written (and so may be "-"), and
// from that: one-line errors that name the flag and suggest the one meant, the `-` rules, and a bash
// completion script generated from the same definitions, so none of them can go stale.

#include <CLI/CLI.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace impulse::cli {

enum class ValueKind {
    other,
    input_file,   // read; "-" is standard input
    output_file,  // written; "-" is standard output
    folder,       // a folder, read or written: never "-"
};

struct FlagCatalog {
    std::map<const CLI::Option*, ValueKind> kinds;
    std::map<const CLI::Option*, std::vector<std::string>> choices;  // the names a choice takes
    std::map<const CLI::Option*, std::string> value_words;           // "a whole number from 1 to 10000000"
};

// Each marks `option` in the catalog, sets the name its value is shown by in the help (N, NUMBER, FILE, ...), adds
// the rule to its description in words, and (for numbers and choices) checks the value, saying what is wrong
// with it in words. Each returns `option`.
CLI::Option* whole_number(CLI::Option* option, FlagCatalog& catalog, long long lowest, long long highest);
CLI::Option* finite_number(CLI::Option* option, FlagCatalog& catalog, double lowest, double highest);
CLI::Option* one_of(CLI::Option* option, FlagCatalog& catalog, std::vector<std::string> names,
                    const std::string& value_name);
// A value in a form of its own (e.g. "K/N"): `check` returns what is wrong with a text, empty when it is good;
// `words` says the form in the help ("K/N: whole numbers, 1 <= K <= N").
CLI::Option* formatted(CLI::Option* option, FlagCatalog& catalog, const std::string& value_name,
                       const std::string& words, std::function<std::string(const std::string&)> check);
CLI::Option* input_file(CLI::Option* option, FlagCatalog& catalog);
CLI::Option* output_file(CLI::Option* option, FlagCatalog& catalog);
CLI::Option* folder(CLI::Option* option, FlagCatalog& catalog);

// The names a person writes for `command`'s options ("--frames", "-h", and positionals by name).
std::vector<std::string> flag_names(const CLI::App& command);

// The one line (without "impulse-lab: ") for a mistake CLI11 found in `args` (the arguments after the program's
// name; the first is the command): an unknown flag named with the one meant ("did you mean --frames?", or the
// command that has it), a missing value said in words, and a pointer to the command's own --help.
std::string parse_error_line(const CLI::App& app, const FlagCatalog& catalog, const std::vector<std::string>& args,
                             const CLI::ParseError& error);

// Throws formats::InputError if two arguments of `command` are "-" in the same direction (two files read from standard
// input, or two written to standard output), or a folder is given as "-".
void check_standard_streams(const CLI::App& command, const FlagCatalog& catalog);

// The help of the program and of every command in one text, laid out for help2man (the manual page is made
// from it): the introduction as the description, options as indented tags, a "*Commands*" section with one subsection
// per command, and `sections` (e.g. the exit codes) as further "*Name*" sections, each a list of "tag  text" lines.
struct HelpSection {
    std::string name;
    std::vector<std::pair<std::string, std::string>> entries;
};
std::string help_all_text(const CLI::App& app, const std::string& introduction,
                          const std::vector<HelpSection>& sections);

// A bash completion script for `app`: its commands, each command's flags, the names a choice takes, files for
// file arguments and folders for folders. Source it, or install it as
// share/bash-completion/completions/impulse-lab.
std::string bash_completion(const CLI::App& app, const FlagCatalog& catalog);

}  // namespace impulse::cli
