#include "apps/version_text.hpp"

#include <fmt/format.h>

#include "multibody/engine.hpp"
#include "vssw_commit.hpp"  // VSSW_GIT_COMMIT, written at build time (apps/CMakeLists.txt)

namespace vssw::cli {

std::string version_text() {
    const std::string commit = VSSW_GIT_COMMIT;
    std::string text = fmt::format("vssw {} ({})\n", VSSW_VERSION,
                                   commit.empty() ? "built outside a git checkout" : "commit " + commit);
    text += "backends in this build:\n";
    for (const std::string& name : multibody::available_engines())
        text += fmt::format("  {:<14} {}\n", name, multibody::make_engine(name)->version());
    const std::vector<std::string> missing = multibody::missing_engines();
    if (!missing.empty())
        text += fmt::format("not in this build (not found at configure time): {}\n", fmt::join(missing, ", "));
    return text;
}

}  // namespace vssw::cli
