// sqlite_file.cc: see sqlite_file.h.
#include "sim/sweep/sqlite_file.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "base/input_error.h"
#include "sim/io/temp_path.h"

namespace pamsim {
namespace {

// Why `path` or its folder cannot be written (SQLite writes -wal and -shm files beside the
// database), or "" if both can. access(2) sees permissions and read-only mounts alike.
std::string why_not_writable(const std::string& path) {
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (::access(path.c_str(), W_OK) != 0) return std::strerror(errno);
  if (::access(folder.c_str(), W_OK) != 0) {
    return "its folder: " + std::string(std::strerror(errno));
  }
  return "";
}

// `path` as an SQLite URI with `parameters` (the characters a URI gives meaning escaped).
std::string uri_of(const std::string& path, const std::string& parameters) {
  std::string uri = "file:";
  for (const char c : path) {
    if (c == '?' || c == '#' || c == '%') {
      char hex[4];
      std::snprintf(hex, sizeof(hex), "%%%02X", static_cast<unsigned char>(c));
      uri += hex;
    } else {
      uri += c;
    }
  }
  return uri + "?" + parameters;
}

// fsync(2) on the folder holding `path`, so a new name in it is durable (best effort).
void sync_folder_of(const std::string& path) {
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

std::string read_only_uri(const std::string& path) {
  return uri_of(path, why_not_writable(path).empty() ? "mode=ro" : "immutable=1");
}

void StatementDeleter::operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }

Statement prepare_statement(sqlite3* db, const std::string& sql) {
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) != SQLITE_OK) {
    sqlite3_finalize(s);
    return nullptr;
  }
  return Statement(s);
}

std::string quoted_identifier(const std::string& name) {
  std::string out = "\"";
  for (char c : name) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void create_sqlite_file(const std::string& path, const std::string& what,
                        const std::string& exists_hint,
                        const std::function<void(const std::string& tmp)>& fill) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    throw InputError(path + ": already exists; " + exists_hint);
  }
  // a WAL left by a killed writer whose database was then deleted would be replayed into the
  // new one: refuse rather than mix two databases
  for (const char* suffix : {"-wal", "-shm", "-journal"}) {
    if (std::filesystem::exists(path + suffix, ec)) {
      throw InputError(path + suffix + ": left over from an earlier database at " + path +
                       "; remove it to make a new one there");
    }
  }
  std::unique_ptr<TempPath> tmp_guard;   // removes the temp name however this ends
  try {
    tmp_guard = std::make_unique<TempPath>(path, TempKind::kFile);
  } catch (const InputError&) {
    throw InputError(path + ": cannot create the " + what + " (is the folder writable?)");
  }
  const std::string& tmp = tmp_guard->path();
  try {
    fill(tmp);
  } catch (const std::exception& e) {
    std::string why = e.what();
    const bool about_tmp = why.rfind(tmp + ": ", 0) == 0;
    // a bad input `fill` read names that input; anything about the new file (a full disk)
    // names the database, not its temp
    if (!about_tmp && dynamic_cast<const InputError*>(&e)) throw;
    if (about_tmp) why = why.substr(tmp.size() + 2);
    throw std::runtime_error(path + ": cannot create the " + what + " (" + why + ")");
  }
  // its content on disk before its name is
  const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  if (fd >= 0) ::close(fd);
  if (!synced) {
    throw std::runtime_error(path + ": cannot create the " + what + " (fsync: " +
                             std::strerror(errno) + ")");
  }
  if (::link(tmp.c_str(), path.c_str()) != 0) {
    throw InputError(path + ": cannot create the " + what + " (" + std::strerror(errno) + ")");
  }
  sync_folder_of(path);
}

sqlite3* open_sqlite_file(const std::string& path, DbAccess access, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path + ": no such " + what);
  }
  const std::string not_writable = why_not_writable(path);
  if (access == DbAccess::kWrite && !not_writable.empty()) {
    throw InputError(path + ": is read-only (" + not_writable + "); the " + what +
                     " must be writable to go on: copy it to a writable folder");
  }
  // Read-only: a WAL database needs a -shm file it cannot make here. Without a -wal (a
  // writer that closed checkpoints and removes it) the file is all there is and is opened
  // immutable; a -wal left by a killed writer holds trials only a writable copy recovers.
  std::string name = path;
  int flags = SQLITE_OPEN_READWRITE;
  if (!not_writable.empty()) {
    flags = SQLITE_OPEN_READONLY;
    if (std::filesystem::file_size(path + "-wal", ec) > 0 && !ec) {
      throw InputError(path + ": is read-only (" + not_writable + ") and its -wal holds " +
                       "results a killed run left uncommitted to the file: copy both to a "
                       "writable folder to read them");
    }
    name = uri_of(path, "immutable=1");   // no locks, no -shm: readable on read-only media
    flags |= SQLITE_OPEN_URI;
  }
  sqlite3* db = nullptr;
  int rc = sqlite3_open_v2(name.c_str(), &db, flags, nullptr);
  const auto fail = [&](const std::string& problem) {
    const std::string why = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    sqlite3_close(db);
    throw InputError(path + ": " + problem + " (" + why + ")");
  };
  if (rc != SQLITE_OK) fail("cannot open the " + what);
  sqlite3_busy_timeout(db, 10000);
  // the schema is read now, so that a file that is not a database, or one that cannot be
  // read here, says so (later reads would take it for a database without the tables)
  rc = sqlite3_exec(db, "SELECT count(*) FROM sqlite_schema", nullptr, nullptr, nullptr);
  if (rc != SQLITE_OK) fail("cannot read the " + what);
  if (access == DbAccess::kWrite && sqlite3_db_readonly(db, "main") == 1) {
    rc = SQLITE_READONLY;
    fail("cannot write the " + what);
  }
  return db;
}

std::unique_ptr<FolderGuard> prepare_database_folder(const std::string& db_path,
                                                     const std::string& file_name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (db_path.empty() || db_path.back() == '/' || fs::is_directory(db_path, ec)) {
    throw InputError("--db " + db_path + ": is a folder; name the database file, e.g. " +
                     (fs::path(db_path) / file_name).lexically_normal().string());
  }
  const std::string parent = fs::path(db_path).parent_path().string();
  if (parent.empty() || fs::exists(db_path, ec)) return nullptr;
  return std::make_unique<FolderGuard>(parent);
}

}  // namespace pamsim
