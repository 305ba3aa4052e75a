// libFuzzer target: fuzz_loaders.hpp, load_trace_text.

#include "fuzz_target.hpp"

IMPULSE_FUZZ_TARGET(load_trace_text)
