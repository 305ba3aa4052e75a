#pragma once
// Which derivation step computes which key of a trace's item objects, read from the word list
// (formats/words.hpp): the one table behind worksheets
// (a step's cells are the keys it computes, its inputs the keys of the steps before it) and behind the
// equation `diff` names beside a mismatch. An item is a prepared contact (frames[f].contacts[k]) or one
// iteration of a phase (frames[f].phases[p].iterations[i]); the step names are those of the inspector's
// tables (model::step_tables). Every key the trace writes into an item appears here once, which a test
// checks over the shipped cases run with every method.

#include "course/json_path.hpp"
#include "formats/words.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::course {

enum class ItemKind {
    contact,             // frames[f].contacts[k]: steps 1-5, as prepared
    position_iteration,  // an iteration of the position phase: the choice, then step 8
    velocity_iteration,  // an iteration of the velocity phase: the choice, then steps 4-7
};

enum class Role {
    given,     // what the item starts from (the contact as detected, the iteration's choice): every step's input
    setting,   // a setting in force (or a given) first used by `step`: an input of that step and those after it
    computed,  // a value `step` computes: a cell of that step, an input of the steps after it
    context,   // recorded for another purpose (why the contact exists): neither cell nor input
};

struct StepKey {
    ItemKind item;
    std::string_view key;  // inside the item object: "basis", "friction_solve.static_impulse", "updates[].after"
    Role role;
    std::string_view step;             // the step table that shows it; empty for given and context keys
    bool per_body;                     // a [body0, body1] array: one cell per body present (null = the world)
    const formats::words::Word* word;  // its word (formats/words.hpp): formula, equation, unit, meaning
};

std::span<const StepKey> step_keys();

// The entry for `key` (in the form of StepKey::key: nested keys joined by '.', "[]" after an array of
// objects) of an item of `item`'s kind, or null.
const StepKey* find_step_key(ItemKind item, std::string_view key);

// The key, in that form, of the value at `path` inside an item whose own path ends before `from`
// ("updates", 2, "after", 0 -> "updates[].after"; a body's or a component's index is dropped).
std::string step_key_of(const std::vector<PathToken>& path, std::size_t from);

// Values outside the item an iteration or contact needs, given as inputs: the bodies' state before the
// frame's resolution and their mass properties, and for an iteration the chosen contact as prepared.
struct OutsideKey {
    std::string_view where;  // "bodies_before" (frames[f].bodies_before[b]), "scene_bodies" (scene.bodies[b]) or
                             // "contact" (frames[f].contacts[k], the chosen contact's preparation)
    std::string_view key;
    bool for_contact;             // an input of a prepared contact's steps
    bool for_position_iteration;  // ... of a position iteration's steps
    bool for_velocity_iteration;  // ... of a velocity iteration's steps
    std::string_view unit = {};
    std::string_view formula = {};
    std::string_view meaning = {};
};

std::span<const OutsideKey> outside_keys();

// What a key means, for a worksheet's entry or a mismatch.
struct Described {
    std::string quantity;  // the vocabulary name (or the key)
    std::string unit;
    std::string formula;
    std::string equation;
    std::string meaning;
};

Described describe_key(const StepKey& key);
Described describe_outside(const OutsideKey& key);

// The meaning of any path into a trace document: the item's entry when the path is inside an item, else the
// last key of the path that is a vocabulary name; empty fields when neither applies (settings, the scene).
Described describe_path(const formats::json& trace_document, const std::vector<PathToken>& path);

}  // namespace impulse::course
