#include "formats/words.hpp"

#include "formats/word_table.hpp"

#include <algorithm>
#include <array>

namespace impulse::formats::words {

namespace {

using detail::table;

constexpr std::array renamed_steps{
    StepRename{"velocity_per_unit_impulse", step::delta_velocity_per_unit_impulse},
    StepRename{"accumulated_impulse", step::accumulated},
};

}  // namespace

std::span<const StepRename> step_renames() {
    return renamed_steps;
}

std::span<const Word> all() {
    return table;
}

const Word* find(std::string_view quantity) {
    const auto found = std::find_if(table.begin(), table.end(), [&](const Word& w) { return w.quantity == quantity; });
    return found == table.end() ? nullptr : &*found;
}

const Word* find(std::string_view quantity, char item) {
    for (const Word& w : table)
        if (w.quantity == quantity && held_by(w, item)) return &w;
    return nullptr;
}

bool is_per_body(Kind kind) {
    return kind == Kind::per_body_number || kind == Kind::per_body_vec3 || kind == Kind::per_body_bool;
}

}  // namespace impulse::formats::words
