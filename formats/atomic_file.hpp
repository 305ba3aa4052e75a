#pragma once
// Every output file is written atomically: the text goes to a temporary file beside the target, is flushed
// to disk, and is renamed over the target. A reader (or a crash, or Ctrl-C) sees the old file or the whole
// new one, never half of it. A command that writes several files stages them all first and renames them
// only when every one was written, so a failure leaves none of them changed.
//
// What is replaced is a file, never what a path stands for: a symbolic link is followed (the whole chain) and
// its target replaced in the target's folder, so the link stays a link; a FIFO, a character device or a
// terminal (/dev/null, a pipe a reader waits on) cannot be replaced by a rename and is written in place;
// a directory, a socket or a block device is refused.

#include <filesystem>
#include <string>
#include <string_view>

namespace impulse::formats {

// How an output path is written.
enum class OutputKind {
    replaced,  // a regular file, or none yet: a temporary in its folder renamed over it
    in_place,  // a FIFO, character device or terminal: opened and written directly, no temporary, no rename
};

struct OutputTarget {
    OutputKind kind = OutputKind::replaced;
    std::filesystem::path path;  // replaced: the file itself (a link's final target); in place: the path as given
};

// Where and how `path` would be written. Throws InputError(flag, "cannot write '<path>': <reason>") for a
// directory, a socket, a block device, a loop of links or a path through something that is not a folder.
OutputTarget output_target(const std::filesystem::path& path, std::string_view flag);

// An anonymous file on disk that a long command appends to and reads back (a run's frames, until the trace's
// head can be written before them): made and unlinked at once beside a path (else in the temporary folder), so
// nothing of it is left whatever ends the program. Throws InputError("", ...) when it cannot be made or written.
class Spool {
public:
    explicit Spool(const std::filesystem::path& beside);
    ~Spool();
    Spool(const Spool&) = delete;
    Spool& operator=(const Spool&) = delete;

    void append(std::string_view text);
    void append(const Spool& other);  // everything `other` holds
    std::size_t size() const { return size_; }
    // Everything appended so far, to a file descriptor (returns why it could not, or "") or a stream.
    std::string copy_to(int fd) const;
    void copy_to(std::ostream& out) const;

private:
    int fd_ = -1;
    std::size_t size_ = 0;
};

// A file written to its temporary name, waiting to be renamed into place; a long command may write it a piece at
// a time (append), so that what it writes is on disk, not in memory. An output written in place (a FIFO, a
// device) is spooled to an anonymous file until commit() writes it whole.
class StagedFile {
public:
    // Throws InputError(flag, "cannot write '<path>': <reason>"); no temporary is left behind.
    StagedFile(const std::filesystem::path& path, std::string_view flag);
    StagedFile(const std::filesystem::path& path, std::string_view contents, std::string_view flag);
    ~StagedFile();  // removes the temporary unless committed
    StagedFile(StagedFile&& other) noexcept;
    StagedFile(const StagedFile&) = delete;
    StagedFile& operator=(const StagedFile&) = delete;
    StagedFile& operator=(StagedFile&&) = delete;

    // Adds to the end; throws InputError like the constructor (the temporary is removed then).
    void append(std::string_view text);
    void append(const Spool& spool);
    std::size_t size() const { return size_; }  // bytes appended

    // Renames it over the target (or writes it in place); throws InputError like the constructor, or
    // WaitInterrupted when an interruption ends the wait for a FIFO's reader.
    void commit();

private:
    void finish();   // flushes and closes the temporary
    void discard();  // closes and removes the temporary

    std::filesystem::path path_;    // as the user named it, for messages
    std::filesystem::path target_;  // what is replaced or written
    OutputKind kind_ = OutputKind::replaced;
    std::string temporary_;  // replaced: the temporary's name until committed
    int fd_ = -1;            // the temporary (replaced) or the spool (in place), open until committed
    std::size_t size_ = 0;
    bool pending_ = false;
    std::string flag_;
};

// An interruption (Ctrl-C, SIGTERM held back by the program's policy) ended the wait for a FIFO's reader: the
// program says so and exits as interrupted (130, 143), not as if the path were wrong.
struct WaitInterrupted {
    std::string flag;
    std::string path;
};

// What the program does about interruptions while files are written. The formats layer knows no process
// signals: the program installs its own (cli/deferred_signals.hpp holds SIGINT and SIGTERM back and turns a
// reader's going away into an error instead of SIGPIPE); a library user without one gets none.
class WriteInterruptions {
public:
    virtual ~WriteInterruptions() = default;
    // Between hold() and its release(), staging and renaming a set of files is never cut short: an
    // interruption that arrives meanwhile takes effect once the files are whole and no temporary is left.
    // Holds nest.
    virtual void hold() = 0;
    virtual void release() = 0;
    // An interruption is waiting (held back): a wait for a FIFO's reader gives up.
    virtual bool pending() const = 0;
};

// The process's one policy (its signals are process-wide too); nullptr for none. Not owned.
void set_write_interruptions(WriteInterruptions* policy);

// Holds interruptions back, through the program's policy, while it lives. write_file_atomically holds them
// itself; a command that stages several files holds them around all of its stages and commits.
class HeldInterruptions {
public:
    HeldInterruptions();
    ~HeldInterruptions();
    HeldInterruptions(const HeldInterruptions&) = delete;
    HeldInterruptions& operator=(const HeldInterruptions&) = delete;

private:
    WriteInterruptions* policy_;
};

void write_file_atomically(const std::filesystem::path& path, std::string_view contents, std::string_view flag);

// Throws InputError(flag, ...) now if `path` could not be written later: it is a directory (or a socket or a
// block device), the folder it would be written in is missing, is not a folder or is not writable, or a FIFO
// or device is not writable. Lets a long run fail before it starts, not after.
void check_writable(const std::filesystem::path& path, std::string_view flag);

}  // namespace impulse::formats
