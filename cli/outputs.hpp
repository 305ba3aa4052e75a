#pragma once
// The files a command writes, named by its flags. "-" is standard output, and so is a path that names the very
// file, pipe or terminal standard output already is (/dev/stdout, or the file it was redirected to): writing
// that path by name would replace a file the shell holds open, or write a device twice. When standard output
// carries a file nothing else goes there: the command's report moves to standard error. The other outputs are
// checked before the command runs and written together at its end, atomically (io/atomic_file.hpp).

#include "formats/atomic_file.hpp"

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::cli {

// True when `stream` is the program's standard output or error and that is a terminal.
bool is_terminal(const std::ostream& stream);

// True when writing `path` would write the program's standard output: "-", or a path naming what standard
// output is. Only when `out` is std::cout can a path name it (in-process tests give a string stream).
bool names_standard_output(const std::string& path, const std::ostream& out);

// The files one command reads and writes, told apart before anything runs: an output that is one of the inputs
// would replace what is being read (`worksheet case.json --out case.json`, `diff --out` over a student's file), and
// two outputs on one file would replace each other (`--trace X --states X` lost the trace). A file is the same
// when its device and inode are (a link, or another spelling of the path), or, before it exists, when its path
// is once made absolute and normal. Standard input and output ("-") and character devices such as /dev/null are
// never the same as anything.
class DistinctFiles {
public:
    // `what` names the file in messages: "the scene SCENE", "--trace".
    void input(std::string what, const std::string& path);
    // Throws formats::InputError(what, ...) when `path` is an input or an output already named.
    void output(std::string what, const std::string& path);

private:
    struct Named {
        std::string what;
        std::string path;
        std::string identity;  // "dev:inode", or the normal absolute path of a file not there yet
        bool output;
    };
    std::vector<Named> named_;
};

// An output a long command writes as it goes, a piece at a time, so that it is on disk and not in memory: into
// its staged file (a temporary beside it) or, for standard output, into an unlinked spool. Nothing reaches the
// file or standard output before Outputs::commit; dropped uncommitted, it leaves nothing behind.
class StreamedOutput {
public:
    // Throw formats::InputError(flag, ...) when the disk refuses it (the temporary is removed then).
    void append(std::string_view text);
    void append(const formats::Spool& spool);

private:
    friend class Outputs;
    std::string flag_;
    std::optional<formats::StagedFile> file_;   // a file: its temporary
    std::unique_ptr<formats::Spool> standard_;  // standard output: spooled until the command ends
};

class Outputs {
public:
    Outputs(std::ostream& out, std::ostream& err) : out_(out), err_(err) {}

    // Names one output, if given, and checks it now: writable, or standard output. Throws formats::InputError(flag,
    // ...) for a second output on standard output, or an output that cannot be written.
    void add(std::string_view flag, const std::optional<std::string>& path);

    // Where the command's report and notes go: standard output, or standard error when a file goes there.
    std::ostream& report() const { return to_standard_output_ ? err_ : out_; }
    bool to_standard_output() const { return to_standard_output_; }
    // The output a flag names goes to standard output.
    bool to_standard_output(std::string_view flag) const;

    // Writes each output's text (by its flag; an output not named is skipped): the files are staged, renamed
    // together with Ctrl-C held back until all are in place, then standard output gets its one.
    struct Text {
        std::string_view flag;
        std::string_view text;
    };
    void write(const std::vector<Text>& texts) const;

    // The output a flag names, to be written as the command goes (nullopt when the flag names none); its
    // temporary is made now. commit() puts every one given in place together, as write() does, then copies
    // standard output's.
    std::optional<StreamedOutput> stream(std::string_view flag) const;
    void commit(const std::vector<StreamedOutput*>& outputs) const;

    // The file a flag's output goes to, for the report; "" when it goes to standard output or was not named.
    std::string file_of(std::string_view flag) const;

private:
    struct Named {
        std::string flag;
        std::string path;
        bool standard_output;
    };
    std::ostream& out_;
    std::ostream& err_;
    std::vector<Named> named_;
    bool to_standard_output_ = false;
};

}  // namespace impulse::cli
