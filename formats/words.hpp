#pragma once
// The word list: every value a trace records, described once. A word's name is its key path inside the item
// that holds it ("desired_delta_velocity", "rewind.time", "updates[].after"), and the same word is the
// inspector's row, the lesson's `value` and the worksheet's cell; a step's name is a word too (the value it
// exists to compute, or the object holding what it computes). The trace writer and reader, the schema test,
// the inspector's tables and annotations, the worksheets and docs/trace-format.md all read this table.
// Pure data: no files, no JSON. It is the trace's vocabulary, so it lives in formats/: the engine's records are
// plain structs that never read it.

#include <span>
#include <string_view>

namespace impulse::formats::words {

// The step names, each a word of the table below (or, for `choice`, `contact`, `body` and `settings`, what a
// given value comes from). Code names a step through these constants, never through a string literal.
namespace step {
inline constexpr std::string_view choice = "choice";                        // which contact an iteration takes, and why
inline constexpr std::string_view basis = "basis";                          // step 1
inline constexpr std::string_view relative_position = "relative_position";  // step 2
inline constexpr std::string_view delta_velocity_per_unit_impulse = "delta_velocity_per_unit_impulse";  // 3
inline constexpr std::string_view contact_velocity = "contact_velocity";                                // 4
inline constexpr std::string_view desired_delta_velocity = "desired_delta_velocity";                    // 5
inline constexpr std::string_view accumulated = "accumulated";          // the accumulating solvers' running total
inline constexpr std::string_view impulse = "impulse";                  // step 6
inline constexpr std::string_view velocity_change = "velocity_change";  // step 7
inline constexpr std::string_view rewind = "rewind";                    // step 8, velocity-based
inline constexpr std::string_view penetration_inertia = "penetration_inertia";  // step 8
inline constexpr std::string_view move_split = "move_split";                    // step 8
inline constexpr std::string_view position_change = "position_change";          // step 8
inline constexpr std::string_view updates = "updates";                          // the other contacts' bookkeeping
// AVBD's (record/avbd_records.hpp): a contact's rows, a body's block and move, a contact's dual update.
inline constexpr std::string_view constraint = "constraint";
inline constexpr std::string_view force = "force";
inline constexpr std::string_view block_matrix = "block_matrix";
inline constexpr std::string_view block_force = "block_force";
inline constexpr std::string_view dual_update = "dual_update";
// Where a given value comes from (not steps a table shows).
inline constexpr std::string_view contact = "contact";    // collision detection or the case file
inline constexpr std::string_view body = "body";          // a body's state or mass
inline constexpr std::string_view settings = "settings";  // a setting in force
}  // namespace step

// Format 1's step names that format 2 renamed: a lesson written for format 1 still opens.
struct StepRename {
    std::string_view old_name;
    std::string_view new_name;
};
std::span<const StepRename> step_renames();

// The JSON kind of a stored word (what the schema says of its key).
enum class Kind {
    integer,
    number,
    boolean,
    word,  // a string from a fixed list
    vec2,
    vec3,
    mat3,
    vec6,  // AVBD's six coordinates of a body: (linear; angular)
    mat6,
    per_body_number,  // [body0, body1], null for the world or where it does not apply
    per_body_vec3,
    per_body_bool,
    bodies,  // [body0, body1] indices, null = the world
    object,  // an object whose keys are words of their own ("rewind": "rewind.time", ...)
    list,    // an array of objects whose keys are words of their own ("updates[].after")
    none,    // not stored under this name: shown by the inspector, kept elsewhere (see `stored_at`)
};

// What a word is to the derivation.
enum class Role {
    given,     // what the item starts from (the contact as detected, the iteration's choice)
    setting,   // a setting in force, first used by `step`
    computed,  // a value `step` computes
    context,   // recorded for another purpose (why a contact exists)
};

struct Word {
    std::string_view quantity;  // the name: key path in its item, row of the inspector, lesson value
    std::string_view formula;
    std::string_view equation;  // "(14.2)" from the chapter, "ch. 15" for the reference engine's additions
    std::string_view unit;
    std::string_view meaning;
    // The step that computes it (its table in the inspector, its worksheet section), or what it is given by:
    // step::contact, step::body, step::settings, step::choice.
    std::string_view step = {};
    std::string_view inputs = {};  // the words it is computed from, separated by spaces
    // The items that hold it: C a prepared contact, P a position iteration, V a velocity iteration, F the
    // frame. A word of kind `none` is shown for those items but stored elsewhere (`stored_at`).
    std::string_view items = {};
    Kind kind = Kind::none;
    Role role = Role::computed;
    std::string_view stored_at = {};  // a word kept elsewhere: "basis" (its column 1), "bodies_before[].position"
    std::string_view format1 = {};    // its key in trace format 1, when that was another
};

// Every word, in the order of the derivation.
std::span<const Word> all();

// The word named `quantity` (the first, when items of different kinds hold different words of one name), or null.
const Word* find(std::string_view quantity);

// The word named `quantity` held by items of kind `item` ('C', 'P', 'V', 'F'), or null.
const Word* find(std::string_view quantity, char item);

// Whether `item` ('C', 'P', 'V', 'F') holds `word`.
constexpr bool held_by(const Word& word, char item) {
    return word.items.find(item) != std::string_view::npos;
}

bool is_per_body(Kind kind);

}  // namespace impulse::formats::words
