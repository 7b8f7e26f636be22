#include "multibody/worker_process.hpp"

#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "analytic/error.hpp"
#include "multibody/child_process.hpp"

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

}  // namespace

std::string_view run_in_worker_process(const std::function<void(std::string&)>& work, const std::string& who) {
    std::string_view out;  // in place, where it was received (a task's rows: no copy)
    const ChildResult child = run_in_child([&] { return answer(work); }, 0.0, out);
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

bool worker_processes_enabled() {
    const char* v = std::getenv("VSSW_WORKER_PROCESSES");
    if (!v || std::string(v).empty() || std::string(v) == "1") return true;
    if (std::string(v) == "0") return false;
    throw InputError(fmt::format("VSSW_WORKER_PROCESSES must be 0 (off) or 1 (on), got '{}'", v));
}

bool runs_in_worker_processes(const Engine& engine, int threads) {
    if (threads <= 1 || engine.runs_concurrently() || !engine.runs_in_worker_process()) return false;
    return worker_processes_enabled();
}

}  // namespace vssw::multibody
