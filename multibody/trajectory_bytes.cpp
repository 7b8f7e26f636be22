#include "multibody/trajectory_bytes.hpp"

#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace vssw::multibody {
namespace {

class Writer {
public:
    explicit Writer(std::string& out) : out_(out) {}
    template <class T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        out_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void put_text(const std::string& s) {
        put(static_cast<std::uint64_t>(s.size()));
        out_.append(s);
    }
    void put_optional(const std::optional<double>& v) {
        put(static_cast<char>(v.has_value()));
        if (v) put(*v);
    }

private:
    std::string& out_;
};

constexpr std::size_t kSampleBytes = 7 * sizeof(double) + sizeof(int);

class Reader {
public:
    explicit Reader(std::string_view in) : in_(in) {}
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T));
        T v;
        std::memcpy(&v, in_.data(), sizeof v);
        in_.remove_prefix(sizeof v);
        return v;
    }
    std::string get_text() {
        const auto n = get<std::uint64_t>();
        need(n);
        std::string s(in_.substr(0, n));
        in_.remove_prefix(n);
        return s;
    }
    std::optional<double> get_optional() {
        if (!get<char>()) return std::nullopt;
        return get<double>();
    }
    bool done() const { return in_.empty(); }

private:
    void need(std::uint64_t n) const {
        if (in_.size() < n) throw std::runtime_error("a trajectory's bytes end early");
    }
    std::string_view in_;
};

}  // namespace

// Field by field (not the structs' raw bytes: their padding is indeterminate, and the strings are not bytes).
std::string to_bytes(const Trajectory& t) {
    std::string out;
    append_bytes(out, t);
    return out;
}

void append_bytes(std::string& out, const Trajectory& t) {
    out.reserve(out.size() + 256 + t.samples.size() * kSampleBytes);  // the samples, and room for the rest
    Writer w(out);
    w.put(static_cast<std::uint64_t>(t.samples.size()));
    for (const TrajectorySample& p : t.samples) {
        w.put(p.t);
        w.put(p.theta1);
        w.put(p.theta1_dot);
        w.put(p.theta2);
        w.put(p.top_dy);
        w.put(p.kinetic);
        w.put(p.potential);
        w.put(p.contacts);
    }
    w.put(static_cast<char>(t.overturned));
    w.put(static_cast<char>(t.at_rest_at_end));
    w.put(t.steps);
    w.put(static_cast<std::uint64_t>(t.warnings.size()));
    for (const std::string& s : t.warnings) w.put_text(s);
    w.put(static_cast<char>(t.located.has_value()));
    if (t.located) {
        const LocatedEvents& e = *t.located;
        w.put(e.max_abs_theta1);
        w.put(e.t_max_abs_theta1);
        w.put_optional(e.t_overturn);
        w.put(e.energy_balance_error);
        w.put(static_cast<char>(e.supports_computed));
        w.put_optional(e.roller_tension_at);
    }
}

Trajectory trajectory_from_bytes(std::string_view bytes) {
    Reader r(bytes);
    Trajectory t;
    const auto n = r.get<std::uint64_t>();
    // A count larger than the bytes could hold is a broken message, not a reason to allocate that much.
    if (n > bytes.size()) throw std::runtime_error("a trajectory's sample count exceeds its bytes");
    t.samples.resize(n);
    for (TrajectorySample& p : t.samples) {
        p.t = r.get<double>();
        p.theta1 = r.get<double>();
        p.theta1_dot = r.get<double>();
        p.theta2 = r.get<double>();
        p.top_dy = r.get<double>();
        p.kinetic = r.get<double>();
        p.potential = r.get<double>();
        p.contacts = r.get<int>();
    }
    t.overturned = r.get<char>() != 0;
    t.at_rest_at_end = r.get<char>() != 0;
    t.steps = r.get<long>();
    const auto warnings = r.get<std::uint64_t>();
    if (warnings > bytes.size()) throw std::runtime_error("a trajectory's warning count exceeds its bytes");
    for (std::uint64_t i = 0; i < warnings; ++i) t.warnings.push_back(r.get_text());
    if (r.get<char>()) {
        LocatedEvents e;
        e.max_abs_theta1 = r.get<double>();
        e.t_max_abs_theta1 = r.get<double>();
        e.t_overturn = r.get_optional();
        e.energy_balance_error = r.get<double>();
        e.supports_computed = r.get<char>() != 0;
        e.roller_tension_at = r.get_optional();
        t.located = e;
    }
    if (!r.done()) throw std::runtime_error("a trajectory's bytes run on past its end");
    return t;
}

}  // namespace vssw::multibody
