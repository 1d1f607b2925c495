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
            "a041bbc92665969d5d43e7ba37f7d1f3bbe10fc57673e234cf6e27b859c9cec8");
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass_fiber.toml", shorter)),
            "e9e1eb7098de632181053665c2c2951c1649076d1a40ddc491884f3057750ad4");
  EXPECT_EQ(sha256_hex(trajectory_csv_of("drop_mass_passive.toml", shorter)),
            "47cdbad070850d32bd64593a5864af3a4444fdb636d8b542f75e7ada62eac7a2");
}

}  // namespace
}  // namespace pamsim
