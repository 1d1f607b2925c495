// scenario_hil.cc: the scenario's [hil] table (core/scenario.h: HilSpec), what `pamsim hil`
// does with a controller board's late or lost commands: each key's unit, range, default and
// meaning as one row, read by the scenario's reader and listed by `pamsim keys`.
#include "sim/scenario/scenario_hil.h"

#include <limits>

#include "base/config_reader.h"

namespace pamsim {

KeyTable hil_key_table(HilSpec* hil) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  KeyTable t{"hil", {}, {}, {}};
  t.optional = true;
  t.trial_only = true;
  t.ints = {int_row("hold_ticks",
                    "a command late or lost: the last one is held this many control ticks, "
                    "then the safe command",
                    0, 1000000, &hil->hold_ticks)};
  t.choices = {{"safe_command",
                {"vent", "hold"},
                "after hold_ticks: vent every valve (0 Pa), or hold the last command on",
                [hil](const std::string& v) {
                  hil->safe = v == "hold" ? SafeCommand::kHold : SafeCommand::kVent;
                },
                [hil] { return std::string(hil->safe == SafeCommand::kHold ? "hold" : "vent"); }}};
  t.numbers = {{"command_timeout_ms",
                "ms",
                1e-3,
                {0.0, 60000.0, true, false},
                "lockstep: how long the plant waits for a tick's command before it counts as "
                "lost",
                &hil->command_timeout_s},
               {"link_lost_s",
                "s",
                1.0,
                {0.0, inf, true, true},
                "no packet from the controller for this long (wall clock): the run ends there",
                &hil->link_lost_s}};
  return t;
}

void read_hil(ConfigReader& in, Scenario* sc) { read_key_rows(in, hil_key_table(&sc->hil)); }

}  // namespace pamsim
