// view_script.cc: see view_script.h. A line is read word by word; each command checks its
// argument; the whole file is checked before the window opens.
#include "sim/view/view_script.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/io/csv_cells.h"
#include "sim/view/live_session.h"

namespace pamsim {
namespace {

constexpr double kMaxWaitS = 60.0;

const std::map<std::string, ScriptCommand> kCommands = {{"pause", ScriptCommand::kPause},
                                                        {"play", ScriptCommand::kPlay},
                                                        {"step", ScriptCommand::kStep},
                                                        {"slow", ScriptCommand::kSlow},
                                                        {"restart", ScriptCommand::kRestart},
                                                        {"drop", ScriptCommand::kDrop},
                                                        {"reflex", ScriptCommand::kReflex},
                                                        {"set", ScriptCommand::kSet},
                                                        {"screenshot", ScriptCommand::kScreenshot},
                                                        {"wait", ScriptCommand::kWait},
                                                        {"close", ScriptCommand::kClose}};

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
  throw InputError(where + ": " + problem);
}

double number_of(const std::string& where, const std::string& word, const std::string& what) {
  double v = 0.0;
  if (!parse_finite_cell(word, &v))
    fail(where, what + " must be a finite number, got '" + word + "'");
  return v;
}

// step's N or restart's SEED, optional: a whole number
void read_count_or_seed(const std::vector<std::string>& words, ScriptLine* line) {
  const bool step = line->command == ScriptCommand::kStep;
  if (words.size() > 1) fail(line->where, step ? "expected step [N]" : "expected restart [SEED]");
  if (words.empty()) return;
  line->number = number_of(line->where, words[0], step ? "N" : "SEED");
  line->has_number = true;
  const bool whole = line->number == std::floor(line->number);
  if (!whole || line->number < (step ? 1 : 0) || line->number > 1e9) {
    fail(line->where, std::string(step ? "N must be a whole number in [1, 1e9]"
                                       : "SEED must be a whole number in [0, 1e9]") +
                          ", got '" + words[0] + "'");
  }
}

// the argument of `line.command`, checked; `words` after the time and the command
void read_argument(const std::vector<std::string>& words, const LiveSession& session,
                   ScriptLine* line) {
  const std::string& where = line->where;
  const auto count = [&](std::size_t lo, std::size_t hi, const char* usage) {
    if (words.size() < lo || words.size() > hi) fail(where, std::string("expected ") + usage);
  };
  switch (line->command) {
    case ScriptCommand::kStep:
    case ScriptCommand::kRestart:
      read_count_or_seed(words, line);
      break;
    case ScriptCommand::kSlow:
      count(1, 1, "slow <1|2|4|8|16>");
      line->number = number_of(where, words[0], "the divisor");
      if (line->number != 1 && line->number != 2 && line->number != 4 && line->number != 8 &&
          line->number != 16) {
        fail(where, "slow takes 1, 2, 4, 8 or 16, got '" + words[0] + "'");
      }
      break;
    case ScriptCommand::kReflex:
      count(1, 1, "reflex <on|off>");
      if (words[0] != "on" && words[0] != "off")
        fail(where, "reflex takes on or off, got '" + words[0] + "'");
      line->on = words[0] == "on";
      break;
    case ScriptCommand::kSet:
      count(2, 2, "set <KEY> <VALUE>");
      line->text = words[0];
      line->number = number_of(where, words[1], "VALUE");
      session.check_setting(line->text, line->number, where);
      break;
    case ScriptCommand::kScreenshot: {
      count(1, 1, "screenshot <FILE.png>");
      line->text = words[0];
      const std::filesystem::path file(line->text);
      if (file.extension() != ".png")
        fail(where, "a screenshot is a .png file, got '" + words[0] + "'");
      const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
      if (!std::filesystem::is_directory(folder))
        fail(where, "no folder " + folder.string() + " for the screenshot");
      break;
    }
    case ScriptCommand::kWait:
      count(1, 1, "wait <SECONDS>");
      line->number = number_of(where, words[0], "SECONDS");
      if (!(line->number > 0 && line->number <= kMaxWaitS)) {
        fail(where, "wait takes (0, 60] seconds, got '" + words[0] + "'");
      }
      break;
    default:
      count(0, 0, "no argument");
  }
}

}  // namespace

std::vector<ScriptLine> read_view_script(const std::string& path, const LiveSession& session) {
  std::istringstream in(read_text_file(path));
  std::vector<ScriptLine> lines;
  std::string text;
  double last_s = 0.0;
  for (int number = 1; std::getline(in, text); ++number) {
    text = text.substr(0, text.find('#'));
    std::istringstream words_in(text);
    std::vector<std::string> words;
    for (std::string w; words_in >> w;) words.push_back(w);
    if (words.empty()) continue;
    ScriptLine line;
    line.where = path + ":" + std::to_string(number);
    if (words.size() < 2) fail(line.where, "expected <time_s> <command> [argument]");
    line.at_s = number_of(line.where, words[0], "the time");
    if (line.at_s < 0) fail(line.where, "the time must be >= 0, got '" + words[0] + "'");
    if (line.at_s < last_s) {
      fail(line.where, "the time " + words[0] +
                           " is before the line above's (times never decrease "
                           "but after a restart)");
    }
    const auto command = kCommands.find(words[1]);
    if (command == kCommands.end()) {
      fail(line.where, "unknown command '" + words[1] +
                           "' (pause, play, step, slow, restart, drop, reflex, set, screenshot, "
                           "wait, close)");
    }
    line.command = command->second;
    read_argument(std::vector<std::string>(words.begin() + 2, words.end()), session, &line);
    last_s = line.command == ScriptCommand::kRestart ? 0.0 : line.at_s;
    lines.push_back(line);
  }
  return lines;
}

}  // namespace pamsim
