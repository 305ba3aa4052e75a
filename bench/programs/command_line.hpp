#pragma once
// What the bench programs share on their command line: parsing with a one-line error, and `--csv FILE`, whose
// file is checked before the run and written whole (atomically) after it; `--csv -` puts the CSV on standard
// output and moves the table to standard error.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <string>

namespace impulse::bench {

// Parses the command line. Returns the code to exit with when the program should stop: 0 after --help, 2 after a
// one-line error ("impulse-bench-world: --repeats: ... (see impulse-bench-world --help)"); nothing to run on.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

class CsvOutput {
public:
    // Adds --csv to `app`, whose name prefixes the errors.
    explicit CsvOutput(CLI::App& app);

    // After parsing: whether the file can be written (or is standard output); prints the error when not.
    bool check() const;
    // Where the table goes: standard error when the CSV takes standard output, else standard output.
    std::FILE* table() const;
    // Writes `rows` where --csv said, if it was given; false after printing the error when it could not.
    bool write(const std::string& rows) const;

private:
    std::string program_;
    std::string path_;
};

}  // namespace impulse::bench
