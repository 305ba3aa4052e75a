#pragma once
// Every output file is written atomically: the text goes to a temporary file beside the target, is flushed
// to disk, and is renamed over the target. A reader (or a crash, or Ctrl-C) sees the old file or the whole
// new one, never half of it. A command that writes several files stages them all first and renames them
// only when every one was written, so a failure leaves none of them changed.

#include <csignal>
#include <filesystem>
#include <string>
#include <string_view>

namespace impulse::io {

// A file written to its temporary name, waiting to be renamed into place.
class StagedFile {
public:
    // Throws InputError(flag, "cannot write '<path>': <reason>"); no temporary is left behind.
    StagedFile(const std::filesystem::path& path, std::string_view contents, std::string_view flag);
    ~StagedFile();  // removes the temporary unless committed
    StagedFile(StagedFile&& other) noexcept;
    StagedFile(const StagedFile&) = delete;
    StagedFile& operator=(const StagedFile&) = delete;
    StagedFile& operator=(StagedFile&&) = delete;

    void commit();  // renames it over the target; throws InputError like the constructor

private:
    std::filesystem::path path_;
    std::string temporary_;
    std::string flag_;
};

// Holds SIGINT and SIGTERM back (in this thread) while it lives, so that staging a file and renaming a set of
// files into place is never cut short: a signal that arrives meanwhile is delivered when it ends, once the
// files are whole and no temporary is left. write_file_atomically holds them itself; a command that stages
// several files holds them around all of its stages and commits.
class DeferredSignals {
public:
    DeferredSignals();
    ~DeferredSignals();
    DeferredSignals(const DeferredSignals&) = delete;
    DeferredSignals& operator=(const DeferredSignals&) = delete;

private:
    sigset_t previous_;
};

void write_file_atomically(const std::filesystem::path& path, std::string_view contents, std::string_view flag);

// Throws InputError(flag, ...) now if `path` could not be written later: its directory is missing or is
// not a directory, or the path is a directory. Lets a long run fail before it starts, not after.
void check_writable(const std::filesystem::path& path, std::string_view flag);

}  // namespace impulse::io
