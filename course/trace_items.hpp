#pragma once
// The items of a trace document a worksheet is made of (a prepared contact, an iteration of a phase) and the
// entries their keys make: shared by the worksheet's cells, its inputs and the wording of a path.

#include "course/step_keys.hpp"
#include "course/worksheet_entry.hpp"
#include "model/navigator.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace impulse::course {

// The item a cursor stands on, in the trace document.
struct ItemAt {
    ItemKind kind;
    std::string path;  // frames[f].contacts[k] or frames[f].phases[p].iterations[i]
    const formats::json* object;
    std::string frame_path;  // frames[f]
    const formats::json* frame;
    std::size_t phase = 0;  // an iteration's phase index p
};

ItemAt item_at(const formats::json& document, const model::Cursor& c);

WorksheetEntry make_entry(std::string path, std::string step, std::string quantity, const Described& d,
                          formats::json value);

// The entries `key` makes in `object` (at `path`, named `quantity` so far): one per value present, one per body
// present for a per-body key, one per element of an array of objects ("updates[].after").
void expand(const formats::json& object, const std::string& path, const std::string& quantity, std::string_view key,
            bool per_body, const Described& d, const std::string& step, std::vector<WorksheetEntry>& out);

void expand_key(const ItemAt& item, const StepKey& key, const std::string& step, std::vector<WorksheetEntry>& out);

// The index in the frame's recorded contacts of the contact numbered `contact`, or -1 when it was not recorded.
long recorded_contact_index(const formats::json& frame, const formats::json& contact);

// What the item's step `order[here]` starts from (docs/coursework.md, "Cells and inputs"). `resolved`: the
// trace resolved a case once (its bodies carry the scene's last_frame_acceleration), else it simulated frames
// (every movable body was accelerated by gravity just before the frame's resolution).
std::vector<WorksheetEntry> inputs_of(const ItemAt& item, const std::vector<std::string>& order, std::size_t here,
                                      const formats::json& document, bool resolved);

}  // namespace impulse::course
