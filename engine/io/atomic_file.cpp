#include "io/atomic_file.hpp"

#include "io/input_error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

namespace impulse::io {

namespace {

[[noreturn]] void fail(std::string_view flag, const std::filesystem::path& path, const std::string& reason) {
    throw InputError(std::string(flag), "cannot write '" + path.string() + "': " + reason);
}

}  // namespace

StagedFile::StagedFile(const std::filesystem::path& path, std::string_view contents, std::string_view flag)
    : path_(path), flag_(flag) {
    if (path.empty()) fail(flag, path, "empty file name");
    const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
    std::string temporary = (directory / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) fail(flag, path, std::strerror(errno));
    // mkstemp creates the file 0600; give it the permissions a normally created file would have.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);

    std::size_t written = 0;
    while (written < contents.size()) {
        const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            const std::string reason = std::strerror(errno);
            ::close(fd);
            ::unlink(temporary.c_str());
            fail(flag, path, reason);
        }
        written += static_cast<std::size_t>(n);
    }
    const bool synced = ::fsync(fd) == 0;
    const std::string sync_reason = synced ? "" : std::strerror(errno);
    const bool closed = ::close(fd) == 0;
    if (!synced || !closed) {
        const std::string reason = synced ? std::strerror(errno) : sync_reason;
        ::unlink(temporary.c_str());
        fail(flag, path, reason);
    }
    temporary_ = temporary;
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : path_(std::move(other.path_)), temporary_(std::move(other.temporary_)), flag_(std::move(other.flag_)) {
    other.temporary_.clear();
}

StagedFile::~StagedFile() {
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void StagedFile::commit() {
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        ::unlink(temporary_.c_str());
        temporary_.clear();
        fail(flag_, path_, reason);
    }
    temporary_.clear();
}

DeferredSignals::DeferredSignals() {
    sigset_t held;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &held, &previous_);
}

DeferredSignals::~DeferredSignals() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }

void write_file_atomically(const std::filesystem::path& path, std::string_view contents, std::string_view flag) {
    const DeferredSignals held;
    StagedFile(path, contents, flag).commit();
}

void check_writable(const std::filesystem::path& path, std::string_view flag) {
    if (path.empty()) fail(flag, path, "empty file name");
    const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
    std::error_code error;
    if (!std::filesystem::exists(directory, error)) fail(flag, path, "No such file or directory");
    if (!std::filesystem::is_directory(directory, error)) fail(flag, path, "Not a directory");
    if (std::filesystem::is_directory(path, error)) fail(flag, path, "Is a directory");
    if (::access(directory.c_str(), W_OK) != 0) fail(flag, path, std::strerror(errno));
}

}  // namespace impulse::io
