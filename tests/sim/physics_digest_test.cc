// physics_digest_test.cc: pinned SHA-256 digests of short trials' trajectory.csv, so a change
// that alters the physics, the sensors' noise stream or the log's columns is seen. A
// deliberate change updates the digests here and says in its commit which outputs changed
// and why. Pinned from pamsim d4f8802 (before the experiment-agnostic core) with
//   pamsim run scenarios/<file> --set sim.duration_s=1.5 drop.time_s=0.3
// and sha256sum of the trajectory.csv it wrote; the core must reproduce them byte for byte.
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
            "fc8ec3d114e7539a69a48fe3521ac6a9e71512a59036a94b3fd7ab62b3e98781");
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass_fiber.toml", shorter)),
            "c34492d48027bb3e6c38d04039ee8262dce134aa66505f26d1ea6d5e96795b18");
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass_passive.toml", shorter)),
            "5db84b1162163e78a296a5b239397fcdd263ecb207883bd7f05b52d7a15251c1");
}

}  // namespace
}  // namespace pamsim
