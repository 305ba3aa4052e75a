#include "cli/terminal_guard.hpp"

#include "formats/printable_text.hpp"

#include <ostream>

namespace impulse::cli {

namespace {

// Text is escaped and passed on in pieces of about this size (and at every flush).
constexpr std::size_t piece = 4096;

}  // namespace

TerminalGuard::~TerminalGuard() {
    forward(true);
    terminal_->pubsync();
}

TerminalGuard::int_type TerminalGuard::overflow(int_type c) {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    pending_ += traits_type::to_char_type(c);
    if (pending_.size() >= piece) forward(false);
    return c;
}

std::streamsize TerminalGuard::xsputn(const char* text, std::streamsize count) {
    pending_.append(text, static_cast<std::size_t>(count));
    if (pending_.size() >= piece) forward(false);
    return count;
}

int TerminalGuard::sync() {
    forward(false);
    return terminal_->pubsync();
}

void TerminalGuard::forward(bool all) {
    const std::size_t kept = all ? 0 : formats::incomplete_tail(pending_);
    const std::string shown = formats::printable(std::string_view(pending_).substr(0, pending_.size() - kept));
    terminal_->sputn(shown.data(), static_cast<std::streamsize>(shown.size()));
    pending_.erase(0, pending_.size() - kept);
}

std::streambuf* raw_buffer(std::ostream& stream) {
    if (auto* guard = dynamic_cast<TerminalGuard*>(stream.rdbuf())) {
        stream.flush();  // what the guard holds goes first
        return guard->terminal();
    }
    return stream.rdbuf();
}

}  // namespace impulse::cli
