// cli_sweep_bad_input_test.cc: `pamsim sweep` on bad sweep files: unknown keys, empty or
// malformed axes, bad counts and designs, a base or a point that fails, counts that would
// overflow or exhaust memory; each is one line naming the file and the problem, exit 2, and
// no database.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/sweep_process.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::run_pamsim;
using pamsim_test::short_sweep;
using pamsim_test::write_text;

// `n` grid axes of two levels each (2^n points); the keys are never reached when the size is
// refused first.
std::string many_axes(int n) {
  std::string text;
  for (int i = 0; i < n; ++i) {
    text +=
        "[[axis]]\nkey = \"reflex.v_thr_mm_s_" + std::to_string(i) + "\"\nvalues = [1.0, 2.0]\n";
  }
  return text;
}

// --- a bad sweep file: one line naming it and the problem, exit 2, no database ---

struct BadSweepFile {
  const char* name;
  std::string text;
  const char* message;  // expected in the error line
};

std::vector<BadSweepFile> bad_sweep_files() {
  const std::string axis = "[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, 70.0]\n";
  return {

      {"unknown_key", short_sweep("seedz = 2\n" + axis), "seedz"},
      {"unknown_axis_key", short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalue = [1.0]\n"),
       "axis[0].value"},
      {"empty_axis", short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = []\n"),
       "axis[0].values is empty"},
      {"zero_count",
       short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nfrom = 1.0\nto = 2.0\n"
                   "count = 0\n"),
       "axis[0].count must be in [1, inf), got 0"},
      {"negative_seeds", short_sweep("seeds = -1\n" + axis), "seeds must be in [1, "},
      {"no_axis", short_sweep(""), "axis is required"},
      {"nan_value", short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [nan]\n"),
       "must be finite"},
      {"log_from_zero",
       short_sweep("[[axis]]\nkey = \"reflex.k_MPa_s_per_mm\"\nfrom = 0.0\n"
                   "to = 1.0\ncount = 3\nscale = \"log\"\n"),
       "log scale"},
      {"unknown_design", short_sweep("design = \"sobol\"\n" + axis),
       "design is \"sobol\", allowed \"grid\" | \"random\" | \"lhs\""},
      {"lhs_without_samples",
       short_sweep("design = \"lhs\"\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\n"
                   "from = 1.0\nto = 2.0\n"),
       "samples is required for a lhs design"},
      {"base_fails", short_sweep("[fixed.reflex]\nduration_s = -1.0\n" + axis), "base scenario"},
      {"point_fails", short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nvalues = [50.0, -5.0]\n"),
       "point 1"},
      {"unknown_scenario_key", short_sweep("[[axis]]\nkey = \"reflex.v_thr\"\nvalues = [50.0]\n"),
       "reflex.v_thr"},
      {"missing_base", "base = \"nowhere.toml\"\n" + axis, "nowhere.toml"},
      // a point that does not bind to its model (caught before the run, not as failed rows)
      {"point_unbound",
       short_sweep("[[axis]]\nkey = \"model.joint\"\n"
                   "values = [\"shoulder\", \"elbow\"]\n"),
       "point 1"},
      // counts that overflow, wrap or exhaust memory are refused before anything is made
      {"seeds_near_2_63", short_sweep("seeds = 9223372036854775807\n" + axis),
       "seeds must be in [1, 1000000000000]"},
      {"huge_count",
       short_sweep("[[axis]]\nkey = \"reflex.v_thr_mm_s\"\nfrom = 1.0\n"
                   "to = 2.0\ncount = 1000000000000\n"),
       "axis[0].count"},
      {"grid_wraps_to_zero", short_sweep(many_axes(64)), "max_trials is 1000000, fewer than"},
      {"grid_times_seeds", short_sweep("seeds = 1000\n" + many_axes(10)), "x 1000 seeds"},
      {"huge_samples",
       short_sweep("design = \"random\"\nsamples = 4611686018427387904\n"
                   "seeds = 4\n[[axis]]\nkey = \"reflex.v_thr_mm_s\"\n"
                   "from = 1.0\nto = 2.0\n"),
       "samples"},
      {"zero_max_trials", short_sweep("max_trials = 0\n" + axis), "max_trials must be in [1, "},
  };
}

TEST(CliSweepTest, BadSweepFilesFailWithOneLineAndNoDatabase) {
  const fs::path dir = fresh_dir("sweep_bad");
  for (const BadSweepFile& c : bad_sweep_files()) {
    const fs::path file = dir / (std::string(c.name) + ".toml");
    write_text(file, c.text);
    const fs::path out = dir / (std::string(c.name) + "_out");
    const auto r = run_pamsim("sweep " + file.string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out / "sweep.db")) << c.name;
  }
  const auto missing = run_pamsim("sweep " + (dir / "absent.toml").string());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(line_count(missing.err), 1) << missing.err;
}

}  // namespace
