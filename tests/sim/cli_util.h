// cli_util.h: running the real `pamsim` binary from a test, as a user would from the source
// folder, with its exit code, stderr and (optionally) stdout captured; and fresh temp folders.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>

namespace pamsim_test {

// --set overrides that make the drop_mass trial short: 1.5 s, the mass dropped at 0.3 s
inline const std::string kShortDrop = " --set sim.duration_s=1.5 drop.time_s=0.3";

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs `pamsim <args>` in the source folder (so scenarios/... paths work), behind `wrapper`
// (a command that runs the rest, e.g. setpriv) if one is given.
inline CliResult run_pamsim(const std::string& args, const std::string& wrapper = "") {
  static int counter = 0;
  const std::string base = ::testing::TempDir() + "pamsim_cli_" + std::to_string(::getpid()) + "_" +
                           std::to_string(counter++);
  const std::string cmd = std::string("cd ") + PAMSIM_SOURCE_DIR + " && " + wrapper + " " +
                          PAMSIM_BINARY + " " + args + " > " + base + ".out 2> " + base + ".err";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(base + ".out");
  r.err = read_file(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

// Every file under `dir` with its bytes (folders as "(folder)"), for before/after checks.
inline std::map<std::string, std::string> folder_snapshot(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    files[std::filesystem::relative(e.path(), dir).string()] =
        e.is_regular_file() ? read_file(e.path()) : "(folder)";
  }
  return files;
}

inline int line_count(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// An empty folder under the test temp folder, unique to this process.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / (name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// `text` as dir/bad.toml, run as `pamsim <command> dir/bad.toml <options> --out dir/out`, is
// refused as bad input must be: exit 2, one line that contains `says`, no output folder.
inline void expect_file_refused(const std::filesystem::path& dir, const std::string& command,
                                const std::string& text, const std::string& options,
                                const std::string& says) {
  SCOPED_TRACE(says);
  write_text(dir / "bad.toml", text);
  const CliResult r = run_pamsim(command + " " + (dir / "bad.toml").string() + " " + options +
                                 " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "nothing written";
}

// A copy of a shipped scenario (scenarios/<name>) in `dir` with `from` replaced by `to` (once;
// a test fails if `from` is not there), its model paths made absolute.
inline std::string scenario_variant(const std::filesystem::path& dir, const std::string& scenario,
                                    const std::string& from, const std::string& to) {
  const std::string source = PAMSIM_SOURCE_DIR;
  std::string text = read_file(source + "/scenarios/" + scenario);
  for (std::size_t at; (at = text.find("\"../models/")) != std::string::npos;) {
    text.replace(at, 11, "\"" + source + "/models/");
  }
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const std::filesystem::path path =
      dir / ("variant_" + std::to_string(std::hash<std::string>{}(to)) + ".toml");
  write_text(path, text);
  return path.string();
}

}  // namespace pamsim_test
