#pragma once
// Where the program finds what it ships with: the lessons, the scenes and cases, the schemas and the docs. One
// lookup, so the installed program and the one in a build folder find their files the same way, from any working
// directory, and nothing is compiled in as a path of the checkout it was built from.

#include <filesystem>
#include <string>
#include <string_view>

namespace impulse::cli {

// The environment variable that names the data folder instead (a folder holding lessons/ and scenes/).
inline constexpr const char* data_folder_variable = "IMPULSE_LAB_DATA_DIR";

// The data folder: $IMPULSE_LAB_DATA_DIR when it is set, else share/impulse-lab beside the program's own folder
// (PREFIX/bin/../share/impulse-lab), which is where `cmake --install` puts it. A build folder has the same layout
// (build/<preset>/share/impulse-lab links to the source tree's folders, made when it is configured), so a program
// run from it finds the checkout's files. Throws formats::InputError naming where it looked when neither holds
// lessons/ and scenes/.
std::filesystem::path data_folder();

// data_folder()'s lessons/ and scenes/, with links resolved: what the user is shown is where the files are.
std::filesystem::path shipped_lessons_folder();
std::filesystem::path shipped_scenes_folder();

// What a command that takes a lesson file (`worksheet`, `diff`'s reference) reads for `argument`: a whole number
// from 1 to 99 that names no file is the shipped lesson of that number (`worksheet 7`), anything else the file
// itself. Throws formats::InputError(`where`, ...) for a number no lesson has.
std::string lesson_or_file(const std::string& argument, std::string_view where);

}  // namespace impulse::cli
