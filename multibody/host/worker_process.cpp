#include "multibody/host/worker_process.hpp"

#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/host/child_process.hpp"

namespace vssw::multibody {
namespace {

// The child's answer: one tag byte, then what the work wrote or the exception's message.
constexpr char kReturned = 'r';
constexpr char kEngineFailure = 'f';
constexpr char kInputError = 'i';
constexpr char kOtherError = 'e';

// Runs in the child: every exception becomes a tagged message, so that the parent throws the same type.
std::string answer(const std::function<void(std::string&)>& work) {
    try {
        std::string out(1, kReturned);
        work(out);
        return out;
    } catch (const EngineFailure& e) {
        return kEngineFailure + std::string(e.what());
    } catch (const InputError& e) {
        return kInputError + std::string(e.what());
    } catch (const std::exception& e) {
        return kOtherError + std::string(e.what());
    } catch (...) {
        return kOtherError + std::string("an exception of unknown type");
    }
}

// In the child, before the work: its CPU time limited (the soft limit sends SIGXCPU, the hard one a second later
// SIGKILL), and no core file written when the library aborts (a core of a process with every engine loaded is
// hundreds of MB, left in the user's folder).
void limit_child(double cpu_seconds) {
    const rlimit no_core{0, 0};
    (void)::setrlimit(RLIMIT_CORE, &no_core);
    if (cpu_seconds <= 0.0) return;
    const auto soft = static_cast<rlim_t>(std::ceil(cpu_seconds));
    const rlimit cpu{soft, soft + 1};
    (void)::setrlimit(RLIMIT_CPU, &cpu);
}

}  // namespace

std::string_view run_in_worker_process(const std::function<void(std::string&)>& work, const std::string& who,
                                       const WorkerLimits& limits) {
    std::string_view out;  // in place, where it was received (a task's rows: no copy)
    const ChildResult child = run_in_child(
        [&] {
            limit_child(limits.cpu_seconds);
            return answer(work);
        },
        limits.wall_seconds, out);
    const bool over_cpu = limits.cpu_seconds > 0.0 && child.end == ChildEnd::crashed && child.signal == SIGXCPU;
    if (over_cpu) throw EngineFailure(fmt::format("{}: the run passed its budget of {}", who, limits.budget));
    if (child.end == ChildEnd::timed_out)
        throw EngineFailure(fmt::format("{}: the run was stopped after {:.0f} s of wall time without an answer (its "
                                        "budget is {})",
                                        who, child.time_s, limits.budget));
    // Ended by a signal of the interrupting kind (the terminal's Ctrl-C reaches the whole process group): the run did
    // not fail, the command is being stopped.
    const bool interrupted = child.end == ChildEnd::crashed &&
                             (child.signal == SIGINT || child.signal == SIGTERM || child.signal == SIGHUP);
    if (interrupted)
        throw RunInterrupted(
            fmt::format("{}: the run was interrupted by signal {} ({})", who, child.signal, ::strsignal(child.signal)));
    if (child.end != ChildEnd::completed)  // answer() catches everything: a signal or an exit of the library's own
        throw EngineFailure(fmt::format("{}: its worker process {}", who, describe_end(child)));
    const char tag = out.empty() ? '\0' : out[0];
    out.remove_prefix(out.empty() ? 0 : 1);
    switch (tag) {
        case kReturned:
            return out;
        case kEngineFailure:
            throw EngineFailure(std::string(out));
        case kInputError:
            throw InputError(std::string(out));
        case kOtherError:
            throw std::runtime_error(std::string(out));
        default:
            throw EngineFailure(fmt::format("{}: its worker process ended without an answer", who));
    }
}

}  // namespace vssw::multibody
