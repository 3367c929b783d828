#include "history/database.h"

#include <sqlite3.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "common/input_error.h"

namespace auv {
namespace fs = std::filesystem;

namespace {
const char* kField = "history database";

[[noreturn]] void throwOpenError(const std::string& path, int sys_errno,
                                 const std::string& sqlite_msg) {
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (fs::is_directory(p, ec))
    throw InputError(kField, "'" + path + "' is a folder, not a history file",
                     "give a file name inside it, e.g. " + (p / "history.db").string());
  if (!fs::is_directory(dir, ec))
    throw InputError(kField, "cannot create '" + path + "': folder '" + dir.string() +
                                 "' does not exist",
                     "create the folder or choose another location for the history");
  std::string why = sqlite_msg;
  if (sys_errno != 0) why += " (" + std::string(std::strerror(sys_errno)) + ")";
  throw InputError(kField,
                   "cannot open or create '" + path + "' for writing: " + why +
                       "; the location is read-only or not permitted",
                   "choose a writable folder for the history database, or fix the "
                   "folder's permissions; the history is never opened read-only");
}
}  // namespace

Database::Database(std::string path) : path_(std::move(path)) {
  const int rc = sqlite3_open_v2(path_.c_str(), &db_,
                                 SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  if (rc != SQLITE_OK) {
    const int sys = db_ ? sqlite3_system_errno(db_) : 0;
    const std::string msg = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    throwOpenError(path_, sys, msg);
  }
  sqlite3_extended_result_codes(db_, 1);
  // SQLite silently falls back to read-only when the file is not writable;
  // a history we cannot save to must be refused up front, not at first save.
  if (sqlite3_db_readonly(db_, "main") == 1) {
    sqlite3_close(db_);
    db_ = nullptr;
    throwOpenError(path_, EACCES, "the file is read-only");
  }
}

Database::~Database() { sqlite3_close_v2(db_); }

bool Database::refreshBackup() {
  // Into a temporary file, then renamed: a writer killed mid-copy leaves the
  // previous backup whole.
  const std::string tmp = backupPath() + ".tmp";
  sqlite3* dest = nullptr;
  bool ok = sqlite3_open_v2(tmp.c_str(), &dest, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) == SQLITE_OK;
  if (ok) {
    sqlite3_backup* b = sqlite3_backup_init(dest, "main", db_, "main");
    ok = b != nullptr && sqlite3_backup_step(b, -1) == SQLITE_DONE;
    ok = sqlite3_backup_finish(b) == SQLITE_OK && ok;
  }
  sqlite3_close_v2(dest);
  std::error_code ec;
  if (ok) fs::rename(tmp, backupPath(), ec);
  if (!ok || ec) fs::remove(tmp, ec);
  return ok && !ec;
}

void Database::fail(int rc, const std::string& doing) {
  const std::string msg = sqlite3_errmsg(db_);
  switch (rc & 0xff) {
    case SQLITE_NOTADB:
      throw InputError(kField, "'" + path_ + "' is not a SQLite database (" + msg + ")",
                       "choose another file for the history; this one was left untouched");
    case SQLITE_CORRUPT:
      throw InputError(kField, "'" + path_ + "' is damaged (" + msg + ") while " + doing,
                       "restore the file from a backup; do not delete it, it may be "
                       "recoverable with the sqlite3 .recover command");
    case SQLITE_READONLY:
    case SQLITE_CANTOPEN:
    case SQLITE_PERM:
      throw InputError(kField, "cannot write '" + path_ + "' while " + doing + ": " + msg,
                       "choose a writable folder for the history database, or fix the "
                       "file's and folder's permissions");
    case SQLITE_CONSTRAINT:
      throw InputError(kField, "the save was refused by a rule of '" + path_ + "' while " +
                                   doing + ": " + msg,
                       "link only records of the same configuration (mission, analysis, "
                       "recommendation) and give every required value");
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      throw InputError(kField, "'" + path_ + "' is being written by another program (waited 5 s) "
                                   "while " + doing,
                       "close the other auvballast window or command and save again");
    case SQLITE_FULL:
      throw InputError(kField, "disk full while " + doing + " in '" + path_ + "'",
                       "free disk space and save again; nothing was half-saved");
    default:
      throw std::runtime_error("history database '" + path_ + "': " + msg + " (while " +
                               doing + ")");
  }
}

void Database::exec(const std::string& sql, const std::string& doing) {
  char* err = nullptr;
  const int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err);
  sqlite3_free(err);
  if (rc != SQLITE_OK) fail(rc, doing);
}

Statement Database::prepare(const std::string& sql) {
  sqlite3_stmt* stmt = nullptr;
  const int rc = sqlite3_prepare_v2(db_, sql.c_str(), int(sql.size()), &stmt, nullptr);
  if (rc != SQLITE_OK) fail(rc, "preparing \"" + sql + "\"");
  return Statement(*this, stmt, sql);
}

std::string Database::queryText(const std::string& sql) {
  auto st = prepare(sql);
  return st.step() && !st.isNull(0) ? st.text(0) : std::string();
}

std::int64_t Database::queryInt(const std::string& sql) {
  auto st = prepare(sql);
  return st.step() ? st.integer(0) : 0;
}

RecordId Database::lastInsertId() { return sqlite3_last_insert_rowid(db_); }
bool Database::inTransaction() { return sqlite3_get_autocommit(db_) == 0; }

Statement::Statement(Database& db, sqlite3_stmt* stmt, std::string sql)
    : db_(&db), stmt_(stmt), sql_(std::move(sql)) {}
Statement::~Statement() { sqlite3_finalize(stmt_); }
Statement::Statement(Statement&& o) noexcept : db_(o.db_), stmt_(o.stmt_), sql_(std::move(o.sql_)) {
  o.stmt_ = nullptr;
}

Statement& Statement::bind(int i, double v) {
  if (const int rc = sqlite3_bind_double(stmt_, i, v); rc != SQLITE_OK) db_->fail(rc, "binding");
  return *this;
}
Statement& Statement::bind(int i, std::int64_t v) {
  if (const int rc = sqlite3_bind_int64(stmt_, i, v); rc != SQLITE_OK) db_->fail(rc, "binding");
  return *this;
}
Statement& Statement::bind(int i, const std::string& v) {
  const int rc = sqlite3_bind_text(stmt_, i, v.data(), int(v.size()), SQLITE_TRANSIENT);
  if (rc != SQLITE_OK) db_->fail(rc, "binding");
  return *this;
}
Statement& Statement::bind(int i, std::nullopt_t) {
  if (const int rc = sqlite3_bind_null(stmt_, i); rc != SQLITE_OK) db_->fail(rc, "binding");
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  db_->fail(rc, "running \"" + sql_ + "\"");
}

void Statement::run() {
  while (step()) {
  }
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

bool Statement::isNull(int c) { return sqlite3_column_type(stmt_, c) == SQLITE_NULL; }
double Statement::real(int c) { return sqlite3_column_double(stmt_, c); }
std::int64_t Statement::integer(int c) { return sqlite3_column_int64(stmt_, c); }
std::string Statement::text(int c) {
  const auto* p = sqlite3_column_text(stmt_, c);
  return p ? std::string(reinterpret_cast<const char*>(p), std::size_t(sqlite3_column_bytes(stmt_, c)))
           : std::string();
}
std::optional<double> Statement::optReal(int c) {
  return isNull(c) ? std::nullopt : std::optional<double>(real(c));
}
std::optional<std::int64_t> Statement::optInteger(int c) {
  return isNull(c) ? std::nullopt : std::optional<std::int64_t>(integer(c));
}

}  // namespace auv
