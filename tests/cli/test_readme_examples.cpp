// The README's examples run as written: its shell lines that call the program, the --script block (on the ruler,
// as `inspect --script` runs it), the table it quotes from `resolve --explain`, the goto by a quantity's last part
// it mentions, and the "Example:" line of each command's help but diff's and bench's (they need a class of
// students and minutes of benchmarks; their own tests cover them). Each runs in a fresh folder that links the
// checkout's scenes/ and lessons/, without a display or a terminal, as a shell would run it.

#include "support/program.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <sys/wait.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace impulse::test {

namespace {

using impulse::test::program;

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

struct Shell {
    int code;
    std::string out, err;
};

// Runs `command` with bash in `dir`, `impulse-lab` standing for the program just built.
Shell run_in(const TempDir& dir, std::string command) {
    command = std::regex_replace(command, std::regex("(^|[ |;&(])(build/default/bin/)?impulse-lab\\b"), "$1" + program);
    const std::filesystem::path script =
        dir.write("example.sh", "cd '" + dir.file("").string() +
                                    "' && unset DISPLAY WAYLAND_DISPLAY && export ASAN_OPTIONS=detect_leaks=0 && " +
                                    "{ " + command + "\n} < /dev/null > out.txt 2> err.txt\n");
    const int status = std::system(("bash '" + script.string() + "'").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(dir.file("out.txt")), read(dir.file("err.txt"))};
}

// A folder to run examples in: the checkout's scenes/ and lessons/ linked in.
struct ExampleFolder : TempDir {
    ExampleFolder() {
        std::filesystem::create_directory_symlink(IMPULSE_SOURCE_DIR "/scenes", file("scenes"));
        std::filesystem::create_directory_symlink(IMPULSE_SOURCE_DIR "/lessons", file("lessons"));
    }
};

// The fenced blocks of the README: their info string ("sh", or "") and text, with the line before each.
struct Block {
    std::string info, text, before;
};
std::vector<Block> fenced_blocks(const std::string& markdown) {
    std::vector<Block> blocks;
    std::istringstream in(markdown);
    std::string line, previous;
    std::optional<Block> open;
    while (std::getline(in, line)) {
        if (line.starts_with("```")) {
            if (open) {
                blocks.push_back(*open);
                open.reset();
            } else {
                open = Block{line.substr(3), {}, previous};
            }
        } else if (open) {
            open->text += line + "\n";
        }
        previous = line;
    }
    return blocks;
}

const std::string readme = read(IMPULSE_SOURCE_DIR "/README.md");

}  // namespace

TEST_CASE("the README's shell lines that call the program run as written") {
    int ran = 0;
    for (const Block& b : fenced_blocks(readme)) {
        if (b.info != "sh") continue;
        std::istringstream lines(b.text);
        for (std::string line; std::getline(lines, line);) {
            // The quick start's last command: the first lesson, which prints itself with its pictures here.
            if (line.starts_with("scripts/install-deps")) {
                const std::size_t last = line.rfind("&& ");
                if (line.find("impulse-lab", last) == std::string::npos) continue;
                line = line.substr(last + 3);
            }
            if (line.find("impulse-lab") == std::string::npos || line.starts_with("cmake")) continue;
            INFO(line);
            ExampleFolder dir;
            const Shell r = run_in(dir, line);
            CHECK(r.code == 0);
            const bool quiet =
                r.err.find("impulse-lab:") == std::string::npos || r.err.find("note:") != std::string::npos;
            CHECK_MESSAGE(quiet, r.err);
            ++ran;
        }
    }
    CHECK(ran >= 2);
}

TEST_CASE("the README's --script block runs on the ruler and writes what it names") {
    const auto blocks = fenced_blocks(readme);
    const auto script = std::find_if(blocks.begin(), blocks.end(), [](const Block& b) {
        return b.text.find("goto phase=position") != std::string::npos;
    });
    REQUIRE(script != blocks.end());
    ExampleFolder dir;
    dir.write("steps.txt", script->text);
    const Shell r = run_in(dir, "impulse-lab inspect scenes/cases/ruler.json --headless --script steps.txt");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(std::filesystem::file_size(dir.file("desired.png")) > 1000);
    CHECK(read(dir.file("angular.csv")).find("position_change.angular_change[0]") != std::string::npos);
}

TEST_CASE("the table the README quotes is what resolve --explain prints for the ruler") {
    const auto blocks = fenced_blocks(readme);
    const auto quoted = std::find_if(blocks.begin(), blocks.end(), [](const Block& b) {
        return b.text.starts_with("delta_velocity_per_unit_impulse — ");
    });
    REQUIRE(quoted != blocks.end());
    const std::smatch command = [&] {
        std::smatch m;
        std::regex_search(quoted->before, m, std::regex("`(impulse-lab [^`]*)`"));
        return m;
    }();
    REQUIRE(command.size() == 2);
    ExampleFolder dir;
    const Shell r = run_in(dir, command[1].str());
    CHECK(r.code == 0);
    CHECK(r.out.find(quoted->text) != std::string::npos);
}

TEST_CASE("the goto by a quantity's last part the README mentions, and each command's help example, run") {
    ExampleFolder dir;
    CHECK(readme.find("e.g. `step=angular_change`") != std::string::npos);
    CHECK(run_in(dir,
                 "impulse-lab inspect scenes/cases/ruler.json --headless --goto step=angular_change "
                 "--screenshot angular.png")
              .code == 0);
    const Shell help = run_in(dir, "impulse-lab help");
    const std::regex example("Example: (impulse-lab [^\\n]*)");
    int ran = 0;
    for (auto m = std::sregex_iterator(help.out.begin(), help.out.end(), example); m != std::sregex_iterator(); ++m) {
        const std::string line = (*m)[1].str();
        if (line.starts_with("impulse-lab diff") || line.starts_with("impulse-lab bench")) continue;
        INFO(line);
        ExampleFolder fresh;
        const Shell r = run_in(fresh, line);
        CHECK(r.code == 0);
        ++ran;
    }
    CHECK(ran >= 5);
}

}  // namespace impulse::test
