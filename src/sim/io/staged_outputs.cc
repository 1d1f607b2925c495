// staged_outputs.cc: see staged_outputs.h.
#include "sim/io/staged_outputs.h"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "base/input_error.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

bool matches_any(const std::vector<std::string>& patterns, const std::string& name) {
  return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& pattern) {
    return ::fnmatch(pattern.c_str(), name.c_str(), FNM_PERIOD) == 0;
  });
}

}  // namespace

void refuse_earlier_outputs(const std::string& dir, const std::vector<std::string>& owned) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (matches_any(owned, e.path().filename())) found.push_back(e.path().filename());
  }
  if (found.empty()) return;
  std::sort(found.begin(), found.end());
  throw InputError((fs::path(dir) / found.front()).string() +
                   ": exists, from an earlier run; add --force to replace that run's outputs, "
                   "or choose another --out");
}

StagedOutputs::StagedOutputs(std::string dir, std::vector<std::string> owned)
    : dir_(std::move(dir)), owned_(std::move(owned)) {
  if (dir_.empty()) dir_ = ".";
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();  // the staging is a sibling
  std::error_code ec;
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec)) {
    throw InputError(dir_ + ": cannot create output folder (a file of that name exists)");
  }
  folder_ = std::make_unique<FolderGuard>(dir_);
  staging_ = std::make_unique<TempPath>(dir_ + "/.pamsim-staging", TempKind::kFolder);
}

StagedOutputs::~StagedOutputs() {
  staging_.reset();  // removes the staging folder unless published, before the folders made
}

std::string StagedOutputs::path(const std::string& name) const {
  return staging_->path() + "/" + name;
}

void StagedOutputs::write(const std::function<void()>& write_outputs) const {
  const auto in_place = [&](std::string message) {
    const std::string& from = staging_->path();
    for (std::size_t at = 0; (at = message.find(from, at)) != std::string::npos;) {
      message.replace(at, from.size(), dir_);
      at += dir_.size();
    }
    return message;
  };
  try {
    write_outputs();
  } catch (const InputError& e) {
    throw InputError(in_place(e.what()));
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(in_place(e.what()));
  }
}

void StagedOutputs::publish() {
  const fs::path staging = staging_->path();
  const fs::path replaced = staging / ".replaced";  // the old entries, until all is in place
  std::error_code ec;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(staging)) names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  fs::create_directory(replaced, ec);
  if (ec) throw InputError(dir_ + ": cannot publish the outputs (" + ec.message() + ")");

  // move aside what the new set replaces, and the owned entries it lacks
  std::vector<std::string> moved;
  // puts the old entries back; if one cannot be, the staging folder is kept (it holds them)
  // and the error says where they are
  const auto fail = [&](const std::string& message) {
    bool restored = true;
    for (const std::string& name : moved) {
      std::error_code e;
      fs::rename(replaced / name, fs::path(dir_) / name, e);
      restored = restored && !e;
    }
    if (restored) throw InputError(message);
    staging_->release();
    throw InputError(message + "; the earlier outputs are kept in " + replaced.string());
  };
  const auto owned = [&](const std::string& name) { return matches_any(owned_, name); };
  std::vector<std::string> old_names;  // read first: the folder changes below
  for (const auto& e : fs::directory_iterator(dir_)) {
    if (fs::equivalent(e.path(), staging, ec)) continue;  // (it is inside `dir`)
    old_names.push_back(e.path().filename());
  }
  for (const std::string& name : old_names) {
    const bool is_new = std::binary_search(names.begin(), names.end(), name);
    if (!is_new && !owned(name)) continue;
    fs::rename(fs::path(dir_) / name, replaced / name, ec);
    if (ec) fail(dir_ + "/" + name + ": cannot replace it (" + ec.message() + ")");
    moved.push_back(name);
  }
  // then the new entries in; a failure puts back what was there
  std::vector<std::string> placed;
  for (const std::string& name : names) {
    fs::rename(staging / name, fs::path(dir_) / name, ec);
    if (ec) {
      const std::string why = ec.message();
      std::error_code ignored;
      for (const std::string& p : placed) fs::rename(fs::path(dir_) / p, staging / p, ignored);
      fail(dir_ + "/" + name + ": cannot put it in place (" + why + ")");
    }
    placed.push_back(name);
  }
  published_ = true;
  folder_->keep();
  staging_.reset();  // removes the staging folder with the replaced entries
}

}  // namespace pamsim
