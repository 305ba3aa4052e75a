// Where the program finds its lessons and scenes (cli/data_folder.hpp): beside its own folder, which for these
// tests, run from build/<preset>/bin, is the build folder's share/impulse-lab linking to the checkout; or the
// folder IMPULSE_LAB_DATA_DIR names. (That an installed tree finds its own, from another working directory, is
// the install test's: tests/install/install_test.cmake.)

#include "cli/data_folder.hpp"
#include "formats/input_error.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>

namespace impulse::test {

namespace {

namespace fs = std::filesystem;

// Sets the variable for one test and removes it after, whatever the test does.
struct DataFolderVariable {
    explicit DataFolderVariable(const fs::path& folder) { ::setenv(cli::data_folder_variable, folder.c_str(), 1); }
    ~DataFolderVariable() { ::unsetenv(cli::data_folder_variable); }
};

}  // namespace

TEST_CASE("a program in a build folder finds the lessons and scenes of the checkout it was built from") {
    ::unsetenv(cli::data_folder_variable);
    TempDir dir;
    ::setenv("XDG_CONFIG_HOME", dir.file("cfg").c_str(), 1);
    CHECK(cli::shipped_lessons_folder() == fs::canonical(IMPULSE_SOURCE_DIR "/lessons"));
    CHECK(cli::shipped_scenes_folder() == fs::canonical(IMPULSE_SOURCE_DIR "/scenes"));

    const CliResult r = run_cli({"lesson"});
    CHECK(r.code == 0);
    CHECK(r.out.starts_with("Lessons in " + fs::canonical(IMPULSE_SOURCE_DIR "/lessons").string()));
    CHECK(r.out.find("  13  Friction against the slip") != std::string::npos);
    ::unsetenv("XDG_CONFIG_HOME");
}

TEST_CASE("IMPULSE_LAB_DATA_DIR names another data folder, and the lessons listed are its own") {
    TempDir dir;
    const fs::path data = dir.file("data");
    fs::create_directories(data / "lessons");
    fs::create_directories(data / "scenes" / "cases");
    fs::copy_file(IMPULSE_SOURCE_DIR "/scenes/cases/sphere_ground.json", data / "scenes/cases/sphere_ground.json");
    fs::copy_file(IMPULSE_SOURCE_DIR "/lessons/01-impulse-is-a-velocity-change.md",
                  data / "lessons/01-impulse-is-a-velocity-change.md");
    ::setenv("XDG_CONFIG_HOME", dir.file("cfg").c_str(), 1);
    DataFolderVariable variable(data);

    CHECK(cli::shipped_lessons_folder() == fs::canonical(data / "lessons"));
    const CliResult r = run_cli({"lesson"});
    CHECK(r.code == 0);
    CHECK(r.out.starts_with("Lessons in " + fs::canonical(data / "lessons").string()));
    CHECK(r.out.find("   1  An impulse is an instant change of velocity") != std::string::npos);
    CHECK(r.out.find("   2  ") == std::string::npos);
    ::unsetenv("XDG_CONFIG_HOME");
}

TEST_CASE("IMPULSE_LAB_DATA_DIR naming a folder without lessons and scenes is one error naming the variable") {
    TempDir dir;
    fs::create_directories(dir.file("empty"));
    DataFolderVariable variable(dir.file("empty"));

    CHECK_THROWS_AS(cli::data_folder(), formats::InputError);
    const CliResult r = run_cli({"lesson"});
    CHECK(r.code == 2);
    CHECK(r.err == "impulse-lab: IMPULSE_LAB_DATA_DIR: '" + dir.file("empty").string() +
                       "' holds no lessons/ and scenes/ folders (it should name the data folder, e.g. "
                       "/usr/share/impulse-lab)\n");
    CHECK(r.out.empty());
}

}  // namespace impulse::test
