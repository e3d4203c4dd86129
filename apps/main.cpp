// mdrsim: the command line. Parse, call the engine, print; exit 0 done, 1 internal, 2 bad input
// (130/143: a sweep stopped by SIGINT/SIGTERM; 141: standard output closed by its reader).
#include <fmt/format.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <cctype>
#include <csignal>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "apps/commands.hpp"
#include "apps/write_error.hpp"
#include "engine/base/available_cpus.hpp"
#include "engine/base/text.hpp"
#include "engine/events/program_version.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/run_label.hpp"
#include "engine/sweep/usage_error.hpp"

namespace {

using mdrsim::join_names;
using mdrsim::one_line;

constexpr const char* kLevels[] = {"trace", "debug", "info", "warn", "error", "off"};

void set_up_logging(const std::string& level) {
  auto logger = spdlog::stderr_color_mt("mdrsim");
  logger->set_formatter(mdrsim::cli::labelled_formatter("[%l] %*%v"));  // %*: a sweep's row
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(level));
}

/// CLI11's messages in our form: "--flag: what" where it names the flag, else "mdrsim: what";
/// lowercase after the location.
std::string usage_message(const std::string& what) {
  std::string text = one_line(what);
  const std::size_t colon = text.find(": ");
  std::size_t start = 0;
  if (text.rfind("--", 0) == 0 && colon != std::string::npos && text.find(' ') > colon) {
    start = colon + 2;
  } else {
    text = "mdrsim: " + text;
    start = 8;
  }
  if (start < text.size()) {
    text[start] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[start])));
  }
  // CLI11 2.1 says "At Most 1 required but received 2".
  if (const auto at = text.find("at Most "); at != std::string::npos) text[at + 3] = 'm';
  return text;
}

/// The names of `app`'s subcommands, joined by ", ".
std::string command_names(CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return join_names(names);
}

/// The registered parts by name, for the help texts.
std::string parts_footer() {
  const auto registries = mdrsim::Registries::builtin();
  return fmt::format(
      "Profiles: {}\nCriteria: {}\nControllers: {}\nFriction laws: {}\n`mdrsim list` gives each "
      "one's keys and units; docs/scene.md \"Changing values from the command line\" the keys a "
      "--set replaces.",
      join_names(registries.profiles.names()), join_names(registries.criteria.names()),
      join_names(registries.controllers.names()), join_names(registries.friction_laws.names()));
}

/// A --set value the shell has split (an unquoted inline table): CLI11 then complains about
/// its pieces, while the user needs to hear about the quotes.
std::optional<std::string> split_set_value(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    std::string_view set;
    if (arg == "--set" && i + 1 < argc) {
      set = argv[i + 1];
    } else if (arg.rfind("--set=", 0) == 0) {
      set = arg.substr(6);
    }
    if (const auto eq = set.find('='); eq != std::string_view::npos && eq > 0) {
      if (auto message = mdrsim::split_value_message(set.substr(0, eq), set.substr(eq + 1))) {
        return message;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  // A closed pipe is an error of the write, handled below (standard output's reader gone: exit
  // 141 quietly), not a signal that kills the process wherever it is.
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{"mdrsim: adhesive contact under combined normal and tangential loading (MDR)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("mdrsim ") + mdrsim::program_version(),
                       "print the version and exit");
  std::string level = "info";
  const std::vector<std::string> levels(std::begin(kLevels), std::end(kLevels));

  mdrsim::cli::RunOptions run;
  CLI::App* run_app = app.add_subcommand("run", "pull one scene off and report its critical point");
  run_app
      ->add_option("scene", run.scene,
                   "scene file: TOML, or JSON (a scene, or the result of run --json, whose "
                   "scene it reruns); - reads standard input")
      ->required();
  run_app->footer(parts_footer);
  run_app->add_option("--set", run.sets, "override one scene value: KEY=VALUE (repeatable)")
      ->allow_extra_args(false);
  run_app->add_option("--json", run.json,
                      "write the JSON result to PATH, or - for standard output");
  run_app->add_option("--trajectory", run.trajectory, "write one CSV row per event to PATH");
  run_app
      ->add_option("--trajectory-stride", run.trajectory_stride,
                   "write every K-th ordinary event row of --trajectory (stage ends, jumps, the "
                   "critical state and a cascade's first and last rows always; default 1)")
      ->check(CLI::Range(std::int64_t{1}, std::numeric_limits<std::int64_t>::max()));
  run_app
      ->add_option("--samples", run.samples,
                   "continuum route: points of the branch in --trajectory, evenly in the contact "
                   "radius (default 1000)")
      ->check(CLI::Range(std::int64_t{2}, std::int64_t{100'000'000}));
  run_app->add_flag("--plan", run.plan,
                    "print the route the scene takes (engine, accuracy driver and why) and exit "
                    "without running");
  run_app->add_option("--log-level", level, "log level on standard error")
      ->check(CLI::IsMember(levels));

  mdrsim::cli::SweepOptions sweep;
  sweep.threads = mdrsim::available_cpus();
  CLI::App* sweep_app =
      app.add_subcommand("sweep", "one run per row of a grid of scene values, as CSV");
  sweep_app->add_option("scene", sweep.scene, "scene file (TOML)")->required();
  sweep_app
      ->add_option("--vary", sweep.vary,
                   "KEY=FROM:TO:COUNT (evenly spaced), KEY=FROM:TO:COUNT:log or KEY=V1,V2,...; "
                   "repeat it for the product of the keys (a random design: KEY=FROM:TO or "
                   "KEY=FROM:TO:log)")
      ->required()
      ->allow_extra_args(false);
  CLI::Option* link_option =
      sweep_app
          ->add_option("--link", sweep.link,
                       "KEY=VALUES varied together with the --vary before it (as many values, "
                       "or the same draw of a random design), not as a product")
          ->allow_extra_args(false);
  sweep_app
      ->add_option("--where", sweep.where,
                   "run only the rows where 'A OP B' holds (OP: <=, <, >=, >, ==, !=; A, B: a "
                   "varied key, a number or NUMBER*KEY); repeatable, all must hold")
      ->allow_extra_args(false);
  sweep_app->add_option("--design", sweep.design,
                        "grid (default: the product of the --vary values), random (uniform "
                        "draws in each FROM:TO) or latin (a Latin hypercube)");
  sweep_app->add_option("--samples", sweep.samples, "N: the rows of a random or latin design");
  sweep_app->add_option("--seed", sweep.seed,
                        "S: the seed of a random or latin design (default 0): the same seed, "
                        "the same rows");
  sweep_app->add_option("--set", sweep.sets, "override one scene value: KEY=VALUE (repeatable)")
      ->allow_extra_args(false);
  sweep_app->add_option("--csv", sweep.csv, "write the CSV to PATH, or - (default)");
  sweep_app
      ->add_option("--threads", sweep.threads,
                   "runs in parallel (default: the CPUs this process may use)")
      ->check(CLI::Range(1, 1024));
  sweep_app->add_option("--shard", sweep.shard, "I/N: run rows I, I+N, I+2N, ... of the sweep");
  sweep_app->add_flag("--resume", sweep.resume,
                      "finish the CSV at --csv PATH: keep its rows, run the missing ones");
  sweep_app->add_flag("--force", sweep.force,
                      "replace the file at --csv PATH (without it, or --resume, a sweep refuses "
                      "a file that is there and not empty)");
  sweep_app->add_option("--log-level", level, "log level on standard error")
      ->check(CLI::IsMember(levels));

  mdrsim::cli::MergeOptions merge;
  CLI::App* merge_app =
      app.add_subcommand("merge", "join the shards of one sweep into the unsharded CSV");
  merge_app->add_option("out", merge.out, "the merged CSV: PATH, or - for standard output")
      ->required();
  merge_app->add_option("shards", merge.shards, "the shard CSVs (every shard, in any order)")
      ->required();
  merge_app->add_option("--log-level", level, "log level on standard error")
      ->check(CLI::IsMember(levels));

  mdrsim::cli::FitOptions fit;
  CLI::App* fit_app = app.add_subcommand(
      "fit", "fit a contact model to measured force curves (AFM files; docs/afm.md)");
  fit_app->add_option("curves", fit.curves, "measured files (JPK, HDF5, Igor .ibw, CSV/TSV)")
      ->required();
  fit_app
      ->add_option("--tip", fit.tip,
                   "parabolic:radius=R, sphere:radius=R, cone:half_angle_deg=A, "
                   "pyramid:half_angle_deg=A (SI units) or a scene file FILE.toml")
      ->required();
  fit_app->add_option("--model", fit.model, "hertz, dmt, jkr (maugis, auto: not yet)");
  fit_app->add_option("--poisson-ratio", fit.poisson_ratio, "the sample's (default 0.5)");
  fit_app->add_option("--segment", fit.segment, "approach (default), retract or both");
  fit_app->add_option("--range", fit.range,
                      "fit only the samples of indentation FROM:TO [m] from the contact point "
                      "(--range=-1e-7:5e-7 where FROM is negative)");
  fit_app
      ->add_option("--fix", fit.fixes,
                   "hold NAME=VALUE (youngs_modulus, contact_point, baseline_offset, "
                   "baseline_slope) or override the calibration (spring_constant, sensitivity); "
                   "repeatable")
      ->allow_extra_args(false);
  fit_app->add_option("--json", fit.json,
                      "write one JSON object per curve (an array) to PATH or -");
  fit_app->add_option("--csv", fit.csv, "write one CSV row per curve to PATH or -");
  fit_app->add_option("--plot", fit.plot,
                      "draw PATH.png: one curve with its fit and residuals, or a map's E, "
                      "work of adhesion and residual (needs python3 with matplotlib)");
  fit.threads = mdrsim::available_cpus();
  fit_app
      ->add_option("--threads", fit.threads,
                   "curves fitted in parallel (default: the CPUs this process may use)")
      ->check(CLI::Range(1, 1024));
  fit_app->add_option("--shard", fit.shard, "I/N: fit files I, I+N, I+2N, ... of those given");
  fit_app->add_flag("--resume", fit.resume,
                    "finish the CSV at --csv PATH: keep its rows, fit the curves it lacks");
  fit_app->add_option("--log-level", level, "log level on standard error")
      ->check(CLI::IsMember(levels));

  // A single-valued option given twice takes the later value, as users expect of a command
  // line they append to (CLI11 refuses it by default); --set and --vary collect every one.
  for (CLI::App* sub : {run_app, sweep_app, merge_app, fit_app}) {
    for (CLI::Option* option : sub->get_options()) {
      if (option->get_expected_max() == 1 && !option->get_positional()) {
        option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
      }
    }
  }

  CLI::App* list_app = app.add_subcommand(
      "list", "the registered profiles, criteria, controllers and friction laws, with keys");
  // Set last: a subcommand made after it would inherit it.
  app.footer("`mdrsim list` names every profile, criterion and controller with its keys.");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    if (const auto split = split_set_value(argc, argv)) {
      std::cerr << one_line(*split) << '\n';
      return 2;
    }
    if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-') {
      std::cerr << "mdrsim: unknown command '" << mdrsim::printable(argv[1])
                << "' (known: " << command_names(app) << "; see mdrsim --help)\n";
      return 2;
    }
    if (app.get_subcommands().empty()) {
      std::cerr << "mdrsim: a command is required (" << command_names(app)
                << "), e.g. mdrsim run SCENE.toml; see mdrsim --help\n";
      return 2;
    }
    std::cerr << usage_message(e.what()) << '\n';
    return 2;
  }
  try {
    // An empty PATH (say an unset shell variable) must not silently mean "not given".
    const std::pair<CLI::App*, const char*> path_flags[] = {
        {run_app, "--json"}, {run_app, "--trajectory"}, {sweep_app, "--csv"},
        {fit_app, "--json"}, {fit_app, "--csv"},        {fit_app, "--plot"}};
    for (const auto& [sub, flag] : path_flags) {
      if (sub->parsed() && sub->count(flag) > 0 &&
          sub->get_option(flag)->as<std::string>().empty()) {
        throw mdrsim::cli::UsageError(fmt::format("{}: needs a file path or -", flag));
      }
    }
    if (sweep_app->parsed()) {
      // A --link joins the axis of the --vary before it: their order on the command line.
      std::size_t varies = 0;
      for (const CLI::Option* option : sweep_app->parse_order()) {
        if (option == link_option) {
          sweep.link_after.push_back(varies);
        } else if (option->get_name() == "--vary") {
          ++varies;
        }
      }
    }
    set_up_logging(level);
    if (list_app->parsed()) return mdrsim::cli::list_command();
    if (run_app->parsed()) return mdrsim::cli::run_command(run);
    if (merge_app->parsed()) return mdrsim::cli::merge_command(merge);
    if (fit_app->parsed()) return mdrsim::cli::fit_command(fit);
    return mdrsim::cli::sweep_command(sweep);
  } catch (const mdrsim::SceneError& e) {
    std::cerr << one_line(e.what()) << '\n';
    return 2;
  } catch (const mdrsim::cli::UsageError& e) {
    std::cerr << one_line(e.what()) << '\n';
    return 2;
  } catch (const mdrsim::cli::StandardOutputClosed&) {
    return 128 + SIGPIPE;
  } catch (const mdrsim::cli::WriteError& e) {
    std::cerr << "mdrsim: " << one_line(e.what()) << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "mdrsim: internal error: " << one_line(e.what()) << '\n';
    return 1;
  } catch (...) {
    std::cerr << "mdrsim: internal error\n";
    return 1;
  }
}
