// Reading JSON text into a document, strictly and in bounded time and memory: nlohmann's SAX parser drives a
// builder of our own. nlohmann's callback parser (which we used before) scans the parent's elements for a
// discarded value after every object ends, so an array of n objects took time n² (240k bodies: 11 s); and its
// ordered objects look a key up by a linear search on every insert. Here a value is appended where it goes,
// a key is checked against the keys before it (a hash set once an object is large), and the memory the document
// takes is estimated as it grows, so a file written to take the most memory per character is refused at a
// fixed cost (formats/input_limits.hpp) rather than when the machine runs out.

#include "formats/input_error.hpp"
#include "formats/input_limits.hpp"
#include "formats/json_text.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_set>
#include <vector>

namespace impulse::formats {

namespace {

using json = nlohmann::ordered_json;

// An object's keys are compared one by one while it is small; past this many a hash set keeps them.
constexpr std::size_t hashed_keys_from = 16;

// Estimated bytes a value takes (libstdc++ on 64 bits, 16 bytes of malloc overhead per block). A value is a
// 16-byte slot in its array, or with its key a 48-byte member of its object; both sit in a vector that grows by
// doubling, so up to twice that is held (and briefly more while it moves), which is charged as twice. A string
// is a heap std::string (32 bytes) and its characters past the 15 kept inline; an object or array a heap vector
// (24 bytes); a large object's keys are also in a hash set (about 64 bytes and the key each).
constexpr std::size_t block_overhead = 16;
constexpr std::size_t element_bytes = 2 * 16;
constexpr std::size_t member_bytes = 2 * 48;
constexpr std::size_t string_bytes = 32 + block_overhead;
constexpr std::size_t container_bytes = 24 + block_overhead;
constexpr std::size_t hashed_key_bytes = 64;

std::size_t text_bytes(std::size_t length) {
    return length > 15 ? length + 1 + block_overhead : 0;
}

// One open array or object.
struct Level {
    json* value;  // the container being filled
    bool is_array;
    std::string key;                         // objects: the key whose value is read next
    std::unordered_set<std::string> hashed;  // objects with many keys: the keys so far
};

class DocumentBuilder {
public:
    explicit DocumentBuilder(json& root, std::size_t memory_limit) : root_(root), limit_(memory_limit) {}

    bool null() { return add(json(nullptr), 0); }
    bool boolean(bool v) { return add(json(v), 0); }
    bool number_integer(json::number_integer_t v) { return add(json(v), 0); }
    bool number_unsigned(json::number_unsigned_t v) { return add(json(v), 0); }
    bool number_float(json::number_float_t v, const std::string&) { return add(json(v), 0); }
    bool string(std::string& v) {
        const std::size_t extra = string_bytes + text_bytes(v.size());
        return add(json(std::move(v)), extra);
    }
    bool binary(json::binary_t&) { return true; }  // not produced by JSON text

    bool start_object(std::size_t) { return open(false); }
    bool start_array(std::size_t) { return open(true); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(std::string& k) {
        Level& level = levels_.back();
        json::object_t& members = *level.value->get_ptr<json::object_t*>();
        if (duplicate(level, members, k)) {
            level.key = k;
            throw InputError(path(true), "key given twice in the same object");
        }
        const std::size_t bytes = member_bytes + text_bytes(k.size()) * (level.hashed.empty() ? 1 : 2) +
                                  (level.hashed.empty() ? 0 : hashed_key_bytes);
        level.key = std::move(k);  // first: a refusal names the key being read ("bodies[9].name", not "bodies[9].")
        charge(bytes);
        return true;
    }

    template <class Exception>
    bool parse_error(std::size_t position, const std::string&, const Exception& e) {
        error_position_ = position;
        error_ = e.what();
        overflow_ = e.id == 406;  // out_of_range 406: a number too large for a double
        return false;
    }

    std::size_t error_position() const { return error_position_; }
    const std::string& error() const { return error_; }
    bool number_overflow() const { return overflow_; }
    // The path of the value being read (after a key: that key's value; in an array: its next element).
    std::string path(bool pending) const {
        std::string text;
        for (std::size_t i = 0; i < levels_.size(); ++i) {
            const Level& level = levels_[i];
            const bool last = i + 1 == levels_.size();
            if (last && !pending) break;
            // An array's element being read is its last one, or, innermost, the one to come.
            const std::size_t index = level.value->size() - (last ? 0 : 1);
            text = level.is_array ? json_path_index(text, index) : json_path_child(text, level.key);
        }
        return text;
    }

private:
    // Whether `k` is already a key of the object; a large object's keys go into its hash set.
    bool duplicate(Level& level, const json::object_t& members, const std::string& k) {
        if (members.size() < hashed_keys_from)
            return std::any_of(members.begin(), members.end(), [&k](const auto& m) { return m.first == k; });
        if (level.hashed.empty()) {
            for (const auto& m : members) level.hashed.insert(m.first);
            charge(members.size() * hashed_key_bytes);
        }
        return !level.hashed.insert(k).second;
    }

    void charge(std::size_t bytes) {
        used_ += bytes;
        if (used_ > limit_)
            throw InputError(path(true), "holds more than one document may: reading it would take over " +
                                             std::to_string(limit_ >> 20) + " MiB of memory");
    }

    // Puts `v` where the parser is: the root, the next element of an array, or the value of the last key.
    json* place(json&& v) {
        if (levels_.empty()) {
            root_ = std::move(v);
            return &root_;
        }
        Level& level = levels_.back();
        if (level.is_array) {
            json::array_t& elements = *level.value->get_ptr<json::array_t*>();
            elements.push_back(std::move(v));
            return &elements.back();
        }
        // The vector beneath the ordered map: the key was checked already, so no search.
        json::object_t& members = *level.value->get_ptr<json::object_t*>();
        members.std::vector<std::pair<const std::string, json>>::emplace_back(level.key, std::move(v));
        return &members.back().second;
    }

    // A value's own bytes; its slot is charged with its array's element or its object's member (key()).
    bool add(json&& v, std::size_t bytes) {
        if (!levels_.empty() && levels_.back().is_array) bytes += element_bytes;
        charge(bytes);
        place(std::move(v));
        return true;
    }

    bool open(bool is_array) {
        if (static_cast<int>(levels_.size()) >= max_json_depth)
            throw InputError(path(true), "nested too deeply (more than " + std::to_string(max_json_depth) + " levels)");
        charge(container_bytes + (!levels_.empty() && levels_.back().is_array ? element_bytes : 0));
        json* value = place(is_array ? json::array() : json::object());
        levels_.push_back(Level{value, is_array, {}, {}});
        return true;
    }

    bool close() {
        levels_.pop_back();
        return true;
    }

    json& root_;
    std::size_t limit_;
    std::size_t used_ = 0;
    std::vector<Level> levels_;
    std::size_t error_position_ = 0;
    std::string error_;
    bool overflow_ = false;
};

// "line 3, column 7" of the byte at `at` (from 0), counted as an editor counts.
std::string line_and_column(std::string_view text, std::size_t at) {
    at = std::min(at, text.size());
    const std::string_view before = text.substr(0, at);
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    const std::size_t line_start = before.rfind('\n');
    const std::size_t column = line_start == std::string_view::npos ? at + 1 : at - line_start;
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Empties `document` without asking for memory. nlohmann's destructor first moves a container's elements onto a
// stack it reserves (destroying an array of 50 million numbers asks for 800 MB more), so a document dropped after
// a refusal, under a memory cap, ended the program (std::bad_alloc in a destructor: SIGABRT) instead of reporting
// the refusal. Here each container is emptied from its back, deepest first, and an element is removed only once it
// is empty: no destructor called has anything to move. The path down is at most as deep as the reader allows.
void release(json& document) {
    std::array<json*, max_json_depth + 2> path{};
    std::size_t depth = 0;
    path[depth++] = &document;
    while (depth > 0) {
        json& top = *path[depth - 1];
        json* last = nullptr;
        if (top.is_array() && !top.empty()) last = &top.back();
        if (top.is_object() && !top.empty()) last = &top.get_ptr<json::object_t*>()->back().second;
        if (!last) {
            --depth;
            continue;
        }
        if (last->is_structured() && !last->empty()) {
            path[depth++] = last;
            continue;
        }
        if (top.is_array()) {
            top.get_ptr<json::array_t*>()->pop_back();
        } else {
            json::object_t& members = *top.get_ptr<json::object_t*>();
            members.std::vector<std::pair<const std::string, json>>::pop_back();
        }
    }
    document = nullptr;
}

}  // namespace

json parse_json_text(std::string_view text, std::size_t memory_limit) {
    json document;
    DocumentBuilder builder(document, memory_limit);
    bool parsed = false;
    try {
        parsed = json::sax_parse(text.begin(), text.end(), &builder, json::input_format_t::json, true, false);
    } catch (...) {  // refused as too large (or out of memory): the part read is let go of without more memory
        release(document);
        throw;
    }
    if (parsed) return document;
    // nlohmann's message reads "[json.exception.parse_error.101] parse error at line 3, column 0: syntax error
    // ... ; last read: ..."; its line can point past a newline it read ahead, while its byte offset is the
    // offending character itself, so the position is counted from that. The path is read before the document
    // it points into is let go of.
    const std::string& what = builder.error();
    const std::size_t bracket = what.find("] ");
    const std::size_t colon = what.find(": ", what.find("parse error"));
    const std::size_t at = builder.error_position() > 0 ? builder.error_position() - 1 : 0;
    const InputError error =
        builder.number_overflow()
            ? InputError(builder.path(true),
                         "invalid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)))
            : InputError("", "invalid JSON at " + line_and_column(text, at) + ": " +
                                 (colon == std::string::npos ? what : what.substr(colon + 2)));
    release(document);
    throw error;
}

}  // namespace impulse::formats
