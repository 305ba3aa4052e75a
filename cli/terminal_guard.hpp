#pragma once
// What reaches a terminal is shown, never obeyed. The program prints text from files — a body's name, a
// student's answer, a lesson's words, a file's name — and an escape sequence among them (ESC [ 2 J, ESC ] 0 ;
// title BEL, a C1 CSI) would clear a teacher's screen, move the cursor or retitle the window. When standard
// output or error is a terminal, main() puts a TerminalGuard between it and the program: every control character
// but the line break and the tab is written as a readable escape (formats::printable). The progress bar, the
// program's one terminal control of its own (a carriage return and ESC [ K), writes past it (raw_buffer).

#include <streambuf>
#include <string>

namespace impulse::cli {

class TerminalGuard final : public std::streambuf {
public:
    explicit TerminalGuard(std::streambuf* terminal) : terminal_(terminal) {}
    ~TerminalGuard() override;
    TerminalGuard(const TerminalGuard&) = delete;
    TerminalGuard& operator=(const TerminalGuard&) = delete;

    std::streambuf* terminal() const { return terminal_; }

protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* text, std::streamsize count) override;
    int sync() override;

private:
    // Writes what is pending, escaped, except an incomplete UTF-8 sequence at its end (unless `all`).
    void forward(bool all);

    std::streambuf* terminal_;
    std::string pending_;
};

// The buffer beneath a guard, or the stream's own buffer when it has none: for writing terminal controls of the
// program's own.
std::streambuf* raw_buffer(std::ostream& stream);

}  // namespace impulse::cli
