#pragma once
// A re-export: refused.
namespace vssw::multibody { struct Engine; }
namespace vssw::compare {
using multibody::Engine;
}  // namespace vssw::compare
