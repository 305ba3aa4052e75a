#pragma once
// A shipped case or scene ("cases/ruler", "stack_3") opened as the inspector opens it.

#include "model/session.hpp"

#include <string>

namespace impulse::test {

inline const std::string shipped_scenes = IMPULSE_SOURCE_DIR "/scenes/";

inline inspect::Session opened_session(const std::string& name, const inspect::OpenOptions& options = {}) {
    return inspect::Session::open(shipped_scenes + name + ".json", options);
}

inline Trace opened(const std::string& name, const inspect::OpenOptions& options = {}) {
    return opened_session(name, options).trace();
}

}  // namespace impulse::test
