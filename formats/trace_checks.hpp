#pragma once
// What a trace's schema cannot say, checked when a trace is read (formats/trace_json.cpp): each throws
// InputError at the path of the first value that is wrong.

#include "formats/json_values.hpp"
#include "record/trace.hpp"

#include <cstddef>
#include <string>

namespace impulse::formats {

// Every index in a frame names a body of the scene or a contact of the frame; each body list has the scene's
// bodies; a move records the word its method's unit calls for; the two phases are one of each; an update names
// the body its contact has in the slot it names.
void check_references(const json& frame, const std::string& path, std::size_t bodies);

// What the counts, numbers and order of a trace say about each other, as every trace we write has them, so
// that a command reading the trace may count on them: the recording's range is first <= last (or last = first - 1,
// no frames); frames come in
// increasing order, once each, inside that range; a frame's contact records come in increasing order of their
// number, once each, no more than contact_count and all of them when no contact filter was given (else only
// contacts the filter names); each phase ran iterations_used iterations, no more than its iteration_limit, and
// records each, numbered 0, 1, 2, ... in order. `document` passed its schema.
void check_counts(const json& document);

// The states and records describe real bodies and contacts (unit orientations, symmetric positive
// semi-definite inverse inertias, unit normals, orthonormal bases), so the replay and the scene view can trust
// them; a trace we write passes with room to spare.
void check_frame_values(const FrameRecord& f, const std::string& path);

}  // namespace impulse::formats
