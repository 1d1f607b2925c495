// sqlite_file.cc: see sqlite_file.h.
#include "sim/io/sqlite_file.h"

#include <fcntl.h>
#include <sys/file.h>
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
  std::unique_ptr<TempPath> tmp_guard;  // removes the temp name however this ends
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
    throw std::runtime_error(path + ": cannot create the " + what +
                             " (fsync: " + std::strerror(errno) + ")");
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
    name = uri_of(path, "immutable=1");  // no locks, no -shm: readable on read-only media
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

// --- SqliteDb -------------------------------------------------------------------------------

SqliteDb SqliteDb::open(const std::string& path, DbAccess access, const std::string& what) {
  return SqliteDb(open_sqlite_file(path, access, what), path);
}

SqliteDb SqliteDb::open_new(const std::string& tmp, const std::string& what, bool uri_attach) {
  sqlite3* db = nullptr;
  const int flags = SQLITE_OPEN_READWRITE | (uri_attach ? SQLITE_OPEN_URI : 0);
  const int rc = sqlite3_open_v2(tmp.c_str(), &db, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string why = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    sqlite3_close(db);
    throw InputError(tmp + ": cannot open the " + what + " (" + why + ")");
  }
  sqlite3_busy_timeout(db, 10000);
  return SqliteDb(db, tmp);
}

SqliteDb::SqliteDb(SqliteDb&& other) noexcept
    : db_(other.db_), path_(std::move(other.path_)), writer_lock_fd_(other.writer_lock_fd_) {
  other.db_ = nullptr;
  other.writer_lock_fd_ = -1;
}

SqliteDb& SqliteDb::operator=(SqliteDb&& other) noexcept {
  if (this != &other) {
    close();
    db_ = other.db_;
    path_ = std::move(other.path_);
    writer_lock_fd_ = other.writer_lock_fd_;
    other.db_ = nullptr;
    other.writer_lock_fd_ = -1;
  }
  return *this;
}

SqliteDb::~SqliteDb() { close(); }

void SqliteDb::close() {
  sqlite3_close(db_);
  db_ = nullptr;
  // only after SQLite is done with the file: closing any descriptor of it drops the
  // process's POSIX locks, SQLite's included
  if (writer_lock_fd_ >= 0) ::close(writer_lock_fd_);
  writer_lock_fd_ = -1;
}

void SqliteDb::fail(const std::string& what) const {
  throw std::runtime_error(path_ + ": " + what + " (" + sqlite3_errmsg(db_) + ")");
}

void SqliteDb::exec(const std::string& sql) const {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string why = err ? err : "unknown error";
    sqlite3_free(err);
    throw std::runtime_error(path_ + ": " + why);
  }
}

Statement SqliteDb::prepare(const std::string& sql, const std::string& what) const {
  Statement s = prepare_statement(db_, sql);
  if (!s) fail(what);
  return s;
}

std::string SqliteDb::meta(const std::string& key) const {
  Statement s = prepare_statement(db_, "SELECT value FROM meta WHERE key = ?");
  if (!s) return "";  // no meta table: not a pamsim database
  sqlite3_bind_text(s.get(), 1, key.c_str(), -1, SQLITE_TRANSIENT);
  if (sqlite3_step(s.get()) != SQLITE_ROW) return "";
  const auto* text = sqlite3_column_text(s.get(), 0);
  return text ? reinterpret_cast<const char*>(text) : "";
}

void SqliteDb::put_meta(const std::vector<std::pair<std::string, std::string>>& entries,
                        const std::string& what) const {
  Statement put = prepare("INSERT OR REPLACE INTO meta VALUES (?, ?)", what);
  for (const auto& [key, value] : entries) {
    sqlite3_bind_text(put.get(), 1, key.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(put.get(), 2, value.c_str(), -1, SQLITE_TRANSIENT);
    if (sqlite3_step(put.get()) != SQLITE_DONE) fail(what);
    sqlite3_reset(put.get());
  }
}

void SqliteDb::become_writer(const std::string& busy, const std::string& what) {
  // flock(2), independent of SQLite's fcntl locks
  const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;  // before close() can change it
    if (fd >= 0) ::close(fd);
    throw InputError(path_ + (error == EWOULDBLOCK ? ": " + busy
                                                   : ": cannot lock the " + what + " (" +
                                                         std::string(std::strerror(error)) + ")"));
  }
  writer_lock_fd_ = fd;
  exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;");
}

void SqliteDb::transaction(const std::function<void()>& body) const {
  exec("BEGIN IMMEDIATE");
  try {
    body();
    exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

}  // namespace pamsim
