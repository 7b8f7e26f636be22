// `vssw scene`: the scene an engine runs, in the engine library's own file format (MJCF for MuJoCo, URDF for DART's
// blocks): the text its
// adapter builds its world from for this wall, release and settings (multibody::Engine::scene_file), so that it can
// be opened in the library's own viewer or loaded with its own parser.
#include <cmath>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "analytic/error.hpp"
#include "cli/commands.hpp"
#include "cli/engine_runs.hpp"
#include "cli/engine_setting_options.hpp"
#include "cli/friction_option.hpp"
#include "cli/wall_options.hpp"
#include "io/atomic_file.hpp"
#include "io/json.hpp"
#include "multibody/engine.hpp"

namespace vssw::cli {
namespace {

struct SceneOptions {
    std::string engine;
    WallOptions wall;
    ModelOptions model;
    EngineSettingOptions settings;
    std::optional<std::string> friction;
    double theta0 = 0.0;  // r: the release as a fraction of alpha1
    std::string out;
    bool json = false;
};

multibody::SceneFile scene_file_of(const SceneOptions& o, const multibody::Engine& engine,
                                   const multibody::EngineSettings& settings, const multibody::WallScene& scene) {
    require(std::isfinite(o.theta0) && std::abs(o.theta0) < 1.0, "--theta0", "from -1 to 1, both excluded (a fraction "
            "of alpha1)", o.theta0);
    multibody::Excitation ex;
    ex.theta0 = o.theta0 * scene.alpha();
    const std::optional<multibody::SceneFile> file = engine.scene_file(scene, ex, settings);
    if (!file)
        throw InputError(fmt::format("--engine {}: {} reads no scene file (its world is built through its library's "
                                     "calls only); docs/engines.md, \"Scene files\", names the engines that have one",
                                     o.engine, engine.display_name()));
    return *file;
}

void run_scene(const SceneOptions& o, std::ostream& out, std::ostream& err) {
    if (o.out.empty()) throw InputError("--out: the path is empty (give a file name, or - for standard output)");
    if (o.out == "-" && o.json)
        throw InputError("--out - and --json both write to standard output: give the scene a file name");
    if (names_analytic_model(o.engine))
        throw InputError(fmt::format("--engine {}: the analytic model is no engine library and has no scene file",
                                     o.engine));
    const ChosenModel chosen = choose_model(o.wall, o.model);
    const std::unique_ptr<multibody::Engine> engine = multibody::make_engine(o.engine);
    const multibody::EngineSettings settings = engine_settings_of(*engine, o.settings);
    const multibody::WallScene scene = with_friction(multibody::WallScene(chosen.wall), o.friction);
    const multibody::SceneFile file = scene_file_of(o, *engine, settings, scene);
    if (o.out == "-") {
        out << file.text;
    } else {
        // Under a temporary name beside it, renamed onto it: a failed write leaves an existing file as it was.
        io::write_file(o.out, [&](std::ostream& to) { to << file.text; });
    }
    std::ostream& summary = o.out == "-" ? err : out;
    if (o.json) {
        io::Json j;
        j["engine"] = engine->name();
        j["version"] = engine->version();
        j["format"] = file.format;
        j["path"] = o.out;
        j["model"] = to_string(chosen.kind);
        j["theta0"] = o.theta0;
        j["dt"] = settings.dt;
        summary << io::dump_json(j, 2) << '\n';
    } else {
        summary << fmt::format("{} scene ({}) of the {} at theta0 = {:g} alpha1 written to {}\n",
                               engine->display_name(), file.format, describe_wall(o.wall, chosen.kind), o.theta0,
                               o.out == "-" ? std::string("standard output") : o.out);
    }
}

}  // namespace

Command add_scene_command(CLI::App& root) {
    auto o = std::make_shared<SceneOptions>();
    CLI::App* cmd = root.add_subcommand(
        "scene",
        "Write the scene an engine runs in the engine's own file format (MJCF for MuJoCo, URDF for DART's blocks), "
        "without running it");
    cmd->add_option("--engine", o->engine,
                    fmt::format("the engine whose scene to write (one with a scene format: mujoco, dart) "
                                "(available: {}) (required)",
                                fmt::join(multibody::available_engines(), ", ")))
        ->required();
    add_model_options(*cmd, o->model);
    add_wall_options(*cmd, o->wall, true);
    add_friction_option(*cmd, o->friction);
    cmd->add_option("--theta0", o->theta0,
                    "the release the scene starts from, as a fraction r of alpha1 (a parapet's alpha), |r| < 1 "
                    "(default 0: upright at rest); MJCF: the keyframe 'release'; URDF: in its comment");
    add_engine_setting_options(*cmd, o->settings);
    cmd->add_option("--out", o->out, "the file to write, or - for standard output (the summary then goes to the "
                                     "error stream) (required)")
        ->required();
    cmd->add_flag("--json", o->json, "print JSON instead of a line");
    cmd->footer(
        "The file is the text the engine's adapter builds its world from (the same code path as its runs), for the\n"
        "wall, release and settings given. What it cannot hold is said in a comment at its top: a ground motion and\n"
        "the overburden N are applied by vssw at every step (DART's URDF holds the blocks only: the ground, the\n"
        "roller, friction and the release are added by vssw too). Depth 1 m: masses per unit depth.\n"
        "JSON keys: engine, version, format, path, model, theta0, dt.");
    return {cmd, nullptr, [o](std::ostream& out, std::ostream& err) { run_scene(*o, out, err); }};
}

}  // namespace vssw::cli
