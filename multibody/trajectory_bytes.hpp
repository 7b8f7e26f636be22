#pragma once
// A Trajectory as bytes and back, exactly: every double as its 8 bytes (the same bits come back: NaN payloads, -0,
// subnormals), so that a run in a worker process (worker_process.hpp) gives the caller the very numbers the same run
// in the caller's process gives. Both ends are the same program on the same machine: native byte order and sizes.
#include <string>
#include <string_view>

#include "multibody/engine.hpp"

namespace vssw::multibody {

std::string to_bytes(const Trajectory& t);
// The same bytes appended to `out` (room made once: a trajectory is megabytes).
void append_bytes(std::string& out, const Trajectory& t);
// Throws std::runtime_error when the bytes end early or run on past the trajectory (a child that died mid-write).
Trajectory trajectory_from_bytes(std::string_view bytes);

}  // namespace vssw::multibody
