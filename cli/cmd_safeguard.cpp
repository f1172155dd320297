// `curvbench safeguard-fires [--output FILE]`: where the safeguarded QR's condition test cuts a
// stencil (harness/run/safeguard_fires.h): LHF-4 and LSCM-4 on both bumps at levels 1-4, the vertices
// whose first stencil it cuts, with the condition numbers. `make experiments` writes
// results/diag-safeguard-fires.csv with it.
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "core/atomic_file.h"
#include "harness/run/safeguard_fires.h"

namespace curvbench::cli {

Command add_safeguard_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "safeguard-fires",
      "Write the vertices whose stencil the safeguarded QR's condition test cuts (LHF-4, LSCM-4, "
      "both bumps, levels 1-4) with the condition numbers, as CSV");
  auto output = std::make_shared<std::string>("results/diag-safeguard-fires.csv");
  sub->add_option("--output", *output, "CSV file to write")->capture_default_str();
  return [output]() {
    const auto rows = safeguard_fires(default_safeguard_fire_cases());
    write_file_atomic(*output, safeguard_fires_csv(rows));
    int fired = 0;
    for (const SafeguardFire& f : rows) fired += f.vertex >= 0;
    std::printf("%s: %d stencils cut by the condition test\n", output->c_str(), fired);
    return 0;
  };
}

}  // namespace curvbench::cli
