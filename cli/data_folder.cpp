#include "cli/data_folder.hpp"

#include "formats/input_error.hpp"

#include <cstdlib>
#include <string>
#include <system_error>

namespace impulse::cli {

namespace {

namespace fs = std::filesystem;

bool holds_data(const fs::path& folder) {
    std::error_code error;
    return fs::is_directory(folder / "lessons", error) && fs::is_directory(folder / "scenes", error);
}

// The program's own file, as the kernel knows it: independent of the working directory and of how it was started
// (a PATH lookup, a relative path, a symlink to it).
fs::path own_executable() {
    std::error_code error;
    fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (error)
        throw formats::InputError("data folder", "cannot find the program's own location (/proc/self/exe: " +
                                                     error.message() + "); set " + data_folder_variable);
    return exe;
}

fs::path resolved(const fs::path& folder) {
    std::error_code error;
    const fs::path canonical = fs::canonical(folder, error);
    return error ? folder.lexically_normal() : canonical;
}

}  // namespace

fs::path data_folder() {
    if (const char* named = std::getenv(data_folder_variable); named && *named) {
        const fs::path folder(named);
        if (!holds_data(folder))
            throw formats::InputError(data_folder_variable,
                                      "'" + folder.string() +
                                          "' holds no lessons/ and scenes/ folders (it should name "
                                          "the data folder, e.g. /usr/share/impulse-lab)");
        return folder;
    }
    const fs::path beside = own_executable().parent_path().parent_path() / "share" / "impulse-lab";
    if (!holds_data(beside))
        throw formats::InputError("data folder",
                                  "no lessons/ and scenes/ in " + beside.lexically_normal().string() +
                                      " (where an installed impulse-lab keeps them); reinstall, or set " +
                                      data_folder_variable + " to the folder that holds them");
    return beside;
}

fs::path shipped_lessons_folder() {
    return resolved(data_folder() / "lessons");
}

fs::path shipped_scenes_folder() {
    return resolved(data_folder() / "scenes");
}

}  // namespace impulse::cli
