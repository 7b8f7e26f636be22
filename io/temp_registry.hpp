#pragma once
// The temporary files and folders vssw has open at a given moment (AtomicFile's ".NAME.vssw-tmp-PID-N", a results
// folder's staging copy ".NAME.vssw-tmp-PID"), so that a program ended by SIGINT, SIGTERM or SIGHUP can remove them
// before it dies (cli/signal_cleanup.hpp). Registering costs a mutex and a set insertion: nothing beside writing a file.
// The library never removes them on a signal by itself: only the program installs the handlers (the Python module
// keeps Python's own SIGINT handling).
#include <filesystem>

namespace vssw::io {

// Register a path before creating it, so that it is never on disk unregistered.
void register_temp(const std::filesystem::path& path);
void unregister_temp(const std::filesystem::path& path);
// Removes every registered path (a folder with what it holds); errors are ignored. Only for a process about to end:
// the registry stays locked, so a thread that would create another temporary file waits until the end. Not
// async-signal-safe: called from a thread, never from a signal handler.
void remove_registered_temps();

// Registers `path` for as long as the object lives.
class TempRegistration {
public:
    explicit TempRegistration(std::filesystem::path path);
    ~TempRegistration();
    TempRegistration(const TempRegistration&) = delete;
    TempRegistration& operator=(const TempRegistration&) = delete;

private:
    std::filesystem::path path_;
};

}  // namespace vssw::io
