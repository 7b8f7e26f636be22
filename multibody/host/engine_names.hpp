#pragma once
// Engine names as users give them (registry.cpp): every list of engines a user writes (the commands' --engine and
// --engines, a study's `engines` and [settings.X], the Python functions) is read through canonical_engine(), and a
// name it does not know is refused with engine_name_hint() (engine.hpp) at the end of the message.
#include <optional>
#include <string>

namespace vssw::multibody {

// The backend of this build a name means, in its canonical name (the one every output prints): the name itself, or it
// in other letter cases, with '_' for '-', or the backend's display name ("ODE", "Simbody-Rigid", "MuJoCo": ode,
// simbody-rigid, mujoco); nullopt when it names none. make_engine() reads names so too.
// engine_name_hint() then suggests the backend nearest to the name: " (did you mean 'mujoco'?)" for one at most two
// letters from it, one per three letters of the name, letter case aside ("mujuco", "bulet"; not "warp" for dart),
// else "".
std::optional<std::string> canonical_engine(const std::string& name);

}  // namespace vssw::multibody
