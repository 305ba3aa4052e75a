#include "formats/trace_docs.hpp"

#include "formats/words.hpp"

namespace impulse::formats {

namespace {

std::string_view kind_name(words::Kind kind) {
    switch (kind) {
        case words::Kind::integer:
            return "integer";
        case words::Kind::number:
            return "number";
        case words::Kind::boolean:
            return "boolean";
        case words::Kind::word:
            return "word";
        case words::Kind::vec2:
            return "vec2";
        case words::Kind::vec3:
            return "vec3";
        case words::Kind::mat3:
            return "mat3";
        case words::Kind::vec6:
            return "vec6";
        case words::Kind::mat6:
            return "mat6";
        case words::Kind::per_body_number:
            return "per body: number";
        case words::Kind::per_body_vec3:
            return "per body: vec3";
        case words::Kind::per_body_bool:
            return "per body: boolean";
        case words::Kind::bodies:
            return "[body, body]";
        case words::Kind::object:
            return "object";
        case words::Kind::list:
            return "array of objects";
        case words::Kind::none:
            return "";
    }
    return "";
}

// A table cell: a pipe would end the cell.
std::string cell(std::string_view text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string item_table(char item, std::string_view title) {
    std::string out = "### ";
    out += title;
    out += "\n\n| key | kind | unit | step | formula | equation | meaning |\n|---|---|---|---|---|---|---|\n";
    for (const words::Word& w : words::all()) {
        if (!words::held_by(w, item) || w.kind == words::Kind::none) continue;
        const bool derived = w.role == words::Role::computed;
        out += "| `" + cell(w.quantity) + "` | " + std::string(kind_name(w.kind)) + " | " + cell(w.unit) + " | " +
               (derived ? "`" + std::string(w.step) + "`" : cell(w.step)) + " | " + cell(w.formula) + " | " +
               cell(w.equation) + " | " + cell(w.meaning) + " |\n";
    }
    return out;
}

}  // namespace

std::string trace_word_docs() {
    std::string out(trace_docs_begin);
    out += "\n\n";
    out +=
        "Each key below is a word of the vocabulary: the inspector's row, a lesson's `value`, a worksheet's cell. "
        "A nested key is written with its path (`rewind.time` is `time` inside `rewind`; `updates[].after` is "
        "`after` in each element of `updates`). The step is the derivation step that computes the value and the "
        "table that shows it; for a given value, what it comes from (`contact`, `choice`, `settings`).\n\n";
    out += item_table('C', "Contact (steps 1–5)") + "\n";
    out += item_table('P', "Position iteration (step 8)") + "\n";
    out += item_table('V', "Velocity iteration (steps 4–7)") + "\n";
    out +=
        "### Renamed from format 1\n\nA trace of format 1 still opens: the reader moves these keys and says so "
        "in one line.\n\n| format 1 | format 2 | items |\n|---|---|---|\n";
    for (const words::Word& w : words::all())
        if (!w.format1.empty())
            out += "| `" + std::string(w.format1) + "` | `" + std::string(w.quantity) + "` | " + std::string(w.items) +
                   (w.quantity == "push_impulse" ? " (split impulse only)" : "") + " |\n";
    out += "\nSteps renamed (a lesson's `step=` still accepts the old name, with a note): ";
    bool first = true;
    for (const words::StepRename& r : words::step_renames()) {
        out += std::string(first ? "" : ", ") + "`" + std::string(r.old_name) + "` → `" + std::string(r.new_name) + "`";
        first = false;
    }
    out += ".\n\n";
    out += trace_docs_end;
    return out;
}

std::string with_trace_word_docs(const std::string& document, const std::string& section) {
    const std::size_t begin = document.find(trace_docs_begin);
    const std::size_t end = document.find(trace_docs_end);
    if (begin == std::string::npos || end == std::string::npos || end < begin) return document;
    return document.substr(0, begin) + section + document.substr(end + trace_docs_end.size());
}

}  // namespace impulse::formats
