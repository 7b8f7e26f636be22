#pragma once
// When a report or a study was made, as every output states it.
#include <string>

namespace vssw::io {

// The current time as ISO 8601 UTC ("2025-01-31T12:00:00Z").
std::string utc_now();

}  // namespace vssw::io
