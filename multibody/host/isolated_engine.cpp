#include "multibody/host/isolated_engine.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>

#include "multibody/host/run_budget.hpp"
#include "multibody/kit/settings_reader.hpp"
#include "multibody/kit/step_resolution.hpp"
#include "multibody/host/worker_process.hpp"

namespace vssw::multibody {
namespace {

// A child that uses no CPU for this many times its CPU budget is waiting on something that will not come (a lock
// held at the fork by a thread the child does not have): it is killed. Generous, so that a loaded machine (the sweep
// ran at load 12 on 2 cores) never stops a run that is merely slow.
constexpr double kWallSecondsPerBudgetSecond = 20.0;

static_assert(std::is_trivially_copyable_v<TrajectorySample>, "samples are sent as bytes");

template <class T>
void put(std::string& out, const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

void put_text(std::string& out, const std::string& s) {
    put(out, static_cast<std::uint64_t>(s.size()));
    out += s;
}

class Reader {
public:
    explicit Reader(std::string_view bytes) : rest_(bytes) {}
    template <class T>
    T get() {
        T v;
        std::memcpy(&v, take(sizeof v).data(), sizeof v);
        return v;
    }
    std::string_view take(std::size_t n) {
        if (n > rest_.size()) throw EngineFailure("an engine run's answer from its child process is cut short");
        const std::string_view part = rest_.substr(0, n);
        rest_.remove_prefix(n);
        return part;
    }
    std::string text() { return std::string(take(static_cast<std::size_t>(get<std::uint64_t>()))); }

private:
    std::string_view rest_;
};

class IsolatedEngine final : public Engine {
public:
    explicit IsolatedEngine(std::unique_ptr<Engine> inner) : inner_(std::move(inner)) {}
    std::string name() const override { return inner_->name(); }
    std::string version() const override { return inner_->version(); }
    std::string display_name() const override { return inner_->display_name(); }
    EngineSettings default_settings() const override { return inner_->default_settings(); }
    std::vector<SettingDescription> setting_descriptions() const override { return inner_->setting_descriptions(); }
    void check_settings(const EngineSettings& settings) const override { inner_->check_settings(settings); }
    // Each run in its own process: two never share the library's process-wide state.
    bool runs_concurrently() const override { return true; }
    bool dt_is_a_reporting_interval() const override { return inner_->dt_is_a_reporting_interval(); }
    double cost_per_simulated_second() const override { return inner_->cost_per_simulated_second(); }
    // Text the adapter writes, as check_settings is: nothing of the library runs but its version string.
    std::optional<SceneFile> scene_file(const WallScene& scene, const Excitation& excitation,
                                        const EngineSettings& settings) const override {
        require_settings_fit_wall(display_name(), settings, setting_descriptions(), scene);
        return inner_->scene_file(scene, excitation, settings);
    }

    Trajectory simulate(const WallScene& scene, const Excitation& excitation,
                        const EngineSettings& settings) const override {
        // A bad setting comes back from the child as the InputError the adapter throws (callers check settings before
        // they run anything: check_settings above). A step the run cannot use is refused here, in this process, before
        // a budget is made of its step count (MuJoCo at dt 1e-310 once failed on "a budget of inf s").
        require_step_resolves(display_name(), scene, excitation, settings.dt, !dt_is_a_reporting_interval());
        require_settings_fit_wall(display_name(), settings, setting_descriptions(), scene);
        WorkerLimits limits;
        limits.cpu_seconds = RunBudget::seconds(excitation.t_end, settings.dt);
        limits.wall_seconds = kWallSecondsPerBudgetSecond * limits.cpu_seconds;
        limits.budget = RunBudget::describe(excitation.t_end, settings.dt);
        const std::string_view bytes = run_in_worker_process(
            [&](std::string& out) { append_trajectory(inner_->simulate(scene, excitation, settings), out); },
            inner_->name(), limits);
        return read_trajectory(bytes);
    }

private:
    std::unique_ptr<Engine> inner_;
};

void put_time(std::string& out, const std::optional<double>& t) {
    put(out, t.has_value());
    put(out, t.value_or(0.0));
}

std::optional<double> read_time(Reader& r) {
    const bool has = r.get<bool>();
    const double t = r.get<double>();
    return has ? std::optional(t) : std::nullopt;
}

void append_slip(const std::optional<SlipMeasures>& slip, std::string& out) {
    put(out, slip.has_value());
    if (!slip) return;
    for (const double v : {slip->base_largest, slip->base_residual, slip->hinge_largest, slip->hinge_residual, slip->b})
        put(out, v);
    put_time(out, slip->t_first_slip);
    put_time(out, slip->t_first_lift);
    put(out, slip->slid_off.has_value());
    put_text(out, slip->slid_off.value_or(""));
}

std::optional<SlipMeasures> read_slip(Reader& r) {
    if (!r.get<bool>()) return std::nullopt;
    SlipMeasures m;
    for (double* v : {&m.base_largest, &m.base_residual, &m.hinge_largest, &m.hinge_residual, &m.b})
        *v = r.get<double>();
    m.t_first_slip = read_time(r);
    m.t_first_lift = read_time(r);
    const bool slid_off = r.get<bool>();
    std::string why = r.text();
    if (slid_off) m.slid_off = std::move(why);
    return m;
}

}  // namespace

std::unique_ptr<Engine> isolated(std::unique_ptr<Engine> inner) {
    return std::make_unique<IsolatedEngine>(std::move(inner));
}

void append_trajectory(const Trajectory& t, std::string& out) {
    // Room for the whole trajectory at once: appended to a string grown by doubling, the samples (64 bytes each, 190
    // kB for a free vibration sampled every step) were copied again into twice the room by the small fields after
    // them, in a child whose every page is fresh. The fields after the samples are a few hundred bytes and the
    // warnings' texts; a longer tail only grows the string once more.
    constexpr std::size_t kTailBytes = 1024;
    std::size_t texts = 0;
    for (const std::string& w : t.warnings) texts += sizeof(std::uint64_t) + w.size();
    out.reserve(out.size() + sizeof(std::uint64_t) + t.samples.size() * sizeof(TrajectorySample) + texts + kTailBytes);
    put(out, static_cast<std::uint64_t>(t.samples.size()));
    out.append(reinterpret_cast<const char*>(t.samples.data()), t.samples.size() * sizeof(TrajectorySample));
    put(out, t.overturned);
    put(out, t.at_rest_at_end);
    put(out, t.steps);
    put(out, static_cast<std::uint64_t>(t.warnings.size()));
    for (const std::string& w : t.warnings) put_text(out, w);
    put(out, t.located.has_value());
    if (t.located) {
        const LocatedEvents& e = *t.located;
        put(out, e.max_abs_theta1);
        put(out, e.t_max_abs_theta1);
        put(out, e.t_overturn.has_value());
        put(out, e.t_overturn.value_or(0.0));
        put(out, e.energy_balance_error);
        put(out, e.supports_computed);
        put(out, e.roller_tension_at.has_value());
        put(out, e.roller_tension_at.value_or(0.0));
        put(out, e.base_friction_needed);
        put(out, e.hinge_friction_needed);
    }
    append_slip(t.slip, out);
}

Trajectory read_trajectory(std::string_view bytes) {
    Reader r(bytes);
    Trajectory t;
    const auto n = r.get<std::uint64_t>();
    if (n > bytes.size() / sizeof(TrajectorySample))
        throw EngineFailure("an engine run's answer from its child process is cut short");
    t.samples.resize(static_cast<std::size_t>(n));
    const std::string_view raw = r.take(t.samples.size() * sizeof(TrajectorySample));
    if (!raw.empty()) std::memcpy(t.samples.data(), raw.data(), raw.size());
    t.overturned = r.get<bool>();
    t.at_rest_at_end = r.get<bool>();
    t.steps = r.get<long>();
    const auto warnings = r.get<std::uint64_t>();
    for (std::uint64_t i = 0; i < warnings; ++i) t.warnings.push_back(r.text());
    if (r.get<bool>()) {
        LocatedEvents e;
        e.max_abs_theta1 = r.get<double>();
        e.t_max_abs_theta1 = r.get<double>();
        const bool has_overturn = r.get<bool>();
        const double t_overturn = r.get<double>();
        if (has_overturn) e.t_overturn = t_overturn;
        e.energy_balance_error = r.get<double>();
        e.supports_computed = r.get<bool>();
        const bool has_tension = r.get<bool>();
        const double tension_at = r.get<double>();
        if (has_tension) e.roller_tension_at = tension_at;
        e.base_friction_needed = r.get<double>();
        e.hinge_friction_needed = r.get<double>();
        t.located = e;
    }
    t.slip = read_slip(r);
    return t;
}

}  // namespace vssw::multibody
