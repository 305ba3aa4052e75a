#include "cli/data_folder.hpp"

#include "course/lesson.hpp"
#include "formats/input_error.hpp"

#include <charconv>
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

std::string lesson_or_file(const std::string& argument, std::string_view where) {
    int number = 0;
    const auto [end, error] = std::from_chars(argument.data(), argument.data() + argument.size(), number);
    std::error_code exists;
    if (error != std::errc() || end != argument.data() + argument.size() || number < 1 || number > 99 ||
        fs::exists(argument, exists))
        return argument;
    const fs::path folder = shipped_lessons_folder();
    for (const fs::path& file : course::lesson_files(folder))
        if (std::atoi(file.filename().string().c_str()) == number) return file.string();
    throw formats::InputError(std::string(where), "there is no lesson " + argument + " in " + folder.string() +
                                                      " (impulse-lab lesson lists them)");
}

}  // namespace impulse::cli
