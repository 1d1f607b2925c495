// report_folder.cc: see report_folder.h.
#include "sim/cli/report_folder.h"

#include <algorithm>
#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "base/input_error.h"
#include "sim/io/html_page.h"
#include "sim/io/markdown_html.h"
#include "sim/io/provenance.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// The tables a command leads with, in the order a reader wants them; other files follow
const char* const kLeading[] = {"table3.md", "table5.md",      "identify.md",
                                "bands.md",  "sensitivity.md", "budget.md"};

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string base64(const std::string& bytes) {
  using namespace boost::archive::iterators;
  using Encode = base64_from_binary<transform_width<std::string::const_iterator, 6, 8>>;
  std::string out(Encode(bytes.begin()), Encode(bytes.end()));
  return out.append((3 - bytes.size() % 3) % 3, '=');
}

// The folder's files ending in `ext`, the leading ones first, then by name
std::vector<fs::path> files_of(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file() && e.path().extension() == ext) files.push_back(e.path());
  }
  auto rank = [](const fs::path& p) {
    const auto at = std::find(std::begin(kLeading), std::end(kLeading), p.filename().string());
    return static_cast<std::size_t>(at - std::begin(kLeading));
  };
  std::sort(files.begin(), files.end(), [&](const fs::path& a, const fs::path& b) {
    return std::make_pair(rank(a), a.filename()) < std::make_pair(rank(b), b.filename());
  });
  return files;
}

// The folder's provenance.json, or null when it has none or cannot be read
nlohmann::json provenance_of(const fs::path& dir) {
  const fs::path p = dir / kProvenanceFile;
  if (!fs::exists(p)) return nullptr;
  nlohmann::json j = nlohmann::json::parse(file_text(p), nullptr, false);
  return j.is_object() ? j : nlohmann::json(nullptr);
}

std::string run_of(const nlohmann::json& provenance);

// What made the page, and what made the folder (its provenance)
std::string footer(const fs::path& dir, const nlohmann::json& provenance) {
  const std::string made =
      "Made by pamsim " PAMSIM_VERSION " from the folder " + dir.string() + ".";
  if (provenance.is_null()) return html_escape(made + " It holds no readable provenance.json.");
  try {
    return html_escape(made + " Its run: " + run_of(provenance) + ".");
  } catch (const nlohmann::json::exception&) {  // a field of another type than pamsim writes
    return html_escape(made + " Its provenance.json is not one pamsim wrote.");
  }
}

// The run a provenance.json records: its command line, build, start, file and inputs; throws
// nlohmann::json::exception for a field of another type
std::string run_of(const nlohmann::json& provenance) {
  std::string line;
  for (const auto& arg : provenance.value("command_line", nlohmann::json::array())) {
    if (arg.is_string()) line += (line.empty() ? "" : " ") + arg.get<std::string>();
  }
  std::string inputs;  // the files it read, with their digests where it recorded them
  for (const auto& in : provenance.value("inputs", nlohmann::json::array())) {
    if (in.is_object()) {
      inputs += ", " + in.value("path", "?") + " (FNV-1a " + in.value("fnv1a64", "?") + ")";
    }
  }
  const nlohmann::json build = provenance.value("build", nlohmann::json::object());
  return line + " (pamsim " + build.value("pamsim_version", "?") + ", commit " +
         build.value("git_commit", "?") + ", started " + provenance.value("started_utc", "?") +
         "); its file " + provenance.value("scenario_file", "?") + inputs;
}

}  // namespace

std::string folder_page_html(const std::string& dir) {
  const fs::path folder(dir);
  const std::vector<fs::path> texts =
      fs::is_directory(folder) ? files_of(folder, ".md") : std::vector<fs::path>{};
  if (texts.empty()) {
    throw InputError(dir +
                     ": no Markdown file of a pamsim command (table5.md, identify.md, "
                     "bands.md, ...) to make a page of");
  }
  const nlohmann::json provenance = provenance_of(folder);
  const std::string title =
      "pamsim " + (provenance.is_null() ? std::string() : provenance.value("command", "") + ": ") +
      folder.string();
  std::ostringstream body;
  body << "<h1>" << html_escape(title) << "</h1>\n";
  for (const fs::path& md : texts) {
    body << "<section class=\"file\" data-file=\"" << html_escape(md.filename().string()) << "\">"
         << markdown_to_html(file_text(md)) << "</section>\n";
  }
  for (const fs::path& png : files_of(folder, ".png")) {
    body << "<figure><img alt=\"" << html_escape(png.filename().string())
         << "\" src=\"data:image/png;base64," << base64(file_text(png)) << "\"><figcaption>"
         << html_escape(png.filename().string()) << "</figcaption></figure>\n";
  }
  return html_document(title, body.str(), "", footer(folder, provenance));
}

}  // namespace pamsim
