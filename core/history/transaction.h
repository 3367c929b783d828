#pragma once
// One save = one transaction. Construct before the first write, call commit()
// after the last; if anything throws in between, the destructor rolls back,
// so a save is either wholly in the history or not at all.
//
// BEGIN IMMEDIATE takes the write lock up front: a second writer waits
// (busy timeout) at the start instead of failing halfway with SQLITE_BUSY.
// Inside an open transaction a Transaction becomes a SAVEPOINT, so a
// composite save (a whole imported file) can reuse the single-record saves
// and still be atomic as a whole.
#include <string>

#include "history/database.h"

namespace auv {

class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

  void commit();

 private:
  Database& db_;
  std::string savepoint_;  // empty for an outermost transaction
  bool done_ = false;
};

}  // namespace auv
