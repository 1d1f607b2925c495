// view_script.h: `pamsim view --script FILE`: the key presses and slider moves of a session,
// timed, read from a file: how the tests drive the viewer and how a lab replays a
// demonstration. One command per line, `#` starts a comment:
//
//   <time_s> <command> [argument]
//
// A line runs once the trial's clock (simulated time) has reached its time, in file order;
// times never decrease, except that the lines after a `restart` count from the new trial's
// start. While the trial is paused its clock stands still, so only lines at or before the
// paused time run (`step` moves it on). Commands:
//   pause | play               stop and go on (the space key)
//   step [N]                   N control periods while paused (default 1; the right arrow)
//   slow <1|2|4|8|16>          real time divided by this (1: real time)
//   restart [SEED]             the trial again from t = 0 (default: the same seed)
//   drop                       the mass drops now (the D key)
//   reflex <on|off>            the controller on or off (the R key)
//   set <KEY> <VALUE>          a controller setting, in the key's unit (a slider)
//   screenshot <FILE.png>      the window as a PNG, written atomically
//   wait <SECONDS>             the window keeps drawing, the script waits (wall clock, <= 60)
//   close                      the window closes (as its close button)
// Errors name the file and line: "<file>:<line>: <problem>".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pamsim {

class LiveSession;

enum class ScriptCommand {
  kPause,
  kPlay,
  kStep,
  kSlow,
  kRestart,
  kDrop,
  kReflex,
  kSet,
  kScreenshot,
  kWait,
  kClose
};

struct ScriptLine {
  std::string where;  // "<file>:<line>"
  double at_s = 0.0;
  ScriptCommand command = ScriptCommand::kPause;
  double number = 0.0;  // step's N, slow's divisor, restart's seed, set's value, wait's seconds
  bool has_number = false;
  bool on = false;   // reflex on
  std::string text;  // set's key, screenshot's file
};

// The lines of `path`, each checked (a setting's key and value against `session`'s
// controller, a screenshot's folder exists). Throws InputError "<file>:<line>: <problem>".
std::vector<ScriptLine> read_view_script(const std::string& path, const LiveSession& session);

}  // namespace pamsim
