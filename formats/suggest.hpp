#pragma once
// "Did you mean ...?" for misspelt names: the closest candidate within a small edit distance.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::formats {

// Levenshtein distance, counting a case difference as no difference.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is at most 2 edits away (ties: the first), else nothing.
std::optional<std::string> closest_name(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace impulse::formats
