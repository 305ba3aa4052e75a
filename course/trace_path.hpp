#pragma once
// Reading a value out of a trace's JSON by the path a lesson's question gives: "impulse_world[1]",
// "rewind.time", "updates[0].after[0]", inside the item a cursor stands on (a prepared contact or an iteration).

#include "model/navigator.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace impulse::course {

// The trace JSON of the item a cursor stands on, as frames[f].contacts[k] or frames[f].phases[p].iterations[i]
// holds it (written for that item alone).
nlohmann::ordered_json item_json(const Trace& trace, const model::Cursor& c);

// Follows "key.key[i][j]" inside `item`; null when a part is missing, and `problem` says which.
const nlohmann::ordered_json* follow(const nlohmann::ordered_json& item, std::string_view path, std::string& problem);

}  // namespace impulse::course
