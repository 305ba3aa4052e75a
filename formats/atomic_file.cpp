#include "formats/atomic_file.hpp"

#include "formats/input_error.hpp"

#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ostream>
#include <ctime>
#include <array>
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace impulse::formats {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(std::string_view flag, const fs::path& path, const std::string& reason) {
    throw InputError(std::string(flag), "cannot write '" + path.string() + "': " + reason);
}

// The folder a replaced file's temporary goes in.
fs::path folder_of(const fs::path& file) {
    return file.has_parent_path() ? file.parent_path() : fs::path(".");
}

bool same_file(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// Follows a chain of symbolic links from `path` to the first name that is not one (which may not exist yet).
// A relative link is read from the folder the link is in, as the kernel reads it.
fs::path end_of_links(const fs::path& path, std::string_view flag) {
    fs::path at = path;
    for (int hops = 0;; ++hops) {
        struct stat info {};
        if (::lstat(at.c_str(), &info) != 0) {
            if (errno == ENOENT) return at;
            fail(flag, path, std::strerror(errno));
        }
        if (!S_ISLNK(info.st_mode)) return at;
        if (hops == 40) fail(flag, path, std::strerror(ELOOP));
        std::error_code error;
        const fs::path next = fs::read_symlink(at, error);
        if (error) fail(flag, path, error.message());
        at = next.is_absolute() ? next : at.parent_path() / next;
    }
}

WriteInterruptions* program_policy = nullptr;

// An interruption is waiting to take effect (held back by the program's policy).
bool interrupt_pending() {
    return program_policy != nullptr && program_policy->pending();
}

constexpr const char* interrupted_waiting = "interrupted while waiting for its reader";

// Throws WaitInterrupted when `reason` says the wait for a reader was interrupted, else InputError.
[[noreturn]] void fail_write(std::string_view flag, const fs::path& path, const std::string& reason) {
    if (reason == interrupted_waiting) throw WaitInterrupted{std::string(flag), path.string()};
    fail(flag, path, reason);
}

// Opens a FIFO, device or terminal for writing without blocking, or returns -1 and why not. A FIFO nobody reads
// yet is waited for in short pauses, so that a Ctrl-C held back meanwhile still ends the wait.
int open_in_place(const fs::path& target, std::string& reason) {
    struct stat info {};
    const bool regular = ::stat(target.c_str(), &info) == 0 && S_ISREG(info.st_mode);
    const int flags = O_WRONLY | O_NOCTTY | O_CLOEXEC | (regular ? O_TRUNC : O_NONBLOCK);
    while (true) {
        const int fd = ::open(target.c_str(), flags);
        if (fd >= 0) return fd;
        if (errno == EINTR) continue;
        if (errno != ENXIO) {  // ENXIO: a FIFO with no reader yet
            reason = std::strerror(errno);
            return -1;
        }
        if (interrupt_pending()) {
            reason = interrupted_waiting;
            return -1;
        }
        const timespec pause{0, 20'000'000};
        ::nanosleep(&pause, nullptr);
    }
}

// Writes all of `text` to an open file, FIFO, device or terminal; returns why it could not, or "". A reader that
// stops reading is waited for in short polls, for the same reason as above.
std::string write_all(int fd, std::string_view text) {
    std::size_t written = 0;
    while (written < text.size()) {
        const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n >= 0) {
            written += static_cast<std::size_t>(n);
            continue;
        }
        if (errno == EINTR) continue;
        if (errno != EAGAIN) return std::strerror(errno);
        pollfd ready{fd, POLLOUT, 0};
        if (interrupt_pending() || (::poll(&ready, 1, 100) < 0 && errno == EINTR)) return interrupted_waiting;
    }
    return {};
}

// Writes everything the file `spool` holds to `fd`, a piece at a time, and leaves `spool` at its end for more
// appends; returns why it could not, or "".
std::string copy_all(int spool, int fd) {
    if (::lseek(spool, 0, SEEK_SET) != 0) return std::strerror(errno);
    std::array<char, 1 << 16> chunk{};
    while (true) {
        const ssize_t n = ::read(spool, chunk.data(), chunk.size());
        if (n == 0) return {};
        if (n < 0) {
            if (errno == EINTR) continue;
            return std::strerror(errno);
        }
        if (std::string reason = write_all(fd, std::string_view(chunk.data(), static_cast<std::size_t>(n)));
            !reason.empty())
            return reason;
    }
}

// Writes what `spool` holds in place. A reader that goes away gives an error (EPIPE) where the program's policy
// holds SIGPIPE back, not a signal that would end the program between two files of a set.
void write_in_place(const fs::path& target, int spool, std::string_view flag, const fs::path& path) {
    std::string reason;
    const int fd = open_in_place(target, reason);
    if (fd >= 0) {
        reason = copy_all(spool, fd);
        if (::close(fd) != 0 && reason.empty() && errno != EINTR) reason = std::strerror(errno);
    }
    if (!reason.empty()) fail_write(flag, path, reason);
}

// An anonymous file in `folder`: made and unlinked at once, so nothing is left of it whatever ends the program.
int anonymous_file(const fs::path& folder, std::string& reason) {
    std::string name = (folder / ".impulse-lab-spool-XXXXXX").string();
    const int fd = ::mkstemp(name.data());
    if (fd < 0) {
        reason = std::strerror(errno);
        return -1;
    }
    ::unlink(name.c_str());
    return fd;
}

// A temporary's name: ".NAME.tmp-PID-XXXXXX" beside NAME, so that one left by a writer that was killed (SIGKILL,
// a power cut) is known for an orphan by its process being gone.
std::string temporary_prefix(const fs::path& target) {
    return "." + target.filename().string() + ".tmp-";
}

// Removes the temporaries an earlier writer of `target` left when it was killed: those whose process no longer
// exists. A writer still running (another impulse-lab writing the same file now) keeps its own.
void remove_orphans(const fs::path& target) {
    const std::string prefix = temporary_prefix(target);
    std::error_code error;
    for (fs::directory_iterator it(folder_of(target), error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (!name.starts_with(prefix)) continue;
        const std::string rest = name.substr(prefix.size());
        const std::size_t dash = rest.find('-');
        if (dash == std::string::npos || dash == 0 || rest.size() - dash - 1 != 6) continue;
        long pid = 0;
        const auto [end_of_pid, bad] = std::from_chars(rest.data(), rest.data() + dash, pid);
        if (bad != std::errc() || end_of_pid != rest.data() + dash || pid <= 0) continue;
        if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to ask
        struct stat info {};
        if (::lstat(it->path().c_str(), &info) == 0 && S_ISREG(info.st_mode)) ::unlink(it->path().c_str());
    }
}

}  // namespace

OutputTarget output_target(const fs::path& path, std::string_view flag) {
    if (path.empty()) fail(flag, path, "empty file name");
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) {
        // Nothing there yet, or a link to nothing yet: the file is made where the last link points.
        if (errno != ENOENT) fail(flag, path, std::strerror(errno));
        return {OutputKind::replaced, end_of_links(path, flag)};
    }
    if (S_ISDIR(info.st_mode)) fail(flag, path, std::strerror(EISDIR));
    if (S_ISFIFO(info.st_mode) || S_ISCHR(info.st_mode)) return {OutputKind::in_place, path};
    if (S_ISBLK(info.st_mode)) fail(flag, path, "is a block device, not a file");
    if (S_ISSOCK(info.st_mode)) fail(flag, path, "is a socket, not a file");
    // A regular file, perhaps at the end of links. A link that the kernel resolves by other means than its text
    // (/proc/self/fd/1 standing for an open file, perhaps one since deleted) has no name to rename over: it is
    // written in place.
    const fs::path file = end_of_links(path, flag);
    struct stat end {};
    if (::lstat(file.c_str(), &end) != 0 || !same_file(info, end)) return {OutputKind::in_place, path};
    return {OutputKind::replaced, file};
}

StagedFile::StagedFile(const fs::path& path, std::string_view flag) : path_(path), flag_(flag) {
    const OutputTarget target = output_target(path, flag);
    target_ = target.path;
    kind_ = target.kind;
    std::string reason;
    if (kind_ == OutputKind::in_place) {
        // Spooled until commit, on disk rather than in memory: a FIFO's reader gets the whole or nothing.
        fd_ = anonymous_file(fs::temp_directory_path(), reason);
        if (fd_ < 0) fail(flag, path, reason);
        pending_ = true;
        return;
    }
    remove_orphans(target_);
    std::string temporary =
        (folder_of(target_) / (temporary_prefix(target_) + std::to_string(::getpid()) + "-XXXXXX")).string();
    fd_ = ::mkstemp(temporary.data());
    if (fd_ < 0) fail(flag, path, std::strerror(errno));
    // mkstemp creates the file 0600: give it the permissions of the file it replaces, or those a newly created
    // file would have.
    struct stat old {};
    if (::stat(target_.c_str(), &old) == 0) {
        ::fchmod(fd_, old.st_mode & 07777);
    } else {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        ::fchmod(fd_, 0666 & ~mask);
    }
    temporary_ = temporary;
    pending_ = true;
}

StagedFile::StagedFile(const fs::path& path, std::string_view contents, std::string_view flag)
    : StagedFile(path, flag) {
    append(contents);
    finish();
}

void StagedFile::append(std::string_view text) {
    if (const std::string reason = write_all(fd_, text); !reason.empty()) {
        discard();
        fail(flag_, path_, reason);
    }
    size_ += text.size();
}

void StagedFile::append(const Spool& spool) {
    std::string reason = spool.copy_to(fd_);
    if (!reason.empty()) {
        discard();
        fail(flag_, path_, reason);
    }
    size_ += spool.size();
}

void StagedFile::finish() {
    if (kind_ != OutputKind::replaced || fd_ < 0) return;
    const bool synced = ::fsync(fd_) == 0;
    const std::string sync_reason = synced ? "" : std::strerror(errno);
    const bool closed = ::close(fd_) == 0;
    fd_ = -1;
    if (!synced || !closed) {
        const std::string reason = synced ? std::strerror(errno) : sync_reason;
        discard();
        fail(flag_, path_, reason);
    }
}

void StagedFile::discard() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (pending_ && kind_ == OutputKind::replaced) ::unlink(temporary_.c_str());
    pending_ = false;
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      kind_(other.kind_),
      temporary_(std::move(other.temporary_)),
      fd_(other.fd_),
      size_(other.size_),
      pending_(other.pending_),
      flag_(std::move(other.flag_)) {
    other.temporary_.clear();
    other.fd_ = -1;
    other.pending_ = false;
}

StagedFile::~StagedFile() {
    discard();
}

void StagedFile::commit() {
    if (!pending_) return;
    finish();
    pending_ = false;
    if (kind_ == OutputKind::in_place) {
        const int spool = fd_;
        fd_ = -1;
        try {
            write_in_place(target_, spool, flag_, path_);
        } catch (...) {
            ::close(spool);
            throw;
        }
        ::close(spool);
        return;
    }
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        ::unlink(temporary_.c_str());
        fail(flag_, path_, reason);
    }
}

Spool::Spool(const fs::path& beside) {
    std::string reason;
    fd_ = anonymous_file(folder_of(beside), reason);
    if (fd_ < 0) fd_ = anonymous_file(fs::temp_directory_path(), reason);
    if (fd_ < 0) throw InputError("", "cannot make a temporary file: " + reason);
}

Spool::~Spool() {
    if (fd_ >= 0) ::close(fd_);
}

void Spool::append(std::string_view text) {
    if (const std::string reason = write_all(fd_, text); !reason.empty())
        throw InputError("", "cannot write a temporary file: " + reason);
    size_ += text.size();
}

void Spool::append(const Spool& other) {
    if (const std::string reason = other.copy_to(fd_); !reason.empty())
        throw InputError("", "cannot write a temporary file: " + reason);
    size_ += other.size_;
}

std::string Spool::copy_to(int fd) const {
    return copy_all(fd_, fd);
}

void Spool::copy_to(std::ostream& out) const {
    ::lseek(fd_, 0, SEEK_SET);
    std::array<char, 1 << 16> chunk{};
    for (ssize_t n; (n = ::read(fd_, chunk.data(), chunk.size())) != 0;) {
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError("", std::string("cannot read a temporary file: ") + std::strerror(errno));
        }
        out.write(chunk.data(), n);
    }
    ::lseek(fd_, 0, SEEK_END);
}

void set_write_interruptions(WriteInterruptions* policy) {
    program_policy = policy;
}

HeldInterruptions::HeldInterruptions() : policy_(program_policy) {
    if (policy_) policy_->hold();
}

HeldInterruptions::~HeldInterruptions() {
    if (policy_) policy_->release();
}

void write_file_atomically(const fs::path& path, std::string_view contents, std::string_view flag) {
    const HeldInterruptions held;
    StagedFile(path, contents, flag).commit();
}

void check_writable(const fs::path& path, std::string_view flag) {
    const OutputTarget target = output_target(path, flag);
    if (target.kind == OutputKind::in_place) {
        if (::access(path.c_str(), W_OK) != 0) fail(flag, path, std::strerror(errno));
        return;
    }
    const fs::path folder = folder_of(target.path);
    struct stat info {};
    if (::stat(folder.c_str(), &info) != 0) fail(flag, path, std::strerror(errno));
    if (!S_ISDIR(info.st_mode)) fail(flag, path, std::strerror(ENOTDIR));
    if (::access(folder.c_str(), W_OK) != 0) fail(flag, path, std::strerror(errno));
}

}  // namespace impulse::formats
