#include "formats/input_files.hpp"

#include "formats/input_error.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <poll.h>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace impulse::formats {

namespace {

std::string size_limit_text(std::size_t limit) {
    return "the limit of " + std::to_string(limit >> 20) + " MiB (" + std::to_string(limit) + " bytes)";
}

// All of standard input, up to one byte past the limit (read straight from the descriptor: std::cin would keep
// what it buffered).
std::string read_standard_input(std::size_t limit) {
    const std::string name = input_name(std::string(standard_stream));
    std::string text;
    std::array<char, 1 << 16> chunk{};
    while (text.size() <= limit) {
        const ssize_t n = ::read(STDIN_FILENO, chunk.data(), std::min(chunk.size(), limit + 1 - text.size()));
        if (n == 0) break;
        if (n < 0) {
            if (errno == EINTR) continue;
            throw FileError{name, "", std::string("cannot read: ") + std::strerror(errno)};
        }
        text.append(chunk.data(), static_cast<std::size_t>(n));
    }
    if (text.size() > limit) throw FileError{name, "", "goes on past " + size_limit_text(limit)};
    return text;
}

// A FIFO or character device: opened without blocking (a FIFO's open waits for a writer), then read as data
// arrives, in polls short enough that a signal's handler runs between them.
std::string read_special(const std::string& path, std::size_t limit, std::chrono::milliseconds silence) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) throw FileError{path, "", std::string("cannot read: ") + std::strerror(errno)};
    std::string text;
    std::array<char, 1 << 16> chunk{};
    const auto start = std::chrono::steady_clock::now();
    bool spoke = false;  // something arrived
    std::string problem;
    while (problem.empty()) {
        pollfd ready{fd, POLLIN, 0};
        const int polled = ::poll(&ready, 1, 100);
        if (polled < 0 && errno != EINTR) {
            problem = std::string("cannot read: ") + std::strerror(errno);
            break;
        }
        if (polled <= 0) {
            if (!spoke && std::chrono::steady_clock::now() - start >= silence) {
                const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(silence).count();
                problem = "nothing arrived within " +
                          (seconds > 0 ? std::to_string(seconds) + " s" : std::to_string(silence.count()) + " ms") +
                          ": a FIFO or device nobody writes to (start its writer first, or give a file)";
            }
            continue;
        }
        const ssize_t n = ::read(fd, chunk.data(), std::min(chunk.size(), limit + 1 - text.size()));
        if (n > 0) {
            spoke = true;
            text.append(chunk.data(), static_cast<std::size_t>(n));
            if (text.size() > limit) problem = "goes on past " + size_limit_text(limit);
        } else if (n == 0) {
            break;  // ready and nothing to read: the writer is done (or the device, /dev/null, has nothing)
        } else if (errno != EAGAIN && errno != EINTR) {
            problem = std::string("cannot read: ") + std::strerror(errno);
        }
    }
    ::close(fd);
    if (!problem.empty()) throw FileError{path, "", problem};
    return text;
}

}  // namespace

std::string input_name(const std::string& path) {
    return path == standard_stream ? "<stdin>" : path;
}

std::string read_input_file(const std::string& path, std::size_t limit, std::chrono::milliseconds silence) {
    if (path == standard_stream) return read_standard_input(limit);
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0)
        throw FileError{path, "", std::string("cannot read: ") + std::strerror(errno)};
    if (S_ISDIR(info.st_mode)) throw FileError{path, "", "is a directory, not a file"};
    if (S_ISFIFO(info.st_mode) || S_ISCHR(info.st_mode)) return read_special(path, limit, silence);
    if (static_cast<std::size_t>(info.st_size) > limit)
        throw FileError{path, "", "is " + std::to_string(info.st_size) + " bytes, over " + size_limit_text(limit)};
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError{path, "", std::string("cannot read: ") + std::strerror(errno)};
    // Read in chunks up to one byte past the limit: the size stat gave is 0 for pipes and devices.
    std::string text;
    std::array<char, 1 << 16> chunk{};
    while (in && text.size() <= limit) {
        in.read(chunk.data(), static_cast<std::streamsize>(std::min(chunk.size(), limit + 1 - text.size())));
        text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (text.size() > limit) throw FileError{path, "", "goes on past " + size_limit_text(limit)};
    if (in.bad()) throw FileError{path, "", std::string("cannot read: ") + std::strerror(errno)};
    return text;
}

namespace {

int parse_count(std::string_view text, std::string_view spec) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value < 0)
        throw formats::InputError(
            "--record", "\"" + std::string(text) + "\" in \"" + std::string(spec) + "\" is not a whole number >= 0");
    return value;
}

}  // namespace

void apply_record_spec(std::string_view spec, TraceFilter& filter) {
    const std::size_t equals = spec.find('=');
    const std::string_view key = spec.substr(0, equals);
    const std::string_view value = equals == std::string_view::npos ? std::string_view{} : spec.substr(equals + 1);
    if (key == "frames" && !value.empty()) {
        const std::size_t dots = value.find("..");
        if (dots == std::string_view::npos) {
            filter.first_frame = filter.last_frame = parse_count(value, spec);
        } else {
            filter.first_frame = parse_count(value.substr(0, dots), spec);
            filter.last_frame = parse_count(value.substr(dots + 2), spec);
        }
        if (filter.last_frame < filter.first_frame)
            throw formats::InputError("--record", "frames=A..B needs A <= B, got \"" + std::string(spec) + "\"");
        return;
    }
    if (key == "contacts" && !value.empty()) {
        std::vector<int> contacts;
        std::size_t start = 0;
        while (start <= value.size()) {
            const std::size_t comma = std::min(value.find(',', start), value.size());
            contacts.push_back(parse_count(value.substr(start, comma - start), spec));
            start = comma + 1;
        }
        std::sort(contacts.begin(), contacts.end());
        contacts.erase(std::unique(contacts.begin(), contacts.end()), contacts.end());
        filter.contacts = contacts;
        return;
    }
    throw formats::InputError("--record",
                              "expected frames=A..B or contacts=I,J,..., got \"" + std::string(spec) + "\"");
}

std::string trace_stopped_note(int frame, std::optional<double> max_trace_mb) {
    std::ostringstream note;
    note << "impulse-lab: note: the trace reached --max-trace-mb " << trace_budget_bytes(max_trace_mb) / 1e6
         << " at frame " << frame << " and ends with frame " << frame - 1
         << "; the frames after it ran unrecorded (raise --max-trace-mb or narrow --record)";
    return note.str();
}

}  // namespace impulse::formats
