#pragma once
// Every output file is written atomically: the text goes to a temporary file beside the target, is flushed
// to disk, and is renamed over the target. A reader (or a crash, or Ctrl-C) sees the old file or the whole
// new one, never half of it.

#include <filesystem>
#include <string_view>

namespace impulse::io {

// Throws InputError(flag, "cannot write '<path>': <reason>") if the file cannot be written; no temporary
// file is left behind.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents, std::string_view flag);

}  // namespace impulse::io
