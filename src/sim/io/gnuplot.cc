// gnuplot.cc: see gnuplot.h. Each plot is a gnuplot script plus whitespace-separated .dat
// files in a private temp folder; gnuplot runs there and writes a temp PNG next to the
// target, which is checked whole and then renamed into place.
#include "sim/io/gnuplot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <memory>
#include <regex>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "sim/io/temp_path.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// unique temp names across threads of this process
std::atomic<unsigned long> g_plot_counter{0};

// a POSIX shell single-quoted word
std::string sh_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

}  // namespace

std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return "";
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) dir = ".";
    const std::string candidate = dir + "/gnuplot";
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
  }
  return "";
}

namespace {

// a private folder under the system temp folder, removed with everything in it
class TempDir {
 public:
  explicit TempDir(const std::string& png_path) {
    std::error_code ec;
    const fs::path base = fs::temp_directory_path(ec);
    if (ec)
      throw std::runtime_error(png_path + ": no temp folder for gnuplot (" + ec.message() + ")");
    for (int attempt = 0; attempt < 100; ++attempt) {
      const fs::path p = base / ("pamsim_plot_" + std::to_string(::getpid()) + "_" +
                                 std::to_string(g_plot_counter++));
      if (fs::create_directory(p, ec)) {
        path_ = p;
        return;
      }
      if (ec) break;
    }
    throw std::runtime_error(png_path + ": cannot create a temp folder in " + base.string() +
                             (ec ? " (" + ec.message() + ")" : ""));
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// the line of gnuplot's stderr that says what went wrong
std::string first_error_line(const std::string& err) {
  static const std::regex located(R"("[^"]*" line [0-9]+: .*)");
  std::stringstream lines(err);
  std::string line, first;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto b = line.find_first_not_of(" \t");
    if (b == std::string::npos) continue;
    line = line.substr(b);
    if (std::regex_match(line, located)) return line;
    if (first.empty()) first = line;
  }
  return first;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// True if `path` starts with the PNG signature and ends with the IEND chunk (length 0, type,
// CRC): a file cut short by a failed write ends elsewhere.
bool png_is_complete(const std::string& path) {
  static const char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  static const char kIend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', '\xae', '\x42', '\x60', '\x82'};
  std::ifstream in(path, std::ios::binary);
  char head[8], tail[12];
  if (!in.read(head, sizeof(head))) return false;
  in.seekg(-static_cast<std::streamoff>(sizeof(tail)), std::ios::end);
  if (!in.read(tail, sizeof(tail))) return false;
  return std::equal(head, head + 8, kSignature) && std::equal(tail, tail + 12, kIend);
}

}  // namespace

// a gnuplot single-quoted string literal ('' escapes a quote)
std::string gp_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'')
      out += "''";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

// a number for a .dat file or a script; non-finite as "nan" (missing, see set datafile)
std::string gp_num(double v) {
  if (!std::isfinite(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

namespace {

std::mutex g_formats_mutex;
std::vector<std::string> g_extra_formats;  // set_extra_plot_formats

std::vector<std::string> extra_formats() {
  const std::lock_guard<std::mutex> lock(g_formats_mutex);
  return g_extra_formats;
}

// The file's last bytes, whitespace trimmed, end with `tail`.
bool ends_with_text(const std::string& path, const std::string& tail) {
  std::string text = read_text(path);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text.size() >= tail.size() &&
         text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// Draws `job` with `terminal` into a temp file beside `path`, checked whole by `complete`,
// and returns it (the caller renames it into place); throws std::runtime_error naming `path`.
std::unique_ptr<TempPath> draw(const std::string& gnuplot, const std::string& path,
                               const GnuplotJob& job, const std::string& terminal,
                               bool (*complete)(const std::string&)) {
  const fs::path target = fs::absolute(path);
  const TempDir dir(path);
  std::unique_ptr<TempPath> tmp_guard;  // exclusive, unpredictable; removed on any failure
  try {
    tmp_guard = std::make_unique<TempPath>(target.string(), TempKind::kFile);
  } catch (const InputError& e) {
    throw std::runtime_error(e.what());
  }
  const std::string tmp = tmp_guard->path();
  auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream out(dir.path() / name, std::ios::binary);
    out << content;
    out.close();
    if (!out) {
      throw std::runtime_error(path + ": cannot write gnuplot input " +
                               (dir.path() / name).string());
    }
  };
  for (const auto& [name, content] : job.data_files) write(name, content);
  std::ostringstream script;
  script << terminal << "\n"
         << "set output " << gp_quote(tmp) << "\n"
         << "set datafile missing 'nan'\n"
         << job.script << "unset output\n";
  write("plot.gp", script.str());

  // run it in the temp folder, stderr captured
  const std::string command = "cd " + sh_quote(dir.path().string()) + " && " + sh_quote(gnuplot) +
                              " plot.gp >gnuplot.out 2>gnuplot.err";
  const int rc = std::system(command.c_str());
  const bool exited_ok = rc != -1 && WIFEXITED(rc) && WEXITSTATUS(rc) == 0;
  // gnuplot exits 0 also when cairo could not write the whole image (a full disk): the file
  // must end as its format ends
  if (!exited_ok || !complete(tmp)) {
    std::string why = first_error_line(read_text(dir.path() / "gnuplot.err"));
    if (why.empty()) {
      why = rc == -1               ? std::string("cannot start a shell")
            : !WIFEXITED(rc)       ? "killed by signal " + std::to_string(WTERMSIG(rc))
            : WEXITSTATUS(rc) != 0 ? "exit status " + std::to_string(WEXITSTATUS(rc))
                                   : std::string("the image was not written whole (disk full?)");
    }
    throw std::runtime_error(path + ": gnuplot failed: " + why);
  }
  return tmp_guard;
}

}  // namespace

void set_extra_plot_formats(const std::vector<std::string>& formats) {
  for (const std::string& f : formats) {
    if (f != "svg" && f != "pdf") throw std::invalid_argument("plot format " + f);
  }
  const std::lock_guard<std::mutex> lock(g_formats_mutex);
  g_extra_formats = formats;
}

// Runs `job` and moves its PNG to png_path (and the extra formats beside it); throws
// std::runtime_error naming the file.
void run_gnuplot(const std::string& png_path, const GnuplotJob& job) {
  // gnuplot must exist and the target folder too (gnuplot's own message would name a temp file)
  const std::string gnuplot = find_gnuplot();
  if (gnuplot.empty()) {
    throw std::runtime_error(
        png_path + ": gnuplot not found on PATH (install gnuplot-nox, pngcairo terminal)");
  }
  const fs::path target = fs::absolute(png_path);
  if (!fs::is_directory(target.parent_path())) {
    throw std::runtime_error(png_path + ": cannot write the plot, no folder " +
                             target.parent_path().string());
  }
  std::ostringstream png;
  png << "set terminal pngcairo size " << job.width_px << "," << job.height_px
      << " noenhanced font 'sans,11'";
  // every format drawn whole first, then all moved into place: no PNG without its SVG
  std::vector<std::pair<std::unique_ptr<TempPath>, std::string>> drawn;
  drawn.emplace_back(draw(gnuplot, png_path, job, png.str(), png_is_complete), png_path);
  for (const std::string& format : extra_formats()) {
    const std::string path = fs::path(png_path).replace_extension(format).string();
    std::ostringstream terminal;
    if (format == "svg") {
      terminal << "set terminal svg size " << job.width_px << "," << job.height_px
               << " noenhanced font 'sans,11' background '#ffffff'";
      drawn.emplace_back(draw(gnuplot, path, job, terminal.str(),
                              [](const std::string& p) { return ends_with_text(p, "</svg>"); }),
                         path);
    } else {  // pdf: the same aspect, 100 px per inch
      terminal << "set terminal pdfcairo size " << gp_num(job.width_px / 100.0) << ","
               << gp_num(job.height_px / 100.0) << " noenhanced font 'sans,11'";
      drawn.emplace_back(draw(gnuplot, path, job, terminal.str(),
                              [](const std::string& p) { return ends_with_text(p, "%%EOF"); }),
                         path);
    }
  }
  for (auto& [tmp, path] : drawn) {
    if (std::rename(tmp->path().c_str(), fs::absolute(path).c_str()) != 0) {
      throw std::runtime_error(path + ": cannot move the plot into place: " + std::strerror(errno));
    }
    tmp->release();
  }
}

bool finite_range(const std::vector<double>& v, double& lo, double& hi) {
  lo = INFINITY;
  hi = -INFINITY;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return lo <= hi;
}

}  // namespace pamsim
