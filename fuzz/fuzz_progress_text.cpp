// libFuzzer target: fuzz_loaders.hpp, load_progress_text.

#include "fuzz_target.hpp"

IMPULSE_FUZZ_TARGET(load_progress_text)
