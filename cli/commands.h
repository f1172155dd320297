// Subcommands of the `curvbench` executable. Each registers itself on the CLI11 app and returns
// the callback run when it is selected; cli/main.cpp maps exceptions to exit codes
// (InputError/UsageError -> 2, anything else -> 1).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "mesh/io.h"
#include "mesh/mesh.h"

namespace curvbench::cli {

using Command = std::function<int()>;

Command add_info_command(CLI::App& app);
Command add_mesh_command(CLI::App& app);
Command add_estimate_command(CLI::App& app);
Command add_run_command(CLI::App& app);
Command add_score_command(CLI::App& app);
Command add_methods_command(CLI::App& app);
Command add_recommend_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_safeguard_command(CLI::App& app);
Command add_noise_check_command(CLI::App& app);

/// Reads the mesh a command was given (read_mesh with --skip-invalid as `skip_invalid`), printing
/// each read warning (dropped faces, skipped vertices) to stderr as "curvbench: warning: ...".
Mesh read_input_mesh(const std::string& path, bool skip_invalid, MeshReadReport& report);

}  // namespace curvbench::cli
