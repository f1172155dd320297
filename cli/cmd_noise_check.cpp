// `curvbench noise-check [--output FILE] [--family F]... [--level L]...`: the noise estimate
// checked against known noise (harness/model/noise_validation.h): every generated family at
// levels 1 and 2, without noise and with normal Gaussian noise sigma = 0.001 h ... 0.1 h, the
// estimated against the true sigma/h. Writes the CSV and prints the Markdown table
// (docs/robustness.md, "The noise estimate", holds its output).
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "core/atomic_file.h"
#include "harness/model/noise_validation.h"

namespace curvbench::cli {

Command add_noise_check_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "noise-check",
      "Check the noise estimate (recommend, info) against known normal Gaussian noise on every "
      "generated family: write the estimated and true sigma/h as CSV and print them as a "
      "Markdown table");
  struct Options {
    std::string output = "results/noise_estimate.csv";
    NoiseCheckSpec spec;
  };
  auto o = std::make_shared<Options>();
  sub->add_option("--output", o->output, "CSV file to write")->capture_default_str();
  sub->add_option("--family", o->spec.families, "Families to check (default: every one)");
  sub->add_option("--level", o->spec.levels, "Mesh levels (default: 1 2)");
  return [o]() {
    const auto rows = noise_check(o->spec);
    write_file_atomic(o->output, noise_check_csv(rows));
    std::fputs(noise_check_markdown(rows).c_str(), stdout);
    int out = 0;
    for (const NoiseCheckRow& r : rows) out += !r.within;
    std::printf("\n%s: %zu rows, %d outside the tolerance\n", o->output.c_str(), rows.size(), out);
    return 0;
  };
}

}  // namespace curvbench::cli
