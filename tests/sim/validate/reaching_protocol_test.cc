// reaching_protocol_test.cc: a reaching protocol file with a `base` (reaching_protocol.cc):
// the shipped PE braid protocol reads as its base with the fishing lines and the brackets it
// names replaced in place; a layer's keys replace the base's; a base with a base, a bracket
// that repeats a base's key under another name and an unknown key are refused by key.
#include <gtest/gtest.h>

#include <string>

#include "base/input_error.h"
#include "sim/cli_util.h"
#include "sim/test_paths.h"
#include "sim/validate/reaching.h"

namespace pamsim {
namespace {

using pamsim_test::kScenarios;

const Bracket& named(const std::vector<Bracket>& brackets, const std::string& name) {
  for (const Bracket& b : brackets) {
    if (b.name == name) return b;
  }
  throw std::runtime_error("no bracket " + name);
}

TEST(ReachingProtocolTest, ThePeBraidProtocolIsItsBaseWithTheLinesReplaced) {
  const ReachingValidationSpec nylon =
      load_reaching_validation(kScenarios + "validate_reaching.toml");
  const ReachingValidationSpec pe =
      load_reaching_validation(kScenarios + "validate_reaching_pe_braid.toml");
  EXPECT_EQ(pe.scenario_file, nylon.scenario_file);
  EXPECT_EQ(pe.trials, nylon.trials);
  EXPECT_EQ(pe.window_end_s, nylon.window_end_s);
  EXPECT_EQ(pe.paper.size(), nylon.paper.size());
  EXPECT_EQ(pe.bracket_seed, nylon.bracket_seed);
  ASSERT_EQ(pe.budget.size(), nylon.budget.size());
  ASSERT_EQ(pe.brackets.size(), nylon.brackets.size());
  for (std::size_t k = 0; k < pe.brackets.size(); ++k) {
    EXPECT_EQ(pe.brackets[k].name, nylon.brackets[k].name) << "replaced in place";
    EXPECT_EQ(pe.brackets[k].key, nylon.brackets[k].key);
  }
  EXPECT_EQ(named(pe.brackets, "agonist line modulus").from, 53000.0);
  EXPECT_EQ(named(pe.brackets, "antagonist line creep").to, 0.05);
  EXPECT_EQ(named(pe.brackets, "board creep").to, named(nylon.brackets, "board creep").to);
  EXPECT_EQ(named(pe.brackets, "agonist line creep time").to, 100.0) << "the base's";
  EXPECT_EQ(pe.budget.back().name, "fishing lines");
  EXPECT_NE(pe.budget.back().on.at(1).find("=84000"), std::string::npos);
}

TEST(ReachingProtocolTest, ALayersOwnKeysWinAndBadLayersAreRefusedByKey) {
  const auto dir = pamsim_test::fresh_dir("reaching_protocol_layers");
  const std::string base = "base = \"" + kScenarios + "validate_reaching.toml\"\n";
  pamsim_test::write_text(dir / "a.toml", base +
                                              "trials = 2\nbracket_seed = 7\n[paper]\n"
                                              "model_agonist = [1.0, 0.5]\n");
  const ReachingValidationSpec a = load_reaching_validation((dir / "a.toml").string());
  EXPECT_EQ(a.trials, 2);
  EXPECT_EQ(a.bracket_seed, 7u);
  EXPECT_EQ(a.paper.at("model_agonist").rmse_pct, 0.5);
  EXPECT_EQ(a.paper.at("model_antagonist").rmse_pct, 5.02) << "the base's other cells";
  const auto refused_key = [&](const std::string& name, const std::string& text) {
    pamsim_test::write_text(dir / name, text);
    try {
      load_reaching_validation((dir / name).string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  // a base that has a base itself; a new bracket on a base bracket's key; an unknown key
  const std::string two = refused_key("b.toml", "base = \"a.toml\"\n");
  EXPECT_NE(two.find("a.toml: base"), std::string::npos) << two;
  const std::string again = refused_key(
      "c.toml", base +
                    "[[bracket]]\nname = \"creep again\"\nkey = "
                    "\"sensors.gauge.board.creep_1000h\"\nfrom = 0.0\nto = 0.1\nsource = \"s\"\n");
  EXPECT_NE(again.find("c.toml: bracket"), std::string::npos) << again;
  EXPECT_NE(again.find("board creep"), std::string::npos) << again;
  const std::string unknown = refused_key("d.toml", base + "trails = 3\n");
  EXPECT_NE(unknown.find("trails"), std::string::npos) << unknown;
  std::string many = base;  // 20 new brackets beside the base's 13: over the 32 allowed
  for (int k = 0; k < 20; ++k) {
    many += "[[bracket]]\nname = \"b" + std::to_string(k) + "\"\nkey = \"a.k" + std::to_string(k) +
            "\"\nfrom = 0.0\nto = 1.0\nsource = \"s\"\n";
  }
  const std::string over = refused_key("f.toml", many);
  EXPECT_NE(over.find("f.toml: bracket may hold at most 32 brackets with the base's"),
            std::string::npos)
      << over;
  const std::string missing = refused_key("e.toml", "base = \"nowhere.toml\"\n");
  EXPECT_NE(missing.find("base"), std::string::npos) << missing;
}

}  // namespace
}  // namespace pamsim
