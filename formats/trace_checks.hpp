#pragma once
// What a trace's schema cannot say, checked when a trace is read (formats/trace_json.cpp): each throws
// InputError at the path of the first value that is wrong.

#include "formats/json_values.hpp"
#include "record/trace.hpp"

#include <cstddef>
#include <string>

namespace impulse::formats {

// Every index in a frame names a body of the scene or a contact of the frame; each body list has the scene's
// bodies; a move records the word its method's unit calls for; the two phases are one of each.
void check_references(const json& frame, const std::string& path, std::size_t bodies);

// The states and records describe real bodies and contacts (unit orientations, symmetric positive
// semi-definite inverse inertias, unit normals, orthonormal bases), so the replay and the scene view can trust
// them; a trace we write passes with room to spare.
void check_frame_values(const FrameRecord& f, const std::string& path);

}  // namespace impulse::formats
