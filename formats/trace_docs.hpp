#pragma once
// The field lists of docs/trace-format.md, written from the word list (formats/words.hpp): one table per
// kind of item, and the keys format 2 renamed. A test keeps the committed docs equal to this text.

#include <string>
#include <string_view>

namespace impulse::formats {

// The marked lines around the generated section of docs/trace-format.md.
inline constexpr std::string_view trace_docs_begin = "<!-- words: generated from formats/word_table.hpp -->";
inline constexpr std::string_view trace_docs_end = "<!-- end of words -->";

// The generated section, markers included.
std::string trace_word_docs();

// `document` with its generated section replaced by `section`; the document unchanged when it has no markers.
std::string with_trace_word_docs(const std::string& document, const std::string& section);

}  // namespace impulse::formats
