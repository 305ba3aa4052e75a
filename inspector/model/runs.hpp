#pragma once
// Making a trace from a scene, as `resolve` and `run` do: shared by those commands and the inspector,
// which re-runs a scene whenever a setting changes.

#include "record/trace.hpp"
#include "world/non_finite_check.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace impulse::model {

// How much trace a run may record (--max-trace-mb): past the budget recording stops at the last complete frame
// and `stopped_at`, if given, receives the frame it stopped at. The run itself goes on (`run` writes every
// frame's states), unless `stop_run`: the inspector shows only what it recorded, so it stops simulating there.
struct TraceBudget {
    std::size_t bytes = SIZE_MAX;
    std::optional<int>* stopped_at = nullptr;
    bool stop_run = false;
};

// A run that stopped because a frame left a body's state non-finite. The trace ends with the frame before it
// (a NaN has no JSON), and its recording filter says so, so it stays valid.
struct BrokenRun {
    int frame = 0;
    NonFiniteBody body;
};

// `frame 12: body "box3" has a non-finite velocity after resolution (last touched by contact 7: box3 / box4)`
std::string broken_run_text(const Scene& scene, const BrokenRun& broken);

// One resolution of the scene's contacts: those written in it, else those its shapes make where they
// stand. Throws formats::InputError("--record", ...) when the filter names a contact the frame does not have.
// If it leaves a body non-finite, `broken` (if given) receives it and the trace holds no frame.
Trace resolve_once(const Scene& scene, const TraceFilter& recording, TraceBudget budget = {},
                   std::optional<BrokenRun>* broken = nullptr);

// `frames` frames of the world step (integrate, detect, resolve), recording those the filter names. A frame
// that leaves a body non-finite ends the run: `broken` (if given) receives it, and the trace ends before it.
// With budget.stop_run, the run also ends at the frame the recording could not keep; the header's frame count
// (trace.scene.world.frames) is then the frames before it, which is what re-running it needs.
Trace run_frames(const Scene& scene, const TraceFilter& recording, int frames, TraceBudget budget = {},
                 std::optional<BrokenRun>* broken = nullptr);

}  // namespace impulse::model
