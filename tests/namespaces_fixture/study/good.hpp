#pragma once
// In its own namespace, naming another folder's type by its owner: accepted.
namespace vssw::io { struct Json; }
namespace vssw::study {
void write(const io::Json& j);
}  // namespace vssw::study
