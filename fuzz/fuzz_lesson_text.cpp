// libFuzzer target: fuzz_loaders.hpp, load_lesson_text.

#include "fuzz_target.hpp"

IMPULSE_FUZZ_TARGET(load_lesson_text)
