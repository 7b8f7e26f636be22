#pragma once
// The commands write JSON as the study library does (io/json.hpp): ordered keys, absent quantities as null.
#include "io/json.hpp"

namespace vssw::cli {

using study::finite_or_null;
using study::Json;
using study::or_null;

}  // namespace vssw::cli
