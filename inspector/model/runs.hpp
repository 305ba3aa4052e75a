#pragma once
// Making a trace from a scene, as `resolve` and `run` do: shared by those commands and the inspector,
// which re-runs a scene whenever a setting changes.

#include "record/trace.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace impulse::inspect {

// How much trace a run may record (--max-trace-mb): past the budget recording stops at the last complete frame
// and `stopped_at`, if given, receives the frame it stopped at (the run itself goes on).
struct TraceBudget {
    std::size_t bytes = SIZE_MAX;
    std::optional<int>* stopped_at = nullptr;
};

// One resolution of the scene's contacts: those written in it, else those its shapes make where they
// stand. Throws io::InputError("--record", ...) when the filter names a contact the frame does not have.
Trace resolve_once(const Scene& scene, const TraceFilter& recording, TraceBudget budget = {});

// `frames` frames of the world step (integrate, detect, resolve), recording those the filter names.
Trace run_frames(const Scene& scene, const TraceFilter& recording, int frames, TraceBudget budget = {});

}  // namespace impulse::inspect
