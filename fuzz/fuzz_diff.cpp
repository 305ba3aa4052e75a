// libFuzzer target: fuzz_loaders.hpp, load_diff.

#include "fuzz_target.hpp"

IMPULSE_FUZZ_TARGET(load_diff)
