#pragma once
// Standard input taken from a file for the life of the object, so a test can run a command given "-" in-process.

#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace impulse::test {

class StandardInputFrom {
public:
    explicit StandardInputFrom(const std::filesystem::path& file) : saved_(::dup(STDIN_FILENO)) {
        const int fd = ::open(file.c_str(), O_RDONLY);
        if (saved_ < 0 || fd < 0 || ::dup2(fd, STDIN_FILENO) < 0) throw std::runtime_error("cannot redirect stdin");
        ::close(fd);
    }
    ~StandardInputFrom() {
        ::dup2(saved_, STDIN_FILENO);
        ::close(saved_);
    }
    StandardInputFrom(const StandardInputFrom&) = delete;
    StandardInputFrom& operator=(const StandardInputFrom&) = delete;

private:
    int saved_;
};

}  // namespace impulse::test
