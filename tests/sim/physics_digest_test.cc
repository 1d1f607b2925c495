// physics_digest_test.cc: pinned SHA-256 digests of short trials' trajectory.csv, so a change
// that alters the physics, the sensors' noise stream or the log's columns is seen. A
// deliberate change updates the digests here and says in its commit which outputs changed
// and why. Pinned from pamsim d4f8802 (before the experiment-agnostic core) with
//   pamsim run scenarios/<file> --set sim.duration_s=1.5 drop.time_s=0.3
// and sha256sum of the trajectory.csv it wrote; the core must reproduce them byte for byte.
// Re-pinned when the drop scenarios moved to physical plants, fitted estimators and the
// closed-loop regulator (issue 12); drop_mass_ideal.toml keeps drop_mass.toml's old pin.
#include <gtest/gtest.h>

extern "C" {
#include <libavutil/mem.h>
#include <libavutil/sha.h>
}

#include <cstdio>
#include <memory>
#include <string>

#include "sim/core/runner.h"
#include "sim/io/outputs.h"
#include "sim/io/scenario_file.h"

namespace pamsim {
namespace {

std::string sha256_hex(const std::string& text) {
  std::unique_ptr<AVSHA, decltype(&av_free)> sha(av_sha_alloc(), &av_free);
  av_sha_init(sha.get(), 256);
  av_sha_update(sha.get(), reinterpret_cast<const uint8_t*>(text.data()), text.size());
  uint8_t digest[32];
  av_sha_final(sha.get(), digest);
  std::string hex;
  char byte[3];
  for (uint8_t b : digest) {
    std::snprintf(byte, sizeof(byte), "%02x", b);
    hex += byte;
  }
  return hex;
}

std::string trajectory_csv_of(const std::string& scenario, std::vector<std::string> overrides) {
  const Scenario sc =
      load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/" + scenario, overrides);
  const TrialModel model = load_trial_model(sc);
  const TrialResult r = run_trial(model, sc, sc.seed);
  EXPECT_EQ(r.summary.status, "ok") << r.summary.message;
  return trajectory_to_csv(r.trajectory);
}

TEST(PhysicsDigestTest, Sha256OfAKnownTextIsTheStandardOne) {
  // FIPS 180-2 test vector: the digest function itself is right
  EXPECT_EQ(sha256_hex("abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(PhysicsDigestTest, ShortDropTrialsAreUnchanged) {
  const std::vector<std::string> shorter = {"sim.duration_s=1.5", "drop.time_s=0.3"};
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass.toml", shorter)),
            "cbb76abe38249b9e417da4502698f9f1d4e5ab002275d9179daa6b8e05595ebb");
  // the ideal plant is pamsim 0.2's drop_mass.toml, byte for byte
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass_ideal.toml", shorter)),
            "fc8ec3d114e7539a69a48fe3521ac6a9e71512a59036a94b3fd7ab62b3e98781");
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass_fiber.toml", shorter)),
            "1828a17bd2b139843c5e7d11853b1c8eb2de267ca2b677ae266db3c55b9996fc");
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass_passive.toml", shorter)),
            "d81352ff8c20f2d40afafd8551d97e0d5815b3c3f1b946a2fb87c3f27ec691be");
}

}  // namespace
}  // namespace pamsim
