// libFuzzer target: fuzz_loaders.hpp, load_worksheet_trace.

#include "fuzz_target.hpp"

IMPULSE_FUZZ_TARGET(load_worksheet_trace)
