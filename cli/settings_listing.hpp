#pragma once
// `vssw compare --list-settings`: every setting of each named backend (Engine::setting_descriptions()), with its
// default, unit and meaning, as text or JSON.
#include <string>
#include <vector>

namespace vssw::cli {

// `engines` as --engine takes them ("all" and comma lists already split); empty: every backend compiled in.
std::string settings_listing(const std::vector<std::string>& engines, bool json);

}  // namespace vssw::cli
