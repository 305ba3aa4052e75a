#include "command_line.hpp"

#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"

#include <iostream>

namespace impulse::bench {

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << app.get_name() << ": " << e.what() << " (see " << app.get_name() << " --help)\n";
        return 2;
    }
    return std::nullopt;
}

CsvOutput::CsvOutput(CLI::App& app) : program_(app.get_name()) {
    app.add_option("--csv", path_, "Also write the figures as CSV");
}

bool CsvOutput::check() const {
    try {
        if (!path_.empty() && path_ != "-") formats::check_writable(path_, "--csv");
    } catch (const formats::InputError& e) {
        std::cerr << program_ << ": " << e.what() << '\n';
        return false;
    }
    return true;
}

std::FILE* CsvOutput::table() const {
    return path_ == "-" ? stderr : stdout;
}

bool CsvOutput::write(const std::string& rows) const {
    if (path_ == "-") {
        std::cout << rows << std::flush;
    } else if (!path_.empty()) {
        try {
            formats::write_file_atomically(path_, rows, "--csv");
        } catch (const formats::InputError& e) {
            std::cerr << program_ << ": " << e.what() << '\n';
            return false;
        }
    }
    return true;
}

}  // namespace impulse::bench
