#pragma once
// A file of io/ in the namespace of study/: refused.
namespace vssw::study {
int helper();
}  // namespace vssw::study
