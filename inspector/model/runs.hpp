#pragma once
// Making a trace from a scene, as `resolve` and `run` do: shared by those commands and the inspector,
// which re-runs a scene whenever a setting changes.

#include "record/trace.hpp"

namespace impulse::inspect {

// One resolution of the scene's contacts: those written in it, else those its shapes make where they
// stand. Throws io::InputError("--record", ...) when the filter names a contact the frame does not have.
Trace resolve_once(const Scene& scene, const TraceFilter& recording);

// `frames` frames of the world step (integrate, detect, resolve), recording those the filter names.
Trace run_frames(const Scene& scene, const TraceFilter& recording, int frames);

}  // namespace impulse::inspect
