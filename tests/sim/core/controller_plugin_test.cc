// controller_plugin_test.cc: a controller kind is one file. The kind "constant_command" is
// defined entirely in this test and touches no other source file: its name, its key
// constant_command.MPa (read, validated, documented), its summary field and its factory,
// registered by name with a ControllerRegistrar. A scenario chooses it with
// controller.kind; its commands reach the valves (the log's p_cmd columns) and the
// chambers deflate; a bad value of its key is refused naming the file and the key; the
// registry's names are the ones controller.kind's message lists.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "base/units.h"
#include "reflex/controller_registry.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// Every muscle's valve is commanded one constant pressure, whatever the schedules say.
class ConstantCommandController final : public Controller {
 public:
  explicit ConstantCommandController(double pressure_pa) : pressure_pa_(pressure_pa) {}
  void update(const ControlInput& in, ControlOutput* out) override {
    for (std::size_t j = 0; j < in.readings->size(); ++j) {
      out->p_cmd_pa[j] = in.enabled ? pressure_pa_ : (*in.p_tp_pa)[j];
      out->velocity_m_s[j] = (*in.readings)[j].velocity_est_m_s;
      // its own channel: how far its command is above the schedule's [MPa]
      out->channels[0][j] = units::pa_to_mpa(out->p_cmd_pa[j] - (*in.p_tp_pa)[j]);
    }
  }

 private:
  double pressure_pa_;
};

class ConstantCommandConfig final : public ControllerConfig {
 public:
  double pressure_pa = 0.0;  // constant_command.MPa
  std::vector<SummaryField> summary_fields() const override {
    return {{"constant_command_MPa", units::pa_to_mpa(pressure_pa)}};
  }
  std::unique_ptr<Controller> make_controller(const ControllerSetup&) const override {
    return std::make_unique<ConstantCommandController>(pressure_pa);
  }
  // the log's column above_schedule_<m>_MPa, declared here and nowhere else
  std::vector<ControllerChannel> channels() const override {
    return {{"above_schedule_", "_MPa", "its command less the schedule's", false, ""}};
  }
};

ControllerKind constant_command_kind() {
  ControllerKind kind;
  kind.name = "constant_command";
  kind.sections = {"constant_command"};
  kind.read = [](ConfigReader& in, const ControllerScenario& sc) {
    auto config = std::make_shared<ConstantCommandConfig>();
    const double mpa = in.get_double("constant_command.MPa", 0.0);
    const double max_mpa = units::pa_to_mpa(sc.command_max_pa);
    in.check(mpa >= 0.0 && mpa <= max_mpa, "constant_command.MPa",
             "must be within [0, " + format_value(max_mpa) + "], got " + format_value(mpa));
    config->pressure_pa = units::mpa_to_pa(mpa);
    return std::shared_ptr<const ControllerConfig>(config);
  };
  kind.docs = {{"constant_command.MPa", "MPa", "0.0", "[0, valve.command_max_MPa]",
                "the pressure every valve is commanded"}};
  return kind;
}

const ControllerRegistrar kRegistered{constant_command_kind()};

const std::string kReaching = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/reaching.toml";

// reaching.toml (agonist at 0.2 MPa, antagonist at 0.6 MPa until t = 2 s) with its
// controller.kind = "none" replaced by `kind`, and `extra` appended
std::string reaching_text(const std::string& kind, const std::string& extra = "") {
  std::ifstream in(kReaching);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string none = "[controller]\nkind = \"none\"";
  const std::size_t at = s.find(none);
  EXPECT_NE(at, std::string::npos);
  s.replace(at, none.size(), "[controller]\nkind = \"" + kind + "\"");
  return s + "\n" + extra;
}

Scenario load(const std::string& kind, const std::string& extra = "") {
  return load_scenario_text(reaching_text(kind, extra), kReaching, {"sim.duration_s=2.0"});
}

TrialResult run(const Scenario& sc) {
  const TrialModel model = load_trial_model(sc);
  return run_trial(model, sc, sc.seed);
}

std::string error_of(const std::string& kind, const std::string& extra = "") {
  try {
    load(kind, extra);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ControllerPlugin, RegisteredAfterTheBuiltInKinds) {
  ASSERT_NE(find_controller_kind("constant_command"), nullptr);
  ASSERT_EQ(controller_kinds().back().name, "constant_command");
  // a plug-in's kind is one of controller.kind's allowed names, as the built-in ones are
  EXPECT_EQ(error_of("bang_bang"),
            kReaching +
                ": controller.kind is \"bang_bang\", allowed \"none\" | "
                "\"stretch_reflex\" | \"tension_reflex\" | \"stretch_tension_reflex\" | "
                "\"constant_command\"");
}

TEST(ControllerPlugin, AScenarioChoosesItAndItsCommandsDriveTheValves) {
  const TrialResult none = run(load("none"));
  const TrialResult zero = run(load("constant_command", "[constant_command]\nMPa = 0.0\n"));
  ASSERT_EQ(none.summary.status, "ok");
  ASSERT_EQ(zero.summary.status, "ok");
  const Trajectory& a = none.trajectory;
  const Trajectory& b = zero.trajectory;
  const std::size_t last = b.rows() - 1;
  // its command is logged; pass-through logs the schedule
  EXPECT_EQ(b.at(last, b.column("p_cmd_ago_MPa")), 0.0);
  EXPECT_EQ(b.at(last, b.column("p_cmd_anta_MPa")), 0.0);
  EXPECT_NEAR(a.at(last, a.column("p_cmd_anta_MPa")), 0.6, 1e-9);
  // the chambers deflate, and the arm goes elsewhere
  EXPECT_LT(b.at(last, b.column("p_anta_MPa")), 0.05);
  EXPECT_GT(a.at(last, a.column("p_anta_MPa")), 0.55);
  EXPECT_GT(std::fabs(b.at(last, b.column("angle_deg")) - a.at(last, a.column("angle_deg"))), 1.0);
  // no reflex, no reflex columns; its own channel, logged as it declares it
  EXPECT_FALSE(b.has_column("reflex_ago"));
  EXPECT_FALSE(a.has_column("above_schedule_anta_MPa"));
  EXPECT_NEAR(b.at(last, b.column("above_schedule_anta_MPa")), -0.6, 1e-9);
  EXPECT_NEAR(b.at(0, b.column("above_schedule_ago_MPa")), -0.2, 1e-9);
}

TEST(ControllerPlugin, WithoutAnEmbeddedFormItIsNotExportedAndSaysSoInOneLine) {
  // the built-in kinds have one (pamsim controller export); this kind has none
  const Scenario none = load("none");
  const Scenario plugin = load("constant_command", "[constant_command]\nMPa = 0.0\n");
  pamctl_config config{};
  EXPECT_EQ(embedded_controller_config(load_trial_model(none), none, &config), "");
  EXPECT_EQ(config.kind, PAMCTL_KIND_PASS_THROUGH);
  const std::string why = embedded_controller_config(load_trial_model(plugin), plugin, &config);
  EXPECT_NE(why.find("no embedded form"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos);
}

TEST(ControllerPlugin, ItsSummaryFieldAndNameGoToSummaryJson) {
  const Scenario sc = load("constant_command", "[constant_command]\nMPa = 0.25\n");
  TrialSummary summary;
  const nlohmann::json j = summary_to_json(summary, sc, false);
  EXPECT_EQ(j["scenario"]["controller"], "constant_command");
  EXPECT_DOUBLE_EQ(j["scenario"]["constant_command_MPa"].get<double>(), 0.25);
}

TEST(ControllerPlugin, ItsKeyIsValidatedNamingTheFileAndTheKey) {
  // (the value as written, as the message echoes it)
  for (const auto& [bad, echoed] :
       {std::pair{"-0.1", "got -0.1"}, std::pair{"5.0", "got 5"}, std::pair{"nan", "got nan"}}) {
    const std::string message =
        error_of("constant_command", std::string("[constant_command]\nMPa = ") + bad + "\n");
    EXPECT_EQ(message.rfind(kReaching + ": constant_command.MPa must be ", 0), 0u) << message;
    EXPECT_NE(message.find(echoed), std::string::npos) << message;
  }
  // its section with another kind is refused, like [reflex] with "none"
  EXPECT_EQ(error_of("none", "[constant_command]\nMPa = 0.1\n"),
            kReaching +
                ": constant_command is the constant_command controller's section, but "
                "controller.kind is \"none\"");
}

}  // namespace
}  // namespace pamsim
