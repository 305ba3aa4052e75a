#include "course/trace_path.hpp"

#include "formats/trace_items_json.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace impulse::course {

using json = nlohmann::ordered_json;

const json* follow(const json& item, std::string_view path, std::string& problem) {
    const json* at = &item;
    std::size_t i = 0;
    while (i < path.size()) {
        if (path[i] == '[') {
            const std::size_t close = path.find(']', i);
            std::size_t index = 0;
            const auto [end, error] = close == std::string_view::npos
                                          ? std::from_chars(path.data(), path.data(), index)
                                          : std::from_chars(path.data() + i + 1, path.data() + close, index);
            if (close == std::string_view::npos || error != std::errc() || end != path.data() + close) {
                problem = "\"" + std::string(path) + "\" is not a path like impulse_world[1]";
                return nullptr;
            }
            if (!at->is_array() || index >= at->size()) {
                problem = "\"" + std::string(path.substr(0, close + 1)) + "\" is outside the value it indexes";
                return nullptr;
            }
            at = &(*at)[index];
            i = close + 1;
        } else {
            if (path[i] == '.') ++i;
            const std::size_t end = std::min(path.find_first_of(".[", i), path.size());
            const std::string key(path.substr(i, end - i));
            if (!at->is_object() || !at->contains(key)) {
                std::string keys;
                if (at->is_object())
                    for (const auto& [k, v] : at->items()) keys += (keys.empty() ? "" : ", ") + k;
                problem = "no \"" + key + "\" here" + (keys.empty() ? std::string() : " (keys: " + keys + ")");
                return nullptr;
            }
            at = &(*at)[key];
            i = end;
        }
    }
    return at;
}

json item_json(const Trace& trace, const model::Cursor& c) {
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(c.frame)];
    const auto i = static_cast<std::size_t>(c.item);
    switch (c.stage) {
        case model::Stage::preparation:
            return formats::item_json(frame.contacts[i]);
        case model::Stage::position:
            return formats::item_json(frame.position.iterations[i]);
        case model::Stage::velocity:
            return formats::item_json(frame.velocity.iterations[i]);
    }
    throw std::logic_error("a cursor in no stage");
}

}  // namespace impulse::course
