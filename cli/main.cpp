// curvbench: normals and curvatures on triangle meshes (the local polynomial fits of Wang, Jiao
// et al., CAGD 2009, CGAL's jet fitting and the common discrete operators), and the paper's
// convergence studies.
//
// Exit codes: 0 success, 2 bad usage or bad input, 1 internal failure.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <map>
#include <string>

#include "cli/commands.h"
#include "core/build_info.h"
#include "core/errors.h"

int main(int argc, char** argv) {
  using namespace curvbench;
  CLI::App app{
      "curvbench: normals and curvatures of triangle meshes with 14 estimators (the local\n"
      "polynomial fits LHF, LOP, Xu and LSCM of Wang, Jiao et al., CAGD 2009; CGAL's jet\n"
      "fitting; the discrete operators of Meyer, Taubin, Rusinkiewicz, libigl's quadric,\n"
      "Goldfeather, the normal cycle and the interpolated corrected curvature measures:\n"
      "`curvbench methods`), and the paper's convergence\n"
      "studies."};
  app.set_version_flag("--version", build_info());
  app.require_subcommand(1);

  std::map<const CLI::App*, cli::Command> commands;
  auto add = [&](cli::Command (*adder)(CLI::App&)) {
    const size_t before = app.get_subcommands({}).size();
    cli::Command cmd = adder(app);
    auto subs = app.get_subcommands({});
    if (subs.size() > before) commands[subs.back()] = std::move(cmd);
  };
  add(&cli::add_info_command);
  add(&cli::add_mesh_command);
  add(&cli::add_estimate_command);
  add(&cli::add_run_command);
  add(&cli::add_score_command);
  add(&cli::add_methods_command);
  add(&cli::add_recommend_command);
  add(&cli::add_report_command);
  add(&cli::add_safeguard_command);
  add(&cli::add_noise_check_command);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, cmd] : commands)
      if (sub->parsed()) return cmd();
    return 2;
  } catch (const InputError& e) {
    std::cerr << "curvbench: error: " << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "curvbench: usage error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "curvbench: internal error: " << e.what() << "\n";
    return 1;
  }
}
