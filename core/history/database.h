#pragma once
// Thin RAII over the SQLite C API: one Database owns one sqlite3*, one
// Statement owns one prepared sqlite3_stmt*. Every failure is turned into an
// exception that names the database file and what we were doing, so nothing
// above this layer ever checks a return code. The SQLite header stays private
// to this module (it is a PRIVATE dependency).
#include <cstdint>
#include <optional>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace auv {

using RecordId = std::int64_t;

class Statement;

class Database {
 public:
  // Opens read-write, creating the file if missing. Throws InputError for a
  // missing folder or a location that cannot be written.
  explicit Database(std::string path);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  const std::string& path() const { return path_; }
  sqlite3* handle() { return db_; }

  void exec(const std::string& sql, const std::string& doing);
  Statement prepare(const std::string& sql);
  // First column of the first row as text ("" when there is no row).
  std::string queryText(const std::string& sql);
  std::int64_t queryInt(const std::string& sql);
  RecordId lastInsertId();
  bool inTransaction();

  // A file whose check found damage is still read, but never written: every
  // save (Transaction) is refused with the restore instructions.
  void refuseWrites(std::string problems) { damage_ = std::move(problems); }
  const std::string& damage() const { return damage_; }
  // The one rolling backup, `path() + ".bak"`, refreshed after each committed
  // save with the SQLite backup API (a consistent copy even under WAL).
  std::string backupPath() const { return path_ + ".bak"; }
  // Best effort: a full disk or read-only folder leaves the previous backup;
  // the save itself has already committed. Returns false if it failed.
  bool refreshBackup();

  // Turns the current SQLite error into an exception (InputError for the
  // operator-fixable ones: not a database, read-only, disk full, corrupt).
  [[noreturn]] void fail(int rc, const std::string& doing);

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
  std::string damage_;
};

class Statement {
 public:
  Statement(Database& db, sqlite3_stmt* stmt, std::string sql);
  ~Statement();
  Statement(Statement&& o) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement& operator=(Statement&&) = delete;

  // 1-based parameter index, as in SQL "?1".
  Statement& bind(int i, double v);
  Statement& bind(int i, std::int64_t v);
  Statement& bind(int i, int v) { return bind(i, std::int64_t{v}); }
  Statement& bind(int i, const std::string& v);
  Statement& bind(int i, const char* v) { return bind(i, std::string(v)); }
  Statement& bind(int i, std::nullopt_t);
  template <class T>
  Statement& bind(int i, const std::optional<T>& v) {
    return v ? bind(i, *v) : bind(i, std::nullopt);
  }

  bool step();  // true while a row is available
  void run();   // step once, expecting no row (INSERT/UPDATE)
  void reset();

  // 0-based column index, as in sqlite3_column_*.
  bool isNull(int col);
  double real(int col);
  std::int64_t integer(int col);
  std::string text(int col);
  std::optional<double> optReal(int col);
  std::optional<std::int64_t> optInteger(int col);

 private:
  Database* db_;
  sqlite3_stmt* stmt_;
  std::string sql_;
};

}  // namespace auv
