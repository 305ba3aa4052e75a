#pragma once
// The body of every fuzz target: one loader of fuzz_loaders.hpp on the input. Bad input (formats::InputError)
// ends the run quietly; anything else escapes to libFuzzer, which keeps the input.

#include "fuzz_loaders.hpp"

#include <cstddef>
#include <cstdint>

namespace impulse::fuzz {

inline int run_loader(void (*load)(std::string_view), const std::uint8_t* data, std::size_t size) {
    try {
        load({reinterpret_cast<const char*>(data), size});
    } catch (const formats::InputError&) {
    }
    return 0;
}

}  // namespace impulse::fuzz

// One target per file: IMPULSE_FUZZ_TARGET(load_scene_text) defines libFuzzer's entry point.
#define IMPULSE_FUZZ_TARGET(loader)                                                     \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
        return impulse::fuzz::run_loader(impulse::fuzz::loader, data, size);            \
    }
